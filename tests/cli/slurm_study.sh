#!/usr/bin/env bash
# slurm_study.sh WPG STUDY: scripts/slurm-study.sh, with a stand-in `sbatch` that runs each job
# at once (every array task in turn, SLURM_ARRAY_TASK_ID set; a dependent job after them):
# one shard per task, and the index it leaves holds the runs of `wpg batch -j 1`, bit for bit
# but the wall times, with its summary files.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$(readlink -f "$1")"; study="$(readlink -f "$2")"
make_workdir
cd "$WORKDIR"
mkdir bin
cat >bin/sbatch <<'SH'
#!/usr/bin/env bash
# sbatch as the test needs it: --array=0-M runs the --wrap command for each task, in order.
array="" wrap="" id=$((RANDOM + 1000))
while (($#)); do
  case "$1" in
    --array=*) array="${1#--array=}" ;;
    --wrap) wrap="$2"; shift ;;
  esac
  shift
done
if [[ -n "$array" ]]; then
  for task in $(seq "${array%-*}" "${array#*-}"); do
    SLURM_ARRAY_TASK_ID="$task" bash -c "$wrap" >>sbatch.log 2>&1 || exit 1
  done
else
  bash -c "$wrap" >>sbatch.log 2>&1 || exit 1
fi
echo "$id"
SH
chmod +x bin/sbatch
PATH="$PWD/bin:$PATH" WPG="$wpg" "$HERE/../../scripts/slurm-study.sh" "$study" out/study.h5 4 \
  --time=00:10:00 >stdout 2>stderr || fail "slurm-study.sh: exit $? ($(cat stderr) $(cat sbatch.log))"
grep -q "4 slices into" stdout || fail "slurm-study.sh said: $(cat stdout)"
[[ -s out/study.summary.csv ]] || fail "no summary beside the index ($(cat sbatch.log))"
"$wpg" batch "$study" -o one.h5 -j 1 --no-plot >/dev/null 2>&1 || fail "batch -j 1: exit $?"
oracle compare_batch_files.py one.h5 out/study.h5 || fail "the array's index differs from -j 1"
ls out/study.shards/slice-{0,1,2,3}.h5 >/dev/null || fail "not one shard per task: $(ls out/study.shards)"
echo ok
