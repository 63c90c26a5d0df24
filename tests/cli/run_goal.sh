#!/usr/bin/env bash
# run_goal.sh WPG SCENARIO [CHECK_GOAL_RUN ARGS...]: `wpg run SCENARIO` on a walk to a goal exits
# 0 with the goal line (reached) in its summary, the FCL post-check finds every step centre
# outside every margin grown by the sole radius, and the dataset has the goal's attributes, the
# plans and a standing pose within the tolerance (check_goal_run.py). Without its figure:
# cli.run.<scenario> draws the figure of every shipped walk to a goal (1.4 s of CPU each).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; scenario="$2"; shift 2
make_workdir
status=0
"$wpg" run "$scenario" --no-plot -o "$WORKDIR/run.h5" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
cat "$WORKDIR/stdout"; cat "$WORKDIR/stderr" >&2
[[ $status == 0 ]] || fail "exit status $status"
[[ ! -s "$WORKDIR/stderr" ]] || fail "unexpected output on stderr"
grep -Eq '^goal      reached in [0-9.]+ s, route [0-9.]+ m, [0-9]+ replans?, planning [0-9.]+ ms$' \
  "$WORKDIR/stdout" || fail "no 'goal      reached in ...' line"
# The FCL world's post-check of every step (wpg/planning/obstacle_checks.hpp) as printed.
centre="$(sed -n 's/^obstacles .*(the NMPC.s constraint) \(-\{0,1\}[0-9.]*\) m.*/\1/p' "$WORKDIR/stdout")"
[[ -n "$centre" ]] || fail "no obstacles line"
awk -v c="$centre" 'BEGIN { exit !(c >= 0) }' || fail "a step centre is inside a margin: $centre m"
check_run_file "$WORKDIR/run.h5"
oracle check_goal_run.py "$WORKDIR/run.h5" "$@" || fail "bad goal run"
echo "ok"
