#!/usr/bin/env bash
# run_goal_not_reached.sh WPG SCENARIO ARGS...: `wpg run SCENARIO ARGS...` on a walk to a goal
# that cannot be reached (e.g. the U trap without a planner) exits 1, says on one stderr line
# that the goal was not reached, prints the goal line, and still writes the dataset, which says
# why (check_goal_run.py --not-reached).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; scenario="$2"; shift 2
make_workdir
status=0
"$wpg" run "$scenario" -o "$WORKDIR/run.h5" "$@" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
cat "$WORKDIR/stdout"; cat "$WORKDIR/stderr" >&2
[[ $status == 1 ]] || fail "exit status $status, expected 1"
[[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "expected one line on stderr"
grep -q "goal not reached" "$WORKDIR/stderr" || fail "stderr does not say the goal was not reached"
grep -q '^goal      not reached (' "$WORKDIR/stdout" || fail "no 'goal      not reached' line"
check_run_file "$WORKDIR/run.h5"
"$PYTHON" "$HERE/check_goal_run.py" "$WORKDIR/run.h5" --not-reached || fail "bad goal run"
echo "ok"
