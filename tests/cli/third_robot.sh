#!/usr/bin/env bash
# third_robot.sh WPG: robots of other proportions made as docs/robots.md ("Add your robot")
# says, in a data directory of their own: HRP-2 scaled to 0.6 of its size (a 0.92 m child-size
# robot, 12.1 kg: make_scaled_robot.py), its sole frames and standing posture renamed; `kid`
# keeps six joints a leg (the closed-form IK), `kid7` has a seventh, a thigh twist (the
# numerical IK). `wpg robot check` passes once com_height is set to the standing posture's CoM
# height it prints; walk_forward and walk_sideways walk on each, `wpg replay` replays and
# filters them: the IK reaches every foot target (1e-9 m) within the joint limits, and the
# dynamic filter cuts the multibody ZMP error (RMS and max) at least 3 times.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
data="$WORKDIR/data"
mkdir -p "$data/robots/kid" "$data/robots/kid7" "$data/datasets"
cp -r "$WPG_DATA_DIR/datasets/scenarios" "$data/datasets/"
cp -r "$WPG_DATA_DIR/analysis" "$data/"
hrp2="$WPG_DATA_DIR/robots/hrp2"
"$PYTHON" "$HERE/make_scaled_robot.py" "$hrp2" "$data/robots/kid" kid 0.6 || fail "kid"
"$PYTHON" "$HERE/make_scaled_robot.py" "$hrp2" "$data/robots/kid7" kid7 0.6 --thigh-twist \
  || fail "kid7"
export WPG_DATA_DIR="$data"

walk_and_replay() {  # walk_and_replay ROBOT JOINTS IK: docs/robots.md's steps 4 and 5
  local robot=$1 joints=$2 ik=$3 check="$WORKDIR/$1.check"
  # Step 4: check, set com_height to the standing posture's CoM height, check again.
  "$wpg" robot check "$robot" >"$check" 2>&1 || true
  cat "$check"
  local standing
  standing=$(sed -nE 's/^  CoM height +standing posture stand ([0-9.]+) m;.*/\1/p' "$check")
  [[ -n "$standing" ]] || fail "$robot: no standing CoM height in the check"
  sed -i -E "s/^com_height: [0-9.]+/com_height: $standing/" "$data/robots/$robot/walking.yaml"
  "$wpg" robot check "$robot" >"$check" 2>"$check.err" || fail "$robot check: exit $?"
  cat "$check"
  [[ ! -s "$check.err" ]] || fail "$robot check warns: $(cat "$check.err")"
  grep -q "${robot}_left_sole $joints joints, ${robot}_right_sole $joints joints; straight 0.4235 m, 0.4235 m (hip to sole); IK $ik, $ik" \
    "$check" || fail "$robot legs: not $joints joints, $ik IK, 0.6 x HRP-2's 0.7059 m"
  grep -q "declared $standing m" "$check" || fail "$robot: com_height not taken"
  # Step 5: walk, then replay and filter.
  local scenario out
  for scenario in walk_forward walk_sideways; do
    out="$WORKDIR/${robot}_$scenario"
    "$wpg" run "$scenario" --set "robot=$robot" --no-plot -o "$out.h5" >"$out.txt" \
      2>"$out.err" || fail "$robot $scenario: exit $?: $(cat "$out.err")"
    [[ ! -s "$out.err" ]] || fail "$robot $scenario: $(cat "$out.err")"
    "$wpg" replay "$out.h5" --no-plot -o "${out}_replayed.h5" >"$out.txt" 2>&1 \
      || fail "replay $robot $scenario: exit $?: $(cat "$out.txt")"
    check_multibody "${out}_replayed.h5" --filtered --min-reduction 3
    "$PYTHON" - "${out}_replayed.h5" "$scenario" "$robot" <<'PY' || fail "$robot $scenario replay"
import sys
import h5py
f = h5py.File(sys.argv[1], "r")
run = f["runs/" + sys.argv[2]]
m = run["multibody"].attrs
assert "robot: " + sys.argv[3] in f.attrs["scenario"]
assert m["ik_failures"] == 0 and m["samples_with_limit_violations"] == 0, dict(m)
assert m["max_ik_foot_error"] < 1e-9 and m["max_ik_com_error"] < 1e-9, dict(m)
assert run["left_foot"].shape[0] > 1000, run["left_foot"].shape
print(f"{sys.argv[3]} {sys.argv[2]}: feet within {m['max_ik_foot_error']:.1e} m, ZMP RMS "
      f"{1e3 * m['zmp_error_rms_before']:.1f} -> {1e3 * m['zmp_error_rms_after']:.1f} mm, max "
      f"{1e3 * m['zmp_error_max_before']:.1f} -> {1e3 * m['zmp_error_max_after']:.1f} mm")
PY
  done
}
walk_and_replay kid 6 analytic
# Not in the sanitizer tree (WPG_SANITIZED): the numerical IK runs under ASan + UBSan in
# test_numerical_leg_ik.cpp (generated 6- and 7-joint legs, a step walked) and
# test_walking_reach.cpp (the walkable heights with HRP-2's legs solved numerically).
[[ "${WPG_SANITIZED:-0}" == 1 ]] || walk_and_replay kid7 7 numerical
echo "ok"
