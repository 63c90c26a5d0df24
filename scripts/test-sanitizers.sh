#!/usr/bin/env bash
# Builds wpg, its tests and the fuzz targets with clang 14 + AddressSanitizer + UBSan in
# build-sanitize/ (or $WPG_SANITIZE_BUILD_DIR; cmake/wpg_sanitizers.cmake), then runs the whole
# test suite there. Fails on a failing test and on any sanitizer report, also one from a
# process whose exit status a test does not look at (reports go to files, printed at the end).
# Suppressions, for third-party libraries only: tests/sanitizers/. Works from any folder.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_SANITIZE_BUILD_DIR:-$repo/build-sanitize}")"
# shellcheck source=scripts/sanitizer-env.sh
source "$repo/scripts/sanitizer-env.sh"

wpg_sanitizer_tree "$build"
wpg_sanitizer_build "$build" "$build/build.log"
wpg_sanitizer_env "$build/sanitizer-reports"
# The tests' temporary folders in the tree (kept there when a test fails), out of reach of
# whatever cleans /tmp meanwhile.
export TMPDIR="$build/tmp"
rm -rf "$TMPDIR"
mkdir -p "$TMPDIR"
status=0
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" || status=$?
wpg_sanitizer_reports "$build/sanitizer-reports" || status=1
exit "$status"
