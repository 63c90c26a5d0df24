#!/usr/bin/env bash
# run_relaxed_obstacle.sh WPG: paper_experiment_a with the obstacle 0.2 m off the path at 1.4 m
# and the paper's linearization at the step, J1 on the mean velocity over a step (the scenario as
# it shipped before the obstacle-on-the-path defaults; the shipped one never relaxes) relaxes
# obstacle rows only, which does not fail the walk: exit 0, mpc/status holds
# relaxed_obstacle (code 1) rows, and the obstacle column of mpc/slack is positive on exactly
# those rows (its relaxed_families bit set there only), every other slack column zero. The
# summary's clearance line names the NMPC's constraint, whose margin a successful walk keeps
# (>= 0, printed without a "-0.000").
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
status=0
"$wpg" run paper_experiment_a --no-plot -o "$WORKDIR/relaxed.h5" \
  --set 'obstacles[0].center=[1.4,-0.2]' --set walking.obstacle_linearization=step \
  --set walking.velocity_window_samples=8 --set walking.weight_yaw=2.5 \
  --set generator.obstacle_reach=1.5 --set duration=30 \
  >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
cat "$WORKDIR/stdout"; cat "$WORKDIR/stderr" >&2
[[ $status == 0 ]] || fail "exit status $status, expected 0"
[[ ! -s "$WORKDIR/stderr" ]] || fail "unexpected output on stderr"
grep -Eq '^status    .*[0-9]+ relaxed_obstacle' "$WORKDIR/stdout" \
  || fail "the summary's status line does not mention relaxed_obstacle"
grep -Eq "^obstacles 1; least clearance: step centre to margin \+ obstacle_foot_radius \(the NMPC's constraint\) [0-9]+\.[0-9]{3} m, sole to margin -?[0-9]+\.[0-9]{3} m; sole to obstacle -?[0-9]+\.[0-9]{3} m\$" \
  "$WORKDIR/stdout" || fail "the summary lacks the obstacle clearance line (or its centre clearance < 0)"
! grep -q -- '-0\.000 ' "$WORKDIR/stdout" || fail "the summary prints -0.000"
check_run_file "$WORKDIR/relaxed.h5"
"$PYTHON" - "$WORKDIR/relaxed.h5" <<'PY' || fail "bad relaxation records in the dataset"
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    run = f["runs/paper_experiment_a"]
    status = run["mpc/status"][()]
    slack = run["mpc/slack"][()]
    families = run["mpc/relaxed_families"][()]
    columns = [c.strip() for c in str(run["mpc/slack"].attrs["columns"]).split(",")]
    assert columns == ["cop", "step_feasibility", "yaw_bound", "obstacle", "landing_bound", "landing_yaw_bound", "swing_reach"], columns
    assert slack.shape == (status.size, 7), slack.shape
    assert "1=relaxed_obstacle" in run["mpc/status"].attrs["codes"]
    relaxed = status == 1  # 1 = relaxed_obstacle
    assert relaxed.any(), "no relaxed_obstacle row"
    assert set(np.unique(status)) <= {0, 1}, f"statuses {np.unique(status)}"
    obstacle = columns.index("obstacle")
    assert np.array_equal(slack[:, obstacle] > 0, relaxed), "obstacle slack not on exactly the relaxed rows"
    others = np.delete(slack, obstacle, axis=1)
    assert not others.any(), "slack in a family other than obstacle"
    assert np.array_equal(families, np.where(relaxed, 1 << obstacle, 0)), families
    assert int(run.attrs["success"]) == 1, "success attribute is not 1"
    print(f"{int(relaxed.sum())} relaxed_obstacle rows of {status.size}, obstacle slack max "
          f"{slack[:, obstacle].max():.4f} m")
PY
echo "ok"
