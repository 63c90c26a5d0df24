#!/usr/bin/env bash
# The first run: installs what `wpg` needs, builds `wpg` only (no tests, no benchmarks), then
# generates the default scenario (walk_forward): out/walk_forward.h5 and out/walk_forward.png at
# the top of the repository. Arguments go to `wpg run` (e.g. --set duration=20).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"
"$repo/scripts/setup.sh"
cd "$repo"
exec "$build/cli/wpg" run walk_forward "$@"
