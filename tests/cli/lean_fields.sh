#!/usr/bin/env bash
# lean_fields.sh WPG STUDY [MPIRUN]: lean runs (a study's `fields:`, `wpg batch --fields`;
# datasets/SCHEMA.md, "Lean runs"):
#  - STUDY's 48 walks of 10 s with --fields summary,footsteps store at most 20 KB a run (the
#    batch file's size over its runs) and only those fields; with summary,com,footsteps,mpc
#    their datasets and attributes are those of the same runs stored whole, bit for bit but the
#    wall times, and the study's `fields:` gives the same file as --fields;
#  - a lean run read as a walk (wpg view) is one line naming what it lacks (wpg.load_run:
#    tests/python/test_lean_runs.py);
#  - under mpirun (MPIRUN given), the lean study's index is the lean -j 2 batch, bit for bit
#    but the wall times;
#  - bad input is one line naming the file or option, exit 2, nothing written: a field that
#    does not exist (with did-you-mean), fields without summary, a lean slice merged with a
#    full one, --resume with other fields (the file left as it was).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; study="$2"; mpirun="${3:-}"
make_workdir
cd "$WORKDIR"

# expect_refusal TEXT OUTPUT COMMAND...: exit 2, one line on stderr containing TEXT, no OUTPUT.
expect_refusal() {
  local text="$1" output="$2"; shift 2
  local status=0
  "$@" >stdout 2>stderr || status=$?
  [[ $status == 2 ]] || fail "$*: exit $status, expected 2 ($(cat stderr))"
  [[ $(wc -l <stderr) == 1 ]] || fail "$*: expected one line, got: $(cat stderr)"
  grep -qF -- "$text" stderr || fail "$*: expected '$text', got: $(cat stderr)"
  [[ ! -e "$output" ]] || fail "$*: wrote $output"
}

"$wpg" batch "$study" -o full.h5 -j 2 --no-plot >/dev/null
"$wpg" batch "$study" -o lean.h5 -j 2 --no-plot --fields summary,footsteps >/dev/null
"$wpg" batch "$study" -o some.h5 -j 2 --no-plot --fields summary,com,footsteps,mpc >/dev/null
sed 's/^name: batch_small$/name: batch_small\nfields: [summary, footsteps]/' "$study" >lean.yaml
"$wpg" batch lean.yaml -o lean-key.h5 -j 1 --no-plot >/dev/null

"$PYTHON" - full.h5 lean.h5 some.h5 lean-key.h5 <<'PY' || fail "lean runs"
import os, sys
import h5py, numpy as np
full_path, lean_path, some_path, key_path = sys.argv[1:]
WALL_TIME = {"solve_time", "timing", "nmpc_time_mean", "nmpc_time_std", "nmpc_time_min",
             "nmpc_time_max", "nmpc_time_p99", "created_at", "created_on"}
full, lean, some, key = (h5py.File(p, "r") for p in sys.argv[1:])
runs = full.attrs["run_count"]
per_run = os.path.getsize(lean_path) / runs
print("lean (summary, footsteps): %.1f KB per run; whole: %.1f KB per run"
      % (per_run / 1e3, os.path.getsize(full_path) / runs / 1e3))
assert per_run <= 20e3, per_run
assert list(lean.attrs["fields"]) == ["summary", "footsteps"], lean.attrs["fields"]
assert "fields" not in full.attrs
def subset(x, y, where):
    """Everything of x (lean) is in y (whole), the same bits but the wall times."""
    for name in x.attrs:
        if name in WALL_TIME or (name == "fields" and where.count("/") <= 2):
            continue
        assert np.array_equal(np.asarray(x.attrs[name]), np.asarray(y.attrs[name])), (where, name)
    if isinstance(x, h5py.Dataset):
        assert x.dtype == y.dtype and x.shape == y.shape and x.chunks == y.chunks, where
        assert (x[()].tobytes() == y[()].tobytes() if x.dtype.kind != "O"
                else list(x[()].flat) == list(y[()].flat)), where
        return
    for name in x:
        if name not in WALL_TIME:
            assert name in y, (where, name)
            subset(x[name], y[name], where + "/" + name)
for lean_file, names in ((lean, {"footsteps", "footstep_side", "footstep_lift_off", "checks"}),
                         (some, {"time", "com", "com_vel", "com_acc", "footsteps",
                                 "footstep_side", "footstep_lift_off", "checks", "mpc"})):
    for run in full["runs"]:
        assert set(lean_file["runs"][run]) == names, (run, sorted(lean_file["runs"][run]))
        if lean_file is some:
            assert "plan" not in lean_file["runs"][run]["mpc"]
        subset(lean_file["runs"][run], full["runs"][run], "/runs/" + run)
    subset(lean_file["batch"], full["batch"], "/batch")
# The study's fields: key and --fields give the same file (but the study text).
subset(key["runs"], lean["runs"], "/runs")
subset(lean["runs"], key["runs"], "/runs")
PY

if [[ -n "$mpirun" ]]; then
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "$mpirun" --oversubscribe -np 2 \
    "$wpg" batch "$study" -o mpi/lean.h5 --no-plot --fields summary,footsteps >stdout 2>stderr ||
    fail "mpirun -np 2 --fields: exit $? ($(cat stderr))"
  oracle compare_batch_files.py lean.h5 mpi/lean.h5 || fail "lean under MPI differs"
fi

# Read as a walk: one line saying what the lean run lacks (the sanitizer tree, WPG_SANITIZED,
# has no viewer bundle: `wpg view` says so first there).
lacks="is a lean run (fields summary, footsteps): it lacks com, cop, feet, mpc"
[[ "${WPG_SANITIZED:-0}" == 1 ]] ||
  expect_refusal "$lacks" page.html "$wpg" view lean.h5 --run batch_small_07 -o page.html
expect_refusal "$lacks" metrics.json "$wpg" analyze lean.h5 --format json

# Bad input.
sed 's/^name: batch_small$/name: batch_small\nfields: [summary, footstep]/' "$study" >typo.yaml
expect_refusal "typo.yaml: fields: 'footstep' is not a field; did you mean 'footsteps'?" out.h5 \
  "$wpg" batch typo.yaml -o out.h5 --no-plot
expect_refusal "--fields: expected 'summary' among the fields (got com, footsteps)" out.h5 \
  "$wpg" batch "$study" -o out.h5 --no-plot --fields com,footsteps
expect_refusal "--fields: 'coms' is not a field; did you mean 'com'?" out.h5 \
  "$wpg" batch "$study" -o out.h5 --no-plot --fields summary,coms
"$wpg" batch "$study" -o slice0.h5 --shard 0/2 --fields summary,footsteps >/dev/null
"$wpg" batch "$study" -o slice1.h5 --shard 1/2 >/dev/null
expect_refusal "slice1.h5: its runs store the fields all, those of slice0.h5 summary, footsteps" \
  index.h5 "$wpg" merge index.h5 slice0.h5 slice1.h5
before="$(sha256sum lean.h5)"
expect_refusal "lean.h5: cannot resume: its runs store the fields summary, footsteps, this batch asks for all" \
  nothing "$wpg" batch "$study" -o lean.h5 --no-plot --resume
[[ "$(sha256sum lean.h5)" == "$before" ]] || fail "--resume with other fields changed lean.h5"
# The same fields resume (nothing left to run) and the slices of one field set merge.
"$wpg" batch "$study" -o lean.h5 --no-plot --resume --fields summary,footsteps >/dev/null
rm slice1.h5
"$wpg" batch "$study" -o slice1.h5 --shard 1/2 --fields summary,footsteps >/dev/null
"$wpg" merge index.h5 slice0.h5 slice1.h5 >/dev/null
"$PYTHON" -c 'import h5py, sys; f = h5py.File(sys.argv[1], "r"); assert list(f.attrs["fields"]) == ["summary", "footsteps"]; assert sorted(f["runs/batch_small_07"]) == ["checks", "footstep_lift_off", "footstep_side", "footsteps"]' index.h5 ||
  fail "the index of lean slices"
echo "ok"
