#!/usr/bin/env bash
# large_data.sh WPG: pages holding arrays beyond what a call's arguments may hold (200 000 NMPC
# iterations in a run page, 200 000 runs in a dashboard: synthetic data in the pages of a 2 s
# walk and of a 2-run batch, check_large_data.py) draw without error in headless Chromium; long
# variant names fit their boxes.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
require_chromium
make_workdir
"$wpg" batch "$VIEWER_TESTS/../cli/studies/tiny_batch.yaml" --no-plot -o "$WORKDIR/tiny.h5" >/dev/null || fail "batch: exit status $?"
"$wpg" view "$WORKDIR/tiny.h5" >/dev/null || fail "view (dashboard): exit status $?"
"$wpg" view "$WORKDIR/tiny.h5" --run tiny_0 -o "$WORKDIR/run.html" >/dev/null || fail "view (run): exit status $?"
"$PYTHON" "$VIEWER_TESTS/check_large_data.py" "$WORKDIR/run.html" "$WORKDIR/tiny.html" "$WORKDIR" \
  || fail "the pages of large data"
echo "ok"
