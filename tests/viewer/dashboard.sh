#!/usr/bin/env bash
# dashboard.sh WPG compare|batch STUDY.yaml: run the study (`wpg compare` or `wpg batch`), write
# its dashboard (`wpg view DIR` or `wpg view BATCH.h5`) and check it in headless Chromium
# (check_dashboard.py): no console error, no request outside its folder, every world x variant
# (or every run) drawn, a run page for every run that opens without error.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1" kind="$2" study="$3"
require_chromium
make_workdir
if [[ "$kind" == compare ]]; then
  "$wpg" compare "$study" -o "$WORKDIR/study" -j 2 --no-plot >/dev/null || fail "compare: exit status $?"
  "$wpg" view "$WORKDIR/study" || fail "view: exit status $?"
  page="$WORKDIR/study/view.html"
  batch="$WORKDIR/study/study.h5"
else
  status=0
  "$wpg" batch "$study" -o "$WORKDIR/batch.h5" -j 2 --no-plot >/dev/null || status=$?
  [[ $status == 0 || $status == 1 ]] || fail "batch: exit status $status"
  "$wpg" view "$WORKDIR/batch.h5" || fail "view: exit status $?"
  page="$WORKDIR/batch.html"
  batch="$WORKDIR/batch.h5"
fi
"$PYTHON" "$VIEWER_TESTS/check_dashboard.py" "$page" "$batch" "$WORKDIR" || fail "the dashboard of $study"
