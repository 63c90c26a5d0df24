#!/usr/bin/env bash
# plan.sh WPG: `wpg run` stores what each NMPC iteration predicted (mpc/plan/, datasets/
# SCHEMA.md): one row per iteration, the first previewed CoM is the CoM executed at the next
# iteration (1e-12), every landed step is the previewed step 0 of the iteration before its
# landing. `wpg replay` keeps the plan as it was, bit for bit. A study's `plan: false` leaves it out of every run; `plan: maybe` is one line naming
# the key, exit 2, no file.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
"$wpg" run curve --no-plot -o "$WORKDIR/curve.h5" >/dev/null
"$PYTHON" - "$WORKDIR/curve.h5" <<'PY' || fail "bad mpc/plan"
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    run = f["runs/curve"]
    plan = run["mpc/plan"]
    k, n, s = len(run["mpc/time"]), plan.attrs["samples"], plan.attrs["steps"]
    assert plan["sample_count"].shape == (k,), plan["sample_count"].shape
    com = plan["com"][()].reshape(k, n, 2)
    per = round(plan.attrs["sampling_period"] / (run["time"][1] - run["time"][0]))
    executed = run["com"][per::per, :2][:k]
    error = np.abs(com[:len(executed), 0] - executed).max()
    assert error <= 1e-12, error
    steps = plan["steps"][()].reshape(k, s, 4)
    landed = run["footsteps"][()]
    landed = landed[landed[:, 0] > 0]
    for row in landed:
        i = int(round(row[0] / plan.attrs["sampling_period"])) - 1
        assert np.array_equal(steps[i, 0], row), (steps[i, 0], row)
    assert plan["active_rows"].shape == (k, run["mpc/slack"].shape[1])
PY
"$wpg" replay "$WORKDIR/curve.h5" --no-filter --no-plot -o "$WORKDIR/replayed.h5" >/dev/null
"$PYTHON" - "$WORKDIR/curve.h5" "$WORKDIR/replayed.h5" <<'PY' || fail "wpg replay changed mpc/plan"
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as a, h5py.File(sys.argv[2], "r") as b:
    before, after = a["runs/curve/mpc/plan"], b["runs/curve/mpc/plan"]
    assert sorted(before) == sorted(after), (sorted(before), sorted(after))
    for name in before:
        assert np.array_equal(before[name][()], after[name][()]), name
    for name in ("samples", "steps", "sampling_period"):
        assert before.attrs[name] == after.attrs[name], name
    assert "q" in b["runs/curve"]
PY
cat >"$WORKDIR/study.yaml" <<'YAML'
name: no_plans
plan: false
base: walk_forward
sweep: {grid: {duration: [2.0, 3.0]}}
YAML
"$wpg" batch "$WORKDIR/study.yaml" -o "$WORKDIR/study.h5" --no-plot >/dev/null
"$PYTHON" - "$WORKDIR/study.h5" <<'PY' || fail "a study with plan: false stored plans"
import sys
import h5py
with h5py.File(sys.argv[1], "r") as f:
    for name, run in f["runs"].items():
        assert "plan" not in run["mpc"], name
        assert len(run["mpc/time"]) > 0, name
PY
sed 's/^plan: false/plan: maybe/' "$WORKDIR/study.yaml" >"$WORKDIR/bad.yaml"
status=0
"$wpg" batch "$WORKDIR/bad.yaml" -o "$WORKDIR/bad.h5" --no-plot >/dev/null 2>"$WORKDIR/stderr" ||
  status=$?
[[ $status == 2 ]] || fail "plan: maybe: exit $status, expected 2"
[[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "expected one line on stderr"
grep -q "bad.yaml: key 'plan'" "$WORKDIR/stderr" || fail "the line does not name the key: $(cat "$WORKDIR/stderr")"
[[ ! -e "$WORKDIR/bad.h5" ]] || fail "a file was written"
echo "ok"
