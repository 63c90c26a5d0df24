#!/usr/bin/env bash
# regression_detects_change.sh WPG REFERENCE.h5 RTOL ATOL IGNORE KEY=VALUE: the regression comparison
# fails on a small intended change (a 1 % change of one cost weight):
# `wpg run <scenario> --set KEY=VALUE` then `wpg diff` against the reference exits 1, and its
# report names the first differing sample of a walk dataset and the changed scenario line.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; reference="$2"; rtol="$3"; atol="$4"; ignore="$5"; override="$6"
scenario="$(basename "$reference" .h5)"
key="${override%%=*}"; key="${key##*.}"   # walking.weight_cop=1010 -> weight_cop
make_workdir
status=0
"$wpg" run "$scenario" -o "$WORKDIR/run.h5" --no-plot --set "$override" >/dev/null 2>&1 || status=$?
[[ $status == 0 || $status == 1 ]] || fail "wpg run $scenario --set $override: exit status $status"
status=0
"$wpg" diff "$reference" "$WORKDIR/run.h5" --rtol "$rtol" --atol "$atol" --ignore "$ignore" >"$WORKDIR/diff.out" \
  2>"$WORKDIR/diff.err" || status=$?
cat "$WORKDIR/diff.out"
[[ $status == 1 ]] || fail "wpg diff: exit status $status, expected 1 (different)"
[[ ! -s "$WORKDIR/diff.err" ]] || fail "unexpected stderr: $(cat "$WORKDIR/diff.err")"
grep -Eq "^first differing sample: /runs/$scenario/[a-z_/]+ row [0-9]+" "$WORKDIR/diff.out" \
  || fail "the report does not name the first differing sample of a dataset"
grep -Eq "^  /runs/$scenario/com: [0-9]+ of [0-9]+ values differ, largest relative difference" \
  "$WORKDIR/diff.out" || fail "the report does not list the CoM among the differing fields"
grep -Eq "^  /@scenario: text differs at line [0-9]+: .*$key" "$WORKDIR/diff.out" \
  || fail "the report does not show the changed scenario line ($key)"
echo "ok"
