#!/usr/bin/env bash
# run_default.sh WPG: `wpg run` without arguments, from another folder and with the data
# found by the executable itself, writes out/walk_forward.h5 and out/walk_forward.png there.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
(cd "$WORKDIR" && env -u WPG_DATA_DIR "$wpg" run) || fail "exit status $?"
check_run_file "$WORKDIR/out/walk_forward.h5"
check_png "$WORKDIR/out/walk_forward.png"
echo "ok"
