#!/usr/bin/env bash
# Installs what the tests need (setup.sh --for-tests: also the Python package, Node.js and npm
# for the page of `wpg view`, and Chromium to open it headless), builds wpg and its tests (not
# the benchmarks), then runs every test: unit tests, CLI regression tests, the viewer's pages,
# the Python package's pytest, the installed-package test, after the module order's check
# (scripts/check-layers.py) and the size limits' (scripts/check-sizes.py). Arguments go to ctest
# (e.g. -R cli.reference).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"
"$repo/scripts/setup.sh" --for-tests
# No include or link from a lower module into a higher one (docs/architecture.md, "Modules").
/usr/bin/python3 "$repo/scripts/check-layers.py" --root "$repo"
# No source file over 600 lines, the README and the documentation within their limits.
/usr/bin/python3 "$repo/scripts/check-sizes.py" --root "$repo"
# The tests' temporary folders in the tree (kept there when a test fails), out of reach of
# whatever cleans /tmp meanwhile.
export TMPDIR="$build/tmp"
rm -rf "$TMPDIR"
mkdir -p "$TMPDIR"
# One test more than there are cores: about a tenth of the suite's time is spent waiting
# (Chromium's pages, the kill and interrupt tests' sleeps, fifos), which the extra test fills.
# On 2 cores the suite took 315 s with -j2 (564 s of CPU) and 296 s with -j3.
exec ctest --test-dir "$build" --output-on-failure -j"$(($(nproc) + 1))" "$@"
