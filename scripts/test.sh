#!/usr/bin/env bash
# Installs what the tests need, builds wpg and its tests (not the benchmarks), then runs every
# test: unit tests, CLI regression tests, the installed-package test. Arguments go to ctest
# (e.g. -R cli.reference).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"
"$repo/scripts/setup.sh" --with-tests
exec ctest --test-dir "$build" --output-on-failure -j"$(nproc)" "$@"
