#!/usr/bin/env bash
# diff_tolerance.sh WPG REFERENCE.h5: `wpg diff` applies |a - b| <= atol + rtol max(|a|, |b|)
# sample by sample and reports the sample it failed on. Copies of the reference with one CoM
# sample scaled by (1 + 0.5e-9) and (1 + 2e-9), compared at rtol 1e-9, atol 0: the first is the
# same (exit 0), the second differs (exit 1) at exactly that row and column, with both values.
# A changed wall time (mpc/solve_time) is ignored unless --compare-wall-time; a changed
# attribute and a missing dataset are reported by name.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; reference="$2"
make_workdir
run="$("$PYTHON" -c "import h5py, sys; print(list(h5py.File(sys.argv[1], 'r')['runs'])[0])" "$reference")"

# edit COPY PYTHON-STATEMENT: a copy of the reference with `f` (h5py, r+) edited by the statement.
edit() {
  cp "$reference" "$WORKDIR/$1"
  "$PYTHON" -c "import h5py, sys
f = h5py.File(sys.argv[1], 'r+'); r = f['runs'][sys.argv[2]]
$2
f.close()" "$WORKDIR/$1" "$run"
}
diff_status() {  # diff_status FILE ARGS...: runs wpg diff into $WORKDIR/out, echoes its status
  local status=0
  "$wpg" diff "$reference" "$WORKDIR/$1" "${@:2}" >"$WORKDIR/out" 2>&1 || status=$?
  echo "$status"
}

edit inside.h5 "r['com'][400, 1] = r['com'][400, 1] * (1 + 0.5e-9)"
[[ "$(diff_status inside.h5 --rtol 1e-9 --atol 0)" == 0 ]] || fail "within rtol: $(cat "$WORKDIR/out")"
grep -q "^same within tolerance; largest relative difference [0-9.e-]* (/runs/$run/com)" "$WORKDIR/out" \
  || fail "the largest difference within tolerance is not reported: $(cat "$WORKDIR/out")"
[[ "$(diff_status inside.h5 --rtol 1e-10 --atol 0)" == 1 ]] || fail "beyond rtol 1e-10 not detected"

edit outside.h5 "r['com'][400, 1] = r['com'][400, 1] * (1 + 2e-9)"
[[ "$(diff_status outside.h5 --rtol 1e-9 --atol 0)" == 1 ]] || fail "beyond rtol: $(cat "$WORKDIR/out")"
cat "$WORKDIR/out"
grep -q "^first differing sample: /runs/$run/com row 400, column 1 (y): A [0-9.e-]*, B [0-9.e-]*, |A - B| [0-9.e-]* > tolerance" \
  "$WORKDIR/out" || fail "the first differing sample is not reported as row 400, column 1 (y)"
grep -q "^  /runs/$run/com: 1 of [0-9]* values differ" "$WORKDIR/out" || fail "count of differing samples"
[[ "$(grep -c '^  /' "$WORKDIR/out")" == 1 ]] || fail "other fields reported"

edit wall_time.h5 "r['mpc/solve_time'][0] = 1.0"
[[ "$(diff_status wall_time.h5)" == 0 ]] || fail "a wall time was compared: $(cat "$WORKDIR/out")"
[[ "$(diff_status wall_time.h5 --compare-wall-time)" == 1 ]] || fail "--compare-wall-time ignored"
grep -q "^  /runs/$run/mpc/solve_time: " "$WORKDIR/out" || fail "solve_time not named"

edit attribute.h5 "r.attrs.modify('success', 0); del r['footstep_side']"
[[ "$(diff_status attribute.h5)" == 1 ]] || fail "attribute change not detected"
grep -q "^  /runs/$run@success: 1 of 1 values differ" "$WORKDIR/out" || fail "attribute not named: $(cat "$WORKDIR/out")"
grep -q "^  /runs/$run/footstep_side: only in A" "$WORKDIR/out" || fail "missing dataset not named"
echo "ok"
