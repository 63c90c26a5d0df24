#!/usr/bin/env bash
# run_on_robot.sh WPG ROBOT SCENARIO.yaml STATUS: `wpg run SCENARIO --set robot=ROBOT` exits
# STATUS (0, or 1 for the scenes that end blocked on HRP-2 too, with the 'blocked' line), writes
# a dataset with the schema's datasets whose stored scenario names ROBOT, and, when it walks to
# the end, prints nothing on stderr: no command of the shipped scenario is clamped to ROBOT's
# speeds (the clamp is a warning there, docs/robots.md).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; robot="$2"; scenario="$3"; expected="$4"
make_workdir
status=0
"$wpg" run "$scenario" --set "robot=$robot" --no-plot -o "$WORKDIR/run.h5" \
  >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
cat "$WORKDIR/stdout"; cat "$WORKDIR/stderr" >&2
[[ $status == "$expected" ]] || fail "exit status $status, expected $expected"
grep -q "robot $robot, " "$WORKDIR/stdout" || fail "the summary does not name $robot"
if [[ $expected == 0 ]]; then
  [[ ! -s "$WORKDIR/stderr" ]] || fail "unexpected output on stderr"
else
  grep -q "the robot is blocked" "$WORKDIR/stderr" || fail "exit $status without 'blocked'"
  [[ "$(grep -vc 'the robot is blocked' "$WORKDIR/stderr")" == 0 ]] || fail "other stderr lines"
fi
check_run_file "$WORKDIR/run.h5"
"$PYTHON" - "$WORKDIR/run.h5" "$robot" <<'PY' || fail "the stored scenario does not name $2"
import sys, h5py
text = h5py.File(sys.argv[1], "r").attrs["scenario"]
sys.exit(0 if "robot: " + sys.argv[2] in text else 1)
PY
echo "ok"
