#!/usr/bin/env bash
# diff_batch.sh WPG STUDY.yaml REFERENCE.h5: `wpg diff` on batch files compares every run group
# and the summary table: the study run with -j 1 and -j 2 is the same bit for bit (rtol 0,
# atol 0) once the wall times are left out, and not without that; a copy with one CoM sample of
# one run changed is reported at that run, row and column; a batch file against a run file
# differs (exit 1) with the members of each named.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; study="$2"; reference="$3"
make_workdir
"$wpg" batch "$study" -o "$WORKDIR/j1.h5" -j 1 --no-plot >/dev/null 2>&1 || fail "batch -j 1: exit status $?"
"$wpg" batch "$study" -o "$WORKDIR/j2.h5" -j 2 --no-plot >/dev/null 2>&1 || fail "batch -j 2: exit status $?"
"$wpg" diff "$WORKDIR/j1.h5" "$WORKDIR/j2.h5" --rtol 0 --atol 0 >"$WORKDIR/out" \
  || fail "-j 1 vs -j 2: exit status $?: $(cat "$WORKDIR/out")"
cat "$WORKDIR/out"
grep -q "ignored: .*batch/summary/nmpc_time_p99.*runs/\*/mpc/solve_time" "$WORKDIR/out" \
  || fail "the ignored wall-time fields are not listed"
status=0
"$wpg" diff "$WORKDIR/j1.h5" "$WORKDIR/j2.h5" --compare-wall-time >"$WORKDIR/out" || status=$?
[[ $status == 1 ]] || fail "--compare-wall-time: exit status $status, expected 1"

run="$("$PYTHON" -c "import h5py, sys; print(sorted(h5py.File(sys.argv[1], 'r')['runs'])[5])" "$WORKDIR/j1.h5")"
cp "$WORKDIR/j1.h5" "$WORKDIR/changed.h5"
"$PYTHON" -c "import h5py, sys
with h5py.File(sys.argv[1], 'r+') as f: f['runs'][sys.argv[2]]['com'][10, 0] += 1e-6" \
  "$WORKDIR/changed.h5" "$run"
status=0
"$wpg" diff "$WORKDIR/j1.h5" "$WORKDIR/changed.h5" >"$WORKDIR/out" || status=$?
cat "$WORKDIR/out"
[[ $status == 1 ]] || fail "a changed run: exit status $status, expected 1"
grep -q "^first differing sample: /runs/$run/com row 10, column 0 (x): " "$WORKDIR/out" \
  || fail "the changed sample is not reported"
[[ "$(grep -c '^  /' "$WORKDIR/out")" == 1 ]] || fail "other fields reported"

status=0
"$wpg" diff "$WORKDIR/j1.h5" "$reference" >"$WORKDIR/out" || status=$?
[[ $status == 1 ]] || fail "batch vs run file: exit status $status, expected 1"
grep -q "^  /@study: only in A" "$WORKDIR/out" || fail "batch vs run file: /@study not named"
grep -q "^  /@scenario: only in B" "$WORKDIR/out" || fail "batch vs run file: /@scenario not named"
echo "ok"
