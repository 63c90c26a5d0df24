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
# As many tests at a time as there are cores. Not one more: without Open MPI -j3 ran the suite
# in 296 s against 315 s with -j2 on 2 cores, but with it the MPI tests' ranks (3 on 2 cores,
# polling while they wait) and a third test shared the cores: 355 s against 329 s.
exec ctest --test-dir "$build" --output-on-failure -j"$(nproc)" "$@"
