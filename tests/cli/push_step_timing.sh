#!/usr/bin/env bash
# push_step_timing.sh WPG: a push across the gait (40 N towards -y at t = 3.7 s while walking
# forward: the capture point lands 83 mm towards the foot about to lift, against 40-68 mm in
# regular walking) is caught by a shortened step (walking.push_step_capture_offset, adaptive
# step timing): the walk recovers with every NMPC iteration solved and the swing foot within
# 2 m/s and 50 m/s², a step after the push has less than the regular 0.7 s of single support
# and the steps before it have 0.7 s; with the key at 0 (the steps keep their timing) the same
# push ends in a fall.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
push='pushes[0]={t: 3.7, force: [0.0, -40.0], duration: 0.1}'
status=0
"$wpg" run push --set "$push" --no-plot -o "$WORKDIR/short.h5" >"$WORKDIR/stdout" 2>&1 ||
  status=$?
[[ $status == 0 ]] || fail "shortened step: exit $status: $(cat "$WORKDIR/stdout")"
grep -Eq '^status +[0-9]+ solved \(' "$WORKDIR/stdout" ||
  fail "shortened step: an NMPC iteration not solved: $(grep '^status' "$WORKDIR/stdout")"
"$PYTHON" - "$WORKDIR/short.h5" <<'PY' || fail "shortened step: see above"
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    run = next(iter(f["runs"].values()))
    steps = run["footsteps"][:]
    lift = run["footstep_lift_off"][:]
    speed = float(run["checks"].attrs["swing_foot_speed_max"])
    accel = float(run["checks"].attrs["swing_foot_acceleration_max"])
single = steps[2:, 0] - lift[2:]
before = single[steps[2:, 0] < 3.7]
after = single[lift[2:] > 3.7]
print(f"single supports before the push {np.unique(np.round(before, 3))}, after {np.round(after[:4], 3)}")
print(f"swing foot peak {speed:.2f} m/s, {accel:.1f} m/s^2")
ok = True
if not np.allclose(before[1:], 0.7, atol=1e-9):
    print("the steps before the push are not the regular 0.7 s"); ok = False
if not (len(after) and after.min() < 0.7 - 1e-9):
    print("no shortened step after the push"); ok = False
if not (speed <= 2.0 and accel <= 50.0):
    print("the swing foot is beyond 2 m/s or 50 m/s^2"); ok = False
sys.exit(0 if ok else 1)
PY
status=0
"$wpg" run push --set "$push" --set walking.push_step_capture_offset=0 --no-plot \
  -o "$WORKDIR/regular.h5" >"$WORKDIR/stdout" 2>&1 || status=$?
grep -q "fallen" "$WORKDIR/stdout" ||
  fail "without the shortened step the push was expected to end in a fall: $(cat "$WORKDIR/stdout")"
echo "ok"
