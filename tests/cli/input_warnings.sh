#!/usr/bin/env bash
# input_warnings.sh WPG: a value the loader accepts but clamps or finds implausible warns, one
# line on stderr ("wpg: warning: FILE: key 'KEY': ...") and a line of the run's `warnings`
# attribute; the walk and the exit status are those without the warning: a 2.0 m/s command
# walks exactly as a 0.4 m/s one (the clamp). A CoM height in cm and a goal yaw in degrees warn;
# a batch run warns with its study, run and sweep; a run without warnings has no attribute.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
cd "$WORKDIR"
run() {  # run NAME ARGS...: wpg run into NAME.h5, stderr into NAME.err, status into NAME.status
  local name="$1"; shift
  local status=0
  "$wpg" run --no-plot -o "$name.h5" "$@" >"$name.out" 2>"$name.err" || status=$?
  echo "$status" >"$name.status"
}
attribute() {  # attribute FILE.h5 RUN: the run's warnings attribute, or "(none)"
  "$PYTHON" - "$1" "$2" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    attrs = f["runs"][sys.argv[2]].attrs
    value = attrs["warnings"] if "warnings" in attrs else "(none)"
    print(value.decode() if isinstance(value, bytes) else value, end="")
PY
}

# A command beyond the forward clamp (0.4 m/s): warned, clamped, the same walk as 0.4 m/s.
run fast walk_forward --set duration=3 --set 'reference[1].v=[2.0, 0, 0]'
run clamped walk_forward --set duration=3 --set 'reference[1].v=[0.4, 0, 0]'
cat fast.err
[[ "$(cat fast.status)" == "$(cat clamped.status)" ]] \
  || fail "exit status $(cat fast.status) with the warning, $(cat clamped.status) without"
[[ "$(wc -l <fast.err)" == 1 ]] || fail "expected one line on stderr, got: $(cat fast.err)"
grep -Eq "^wpg: warning: .*walk_forward\.yaml: key 'reference\[1\]\.v\[0\]': 2\.0 m/s is beyond walking\.max_forward_velocity 0\.4 m/s: the command is clamped to 0\.4 m/s \(set by --set 'reference\[1\]\.v=\[2\.0, 0, 0\]'\)$" fast.err \
  || fail "warning line: $(cat fast.err)"
if grep -q warning clamped.err; then fail "a command at the clamp warns: $(cat clamped.err)"; fi
[[ "$(attribute fast.h5 walk_forward)" == "$(sed 's/^wpg: warning: //' fast.err)" ]] \
  || fail "warnings attribute: '$(attribute fast.h5 walk_forward)'"

# A command inside the clamps that no gait reaches (0.3 m/s sideways; HRP-2's shortest steps,
# 0.5 s, reach 0.2): warned, with what happens; one the gait reaches (0.15 m/s) is not.
run sideways walk_forward --set duration=3 --set 'reference[1].v=[0, 0.3, 0]'
run reachable walk_forward --set duration=3 --set 'reference[1].v=[0, 0.15, 0]'
[[ "$(wc -l <sideways.err)" == 1 ]] || fail "beyond the reach: not one line: $(cat sideways.err)"
grep -Eq "key 'reference\[1\]\.v': \[0\.0, 0\.3, 0\.0\] is beyond the reach of the gait \(steps of 0\.5 s inside walking\.feasibility_x/y walk [0-9]+% of it\): the robot falls behind the command and may fall \(set by --set 'reference\[1\]\.v=\[0, 0\.3, 0\]'\)$" sideways.err \
  || fail "beyond the reach: $(cat sideways.err)"
if grep -q warning reachable.err; then fail "a command the gait reaches warns: $(cat reachable.err)"; fi
[[ "$(attribute clamped.h5 walk_forward)" == "(none)" ]] || fail "a run without warnings has the attribute"
# The walk is the clamped one, bit for bit: only the stored scenario and the warning differ.
"$wpg" diff fast.h5 clamped.h5 --rtol 0 --atol 0 --ignore '*@scenario' --ignore '*@warnings' \
  >diff.out || fail "the walk of 2.0 m/s differs from that of 0.4 m/s: $(cat diff.out)"

# A CoM height in cm: warned (the walk runs as given; its status is the walk's).
run centimetres walk_forward --set duration=2 --set walking.com_height=81.4
cat centimetres.err
grep -Eq "^wpg: warning: .*walk_forward\.yaml: key 'walking\.com_height': 81\.4 m is outside the plausible CoM heights of robot 'hrp2'" centimetres.err \
  || fail "no com_height warning: $(cat centimetres.err)"
[[ "$(cat centimetres.status)" != 2 ]] || fail "a warning turned into bad input"

# A goal yaw in degrees.
run degrees goal_with_yaw --set duration=1 --set goal.yaw=90
cat degrees.err
grep -Eq "^wpg: warning: .*goal_with_yaw\.yaml: key 'goal\.yaw': 90\.0 rad is more than a turn" degrees.err \
  || fail "no goal.yaw warning: $(cat degrees.err)"
[[ "$(cat degrees.status)" != 2 ]] || fail "a warning turned into bad input"

# A batch: the run whose swept command clamps warns, with the study, run and sweep named.
cat >study.yaml <<'YAML'
name: speeds
base: walk_forward
sweep:
  grid:
    duration: [1.5]
    "reference[1].v": [[0.2, 0, 0], [0.9, 0, 0]]
YAML
status=0
"$wpg" batch study.yaml -o batch.h5 -j 1 --no-plot >batch.out 2>batch.err || status=$?
cat batch.err
[[ $status != 2 ]] || fail "batch: exit 2"
[[ "$(grep -c 'wpg: warning:' batch.err)" == 1 ]] || fail "batch: expected one warning"
grep -Eq "^wpg: warning: study\.yaml: run 1 \(.*reference\[1\]\.v=[^)]*0\.9[^)]*\): .*key 'reference\[1\]\.v\[0\]': 0\.9 m/s is beyond .* \(set by sweep 'reference\[1\]\.v=" batch.err \
  || fail "batch warning line: $(cat batch.err)"
[[ "$(attribute batch.h5 speeds_1)" == *"0.9 m/s is beyond"* ]] || fail "batch run 1 lacks its warning"
[[ "$(attribute batch.h5 speeds_0)" == "(none)" ]] || fail "batch run 0 has a warning"
echo "ok"
