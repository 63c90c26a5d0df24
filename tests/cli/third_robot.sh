#!/usr/bin/env bash
# third_robot.sh WPG: a robot of other proportions made as docs/robots.md ("Add your robot")
# says, in a data directory of its own: HRP-2 scaled to 0.6 of its size (a 0.92 m child-size
# robot, 12.1 kg: make_scaled_robot.py), its sole frames and standing posture renamed. `wpg
# robot check` passes once com_height is set to the standing posture's CoM height it prints;
# walk_forward and walk_sideways walk on it, `wpg replay` replays and filters them: the IK
# reaches every foot target (1e-9 m) within the joint limits, and the dynamic filter cuts the
# multibody ZMP error (RMS and max) at least 3 times.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
data="$WORKDIR/data"
mkdir -p "$data/robots/kid" "$data/datasets"
cp -r "$WPG_DATA_DIR/datasets/scenarios" "$data/datasets/"
cp -r "$WPG_DATA_DIR/analysis" "$data/"
"$PYTHON" "$HERE/make_scaled_robot.py" "$WPG_DATA_DIR/robots/hrp2" "$data/robots/kid" kid 0.6 \
  || fail "make_scaled_robot.py"
export WPG_DATA_DIR="$data"

# Step 4: check, set com_height to the standing posture's CoM height, check again.
status=0
"$wpg" robot check kid >"$WORKDIR/check.txt" 2>&1 || status=$?
cat "$WORKDIR/check.txt"
standing=$(sed -nE 's/^  CoM height +standing posture stand ([0-9.]+) m;.*/\1/p' "$WORKDIR/check.txt")
[[ -n "$standing" ]] || fail "no standing CoM height in the check"
sed -i -E "s/^com_height: [0-9.]+/com_height: $standing/" "$data/robots/kid/walking.yaml"
"$wpg" robot check kid >"$WORKDIR/check.txt" 2>"$WORKDIR/check.err" || fail "check: exit $?"
cat "$WORKDIR/check.txt"
[[ ! -s "$WORKDIR/check.err" ]] || fail "check warns: $(cat "$WORKDIR/check.err")"
grep -q "kid_left_sole 6 joints, kid_right_sole 6 joints; straight 0.4235 m" "$WORKDIR/check.txt" \
  || fail "legs: not 0.6 x HRP-2's 0.7059 m"
grep -q "declared $standing m" "$WORKDIR/check.txt" || fail "com_height not taken"

# Step 5: walk, then replay and filter.
for scenario in walk_forward walk_sideways; do
  "$wpg" run "$scenario" --set robot=kid --no-plot -o "$WORKDIR/$scenario.h5" \
    >"$WORKDIR/run.txt" 2>"$WORKDIR/run.err" || fail "$scenario: exit $?: $(cat "$WORKDIR/run.err")"
  [[ ! -s "$WORKDIR/run.err" ]] || fail "$scenario: $(cat "$WORKDIR/run.err")"
  "$wpg" replay "$WORKDIR/$scenario.h5" --no-plot -o "$WORKDIR/${scenario}_replayed.h5" \
    >"$WORKDIR/replay.txt" 2>&1 || fail "replay $scenario: exit $?: $(cat "$WORKDIR/replay.txt")"
  grep '^multibody' "$WORKDIR/replay.txt" | sed "s/^/$scenario: /"
  check_multibody "$WORKDIR/${scenario}_replayed.h5" --filtered --min-reduction 3
  "$PYTHON" - "$WORKDIR/${scenario}_replayed.h5" "$scenario" <<'PY' || fail "$scenario replay"
import sys
import h5py
run = h5py.File(sys.argv[1], "r")["runs/" + sys.argv[2]]
m = run["multibody"].attrs
assert "robot: kid" in h5py.File(sys.argv[1], "r").attrs["scenario"]
assert m["ik_failures"] == 0 and m["samples_with_limit_violations"] == 0, dict(m)
assert m["max_ik_foot_error"] < 1e-9 and m["max_ik_com_error"] < 1e-9, dict(m)
assert run["left_foot"].shape[0] > 1000 and "time" in run, run["left_foot"].shape
print(f"{sys.argv[2]}: feet within {m['max_ik_foot_error']:.1e} m, ZMP RMS "
      f"{1e3 * m['zmp_error_rms_before']:.1f} -> {1e3 * m['zmp_error_rms_after']:.1f} mm")
PY
done
echo "ok"
