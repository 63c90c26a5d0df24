#!/usr/bin/env bash
# push_sweep.sh WPG: `wpg push-sweep` on one situation with 2 phases (kept small for ctest):
# the JSON, the HDF5 table and the figure are written and agree; two of the JSON's pushes replay
# with `wpg run --set pushes[0]=...` (recovered; 15 % stronger fails: check_push_sweep.py);
# -j 1 and -j 2 give the same JSON byte for byte; --set is applied (a scenario file beside
# the output, named in the JSON, that replays too).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
cd "$WORKDIR"
"$wpg" push-sweep --help >help || fail "push-sweep --help: exit $?"
grep -q 'out/push_sweep.h5' help && grep -q 'K=8' help && grep -q -- '--max-force N=600' help ||
  fail "push-sweep --help does not show the defaults"
"$wpg" push-sweep --situation on_spot --phases 2 -j 2 --json sweep.json -o sweep.h5 >stdout ||
  fail "push-sweep: exit $?"
grep -q "^on_spot   coronal- .* -45 " stdout || fail "no table row beside the paper's: $(cat stdout)"
check_png sweep.png
"$PYTHON" "$HERE/check_push_sweep.py" "$wpg" sweep.h5 sweep.json 2 on_spot ||
  fail "push-sweep files disagree or do not replay"
"$wpg" push-sweep --situation on_spot --phases 2 -j 1 --json sweep1.json -o sweep1.h5 --no-plot \
  >/dev/null 2>&1 || fail "push-sweep -j 1: exit $?"
cmp -s sweep.json sweep1.json || fail "-j 1 and -j 2 differ: $(diff sweep.json sweep1.json | head -5)"
[[ ! -e sweep1.png ]] || fail "--no-plot drew a figure"
"$wpg" push-sweep --situation on_spot --phases 1 --set walking.max_landing_speed=0.4 \
  --set walking.max_landing_yaw_rate=1.5 --json set.json -o set.h5 --no-plot >/dev/null 2>&1 ||
  fail "push-sweep --set: exit $?"
grep -q "max_landing_speed: 0.4" set.on_spot.yaml || fail "set.on_spot.yaml lacks the override"
grep -q '"scenario": "set.on_spot.yaml"' set.json || fail "set.json does not name set.on_spot.yaml"
"$PYTHON" "$HERE/check_push_sweep.py" "$wpg" set.h5 set.json 1 on_spot ||
  fail "push-sweep --set files disagree or do not replay"
echo "ok"
