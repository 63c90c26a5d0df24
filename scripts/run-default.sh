#!/usr/bin/env bash
# Sets up and builds wpg, then generates the default scenario (walk_forward): writes
# out/walk_forward.h5 and out/walk_forward.png at the top of the repository.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"
"$repo/scripts/setup.sh"
cd "$repo"
exec "$build/cli/wpg" run walk_forward "$@"
