#!/usr/bin/env bash
# run_page.sh WPG DURATION MIN_FPS: `wpg run walk_forward --replay` for DURATION s, `wpg view`
# of it, and check_run_page.py: at #t=0 and #t=6 no console error and no request, the two
# screenshots differ where the robot is; with MIN_FPS > 0, the page is at most 5 MB and its
# frame rate is measured and printed (required to be at least MIN_FPS only with
# WPG_VIEWER_MEASURE_FPS=1 in the environment: a timing on a shared machine is no assertion).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1" duration="$2" min_fps="$3"
require_chromium
make_workdir
"$wpg" run walk_forward --replay --no-plot --set "duration=$duration" -o "$WORKDIR/walk.h5" >/dev/null \
  || fail "run: exit status $?"
"$wpg" view "$WORKDIR/walk.h5" -o "$WORKDIR/walk.html" || fail "view: exit status $?"
checks=("$WORKDIR/walk.html" "$WORKDIR")
if [[ "$min_fps" != 0 ]]; then
  checks+=(--max-bytes 5000000)
  checks+=(--min-fps "$min_fps")
fi
"$PYTHON" "$VIEWER_TESTS/check_run_page.py" "${checks[@]}" || fail "the page of $duration s of walk_forward"
