#!/usr/bin/env bash
# Sets up and builds wpg (with the Python package), then runs every test (unit, CLI
# regression, package test, the Python package's pytest).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"
"$repo/scripts/setup.sh" --with-python
exec ctest --test-dir "$build" --output-on-failure -j2
