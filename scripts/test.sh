#!/usr/bin/env bash
# Sets up and builds wpg with what every test needs (setup.sh --for-tests: also Node.js, npm and
# Chromium for the pages of `wpg view`, the Python package), then runs every test (unit, CLI regression, viewer,
# package test, the Python package's pytest).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"
"$repo/scripts/setup.sh" --for-tests
exec ctest --test-dir "$build" --output-on-failure -j2
