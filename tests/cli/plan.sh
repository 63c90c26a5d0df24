#!/usr/bin/env bash
# plan.sh WPG: `wpg run` stores what each NMPC iteration predicted (mpc/plan/, datasets/
# SCHEMA.md): one row per iteration, the first previewed CoM is the CoM executed at the next
# iteration (1e-12), every landed step is the previewed step 0 of the iteration before its
# landing. `wpg replay` keeps the plan as it was, bit for bit. `wpg plot --plan` draws it
# against the walk (RUN.plan.png); a run without a plan, --at outside the walk and --at without
# --plan are one line, exit 2, no figure. A study's `plan: false` leaves it out of every run; `plan: maybe` is one line naming
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
# Predicted against executed: the PNG beside the run, then the refusals.
"$wpg" plot "$WORKDIR/curve.h5" --plan --at 3 7.5 >"$WORKDIR/stdout" || fail "plot --plan: exit $?"
grep -qx "figure: $WORKDIR/curve.plan.png" "$WORKDIR/stdout" || fail "plot --plan: $(cat "$WORKDIR/stdout")"
[[ "$(head -c 8 "$WORKDIR/curve.plan.png" | od -An -tx1 | tr -d ' ')" == 89504e470d0a1a0a ]] ||
  fail "curve.plan.png is not a PNG"
"$wpg" run walk_forward --no-plot --set duration=3 --set generator.record_plan=false \
  -o "$WORKDIR/no_plan.h5" >/dev/null
refused() {  # refused EXPECTED PNG ARGS...: exit 2, one line holding EXPECTED, no PNG
  local expected="$1" png="$2" status=0
  shift 2
  "$wpg" plot "$@" >/dev/null 2>"$WORKDIR/stderr" || status=$?
  [[ $status == 2 ]] || fail "plot $*: exit $status, expected 2"
  [[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "plot $*: expected one line: $(cat "$WORKDIR/stderr")"
  grep -qF -- "$expected" "$WORKDIR/stderr" || fail "plot $*: $(cat "$WORKDIR/stderr")"
  [[ ! -e "$png" ]] || fail "plot $*: wrote $png"
}
refused "/runs/walk_forward/mpc/plan: expected the NMPC's plans, missing" \
  "$WORKDIR/no_plan.plan.png" "$WORKDIR/no_plan.h5" --plan
refused "--at 99: expected a time of the walk" "$WORKDIR/late.png" "$WORKDIR/curve.h5" --plan --at 99 -o "$WORKDIR/late.png"
refused "--at: expected with --plan only" "$WORKDIR/curve.png" "$WORKDIR/curve.h5" --at 3
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
