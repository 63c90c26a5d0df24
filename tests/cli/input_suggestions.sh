#!/usr/bin/env bash
# input_suggestions.sh WPG: an unknown key or planner name is refused (exit 2, one line, nothing
# written) with the nearest known name ("did you mean 'algorithm'?"); planner names are read
# case-insensitively (RRTConnect) and stored by their canonical name.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
cd "$WORKDIR"
refused() {  # refused EXPECTED_TEXT ARGS...: `wpg run ARGS` exits 2 with one line holding it
  local expected="$1"; shift
  local status=0
  rm -f out.h5
  "$wpg" run --no-plot -o out.h5 "$@" >out.txt 2>err.txt || status=$?
  cat err.txt
  [[ $status == 2 ]] || fail "$*: exit status $status, expected 2"
  [[ "$(wc -l <err.txt)" == 1 ]] || fail "$*: expected one line on stderr"
  grep -qF -- "$expected" err.txt || fail "$*: '$expected' not in: $(cat err.txt)"
  [[ ! -e out.h5 ]] || fail "$*: a dataset was written"
}
refused "did you mean 'rrtconnect'?" goal_with_yaw --set planner.algorithm=rrtconect
refused "did you mean 'algorithm'?" goal_with_yaw --set planner.algoritm=rrtconnect
refused "did you mean 'com_height'?" walk_forward --set walking.com_heigth=0.8
refused "did you mean 'duration'?" walk_forward --set durration=3
refused "did you mean 'command_tangent'?" walk_forward --set walking.obstacle_linearization=comand_tangent
refused "did you mean 'lmpc'?" walk_forward --set generator.algorithm=lmcp

# RRTConnect is rrtconnect: it runs, and the dataset stores the canonical name.
status=0
"$wpg" run --no-plot -o case.h5 goal_with_yaw --set duration=1 --set planner.algorithm=RRTConnect \
  >case.txt 2>case.err || status=$?
cat case.err
[[ $status != 2 ]] || fail "RRTConnect refused: $(cat case.err)"
"$PYTHON" - case.h5 <<'PY' || fail "the stored scenario does not name rrtconnect"
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    run = f["runs"]["goal_with_yaw"]
    text = run.attrs["scenario"] if "scenario" in run.attrs else f.attrs["scenario"]
    text = text.decode() if isinstance(text, bytes) else text
    assert "algorithm: rrtconnect" in text, text
PY
echo "ok"
