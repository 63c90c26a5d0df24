#!/usr/bin/env bash
# run_blocked.sh WPG: the shipped wall with no way round (obstacle_wall) ends blocked: exit 1,
# the summary as any run's, one error line saying where and since when the robot is blocked;
# the dataset holds blocked = 1, blocked_since 8.9 s and the CoM then, success 0, the message,
# and the whole walk's progress_ratio, which numpy recomputes from com and
# mpc/commanded_velocity (datasets/METRICS.md). generator.stop_when_blocked ends the walk at
# 13.7 s, where it is found blocked.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
status=0
"$wpg" run obstacle_wall --no-plot -o "$WORKDIR/wall.h5" \
  >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
cat "$WORKDIR/stdout"; cat "$WORKDIR/stderr" >&2
[[ $status == 1 ]] || fail "exit status $status, expected 1 (blocked)"
for word in walked status solve obstacles dataset; do
  grep -q "^$word " "$WORKDIR/stdout" || fail "summary lacks the '$word' line"
done
[[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "expected one line on stderr"
grep -qx "wpg: error: the walk failed: the robot is blocked: 0.00 m walked of the 0.96 m commanded in the 4.8 s to t = 29.9 s, since t = 8.9 s at (1.29, -0.01) m (dataset written)" \
  "$WORKDIR/stderr" || fail "the error line does not say where and since when the robot is blocked"
check_run_file "$WORKDIR/wall.h5"
"$PYTHON" - "$WORKDIR/wall.h5" <<'PY' || fail "bad blocked records in the dataset"
import sys
import h5py
import numpy as np
import yaml
with h5py.File(sys.argv[1], "r") as f:
    run = f["runs/obstacle_wall"]
    a = run.attrs
    assert int(a["blocked"]) == 1 and int(a["success"]) == 0, dict(a)
    assert abs(a["blocked_since"] - 8.9) < 1e-9, a["blocked_since"]
    com, time = run["com"][()], run["time"][()]
    i = int(np.argmin(abs(time - a["blocked_since"])))
    assert (a["blocked_x"], a["blocked_y"]) == tuple(com[i, :2]), (a["blocked_x"], a["blocked_y"])
    assert a["message"].startswith("the robot is blocked: "), a["message"]
    # progress_ratio as METRICS.md defines it, from the raw fields
    walking = yaml.safe_load(f.attrs["scenario"])["walking"]
    T = walking["sampling_period"]
    sub = round(T / walking["control_period"])
    v = run["mpc/commanded_velocity"][()]
    rows = np.round(run["mpc/time"][()] / walking["control_period"]).astype(int)
    keep = (rows + sub <= len(time) - 1) & (np.linalg.norm(v, axis=1) > 1e-3)
    d = v[keep] * T
    length = np.linalg.norm(d, axis=1)
    walked = np.sum(np.sum((com[rows[keep] + sub, :2] - com[rows[keep], :2]) * d, axis=1) / length)
    ratio = walked / length.sum()
    assert abs(ratio - a["progress_ratio"]) <= 1e-12, (ratio, a["progress_ratio"])
    assert 0.2 < ratio < 0.3, ratio
    print("blocked since %.1f s at (%.2f, %.2f) m, progress_ratio %.3f"
          % (a["blocked_since"], a["blocked_x"], a["blocked_y"], ratio))
PY

# Stopped where it is found blocked: one window after the stretch's start.
status=0
"$wpg" run obstacle_wall --no-plot -o "$WORKDIR/stopped.h5" --set generator.stop_when_blocked=true \
  >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
[[ $status == 1 ]] || fail "stop_when_blocked: exit status $status, expected 1"
grep -q "in the 4.8 s to t = 13.7 s, since t = 8.9 s" "$WORKDIR/stderr" \
  || fail "stop_when_blocked: $(cat "$WORKDIR/stderr")"
"$PYTHON" - "$WORKDIR/stopped.h5" <<'PY' || fail "stop_when_blocked: the walk does not end at 13.7 s"
import sys
import h5py
with h5py.File(sys.argv[1], "r") as f:
    run = f["runs/obstacle_wall"]
    assert int(run.attrs["blocked"]) == 1
    assert abs(run["time"][-1] - 13.7) < 1e-9, run["time"][-1]
PY
echo "ok"
