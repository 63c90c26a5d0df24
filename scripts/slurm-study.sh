#!/usr/bin/env bash
# A study on a Slurm cluster without MPI (docs/studies.md, "Running on a cluster"): one job
# array of N tasks, task K running slice K/N of the study into its own shard file, then one job,
# started once every task has succeeded, joining the shards into the index OUT.h5 (external
# links: no run copied) and writing OUT.summary.csv/.md. Each task is an ordinary process: a
# slice of a study of 10^7 runs starts its first run in 0.6 s and 39 MB.
#
#   scripts/slurm-study.sh STUDY.yaml OUT.h5 TASKS [sbatch options...]
#   e.g. scripts/slurm-study.sh study.yaml /scratch/me/study.h5 1000 --time=02:00:00
#
# A task that failed (a node lost, its time limit) is run again with the same slice and
# --resume: `sbatch --array=K ... ` of the same script (printed below), then the merge again.
# WPG (default: build/cli/wpg beside this script) must be reachable from the compute nodes,
# and OUT.h5's folder shared by them.
set -euo pipefail
if (($# < 3)); then
  echo "usage: $0 STUDY.yaml OUT.h5 TASKS [sbatch options...]" >&2
  exit 2
fi
study="$(realpath -- "$1")"; output="$(realpath -m -- "$2")"; tasks="$3"; shift 3
wpg="$(realpath -- "${WPG:-$(dirname "${BASH_SOURCE[0]}")/../build/cli/wpg}")"
shards="${output%.h5}.shards"
mkdir -p "$shards"
# One slice per array task, one worker per task (Slurm gives each task its CPU); --resume
# finishes a slice a failed attempt left, and starts one that has no file.
array_job="$(sbatch --parsable --job-name=wpg-study --array="0-$((tasks - 1))" \
  --cpus-per-task=1 --output="$shards/slurm-%a.log" "$@" --wrap \
  "'$wpg' batch '$study' --no-plot --resume -j 1 \
     --shard \"\$SLURM_ARRAY_TASK_ID/$tasks\" -o \"$shards/slice-\$SLURM_ARRAY_TASK_ID.h5\"")"
# The index once every task succeeded (a missing or unfinished slice: exit 2, naming it).
merge_job="$(sbatch --parsable --job-name=wpg-merge --dependency="afterok:$array_job" \
  --output="${output%.h5}.merge.log" --wrap "'$wpg' merge '$output' '$shards' --no-plot")"
echo "array job $array_job ($tasks slices into $shards), merge job $merge_job -> $output"
echo "a failed task K: sbatch --array=K again (this script's first sbatch line), then the merge"
