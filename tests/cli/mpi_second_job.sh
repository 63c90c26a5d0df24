#!/usr/bin/env bash
# mpi_second_job.sh WPG MPIRUN STUDY CASE: a second MPI job writing the same index and shards
# (OUT.h5, OUT.shards/rank-K.h5) while the first runs is refused as a second `wpg batch` is:
# exit 2, one line "in use by another wpg", nothing of the first job's touched (its index then
# holds every run, through its own shards). CASE: second_job, or second_resume (with --resume,
# which must not take the first job's shards for damaged ones either).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; mpirun="$2"; study="$3"; case_name="$4"
make_workdir
cd "$WORKDIR"
mpi=("$mpirun" --oversubscribe -np 2)
# Walks of 60 s (twice the test study's): the first job runs long enough to be caught.
sed -e 's/duration: \[30.0, 30.5, 31.0, 31.5\]/duration: [60.0, 60.5, 61.0, 61.5]/' "$study" >long.yaml

"${mpi[@]}" "$wpg" batch long.yaml -o out.h5 --no-plot >first.out 2>first.err &
first=$!
for _ in $(seq 1000); do  # until both ranks' shards have their layout
  [[ "$(stat -c %s out.shards/rank-0.h5 2>/dev/null || echo 0)" -gt 4096 &&
     "$(stat -c %s out.shards/rank-1.h5 2>/dev/null || echo 0)" -gt 4096 ]] && break
  sleep 0.02
done
kill -0 "$first" 2>/dev/null || fail "the first job ended before the second started"
before="$(stat -c %i out.shards/rank-0.h5) $(stat -c %i out.shards/rank-1.h5)"
extra=()
[[ $case_name == second_resume ]] && extra=(--resume)
status=0
timeout 120 "${mpi[@]}" "$wpg" batch long.yaml -o out.h5 --no-plot "${extra[@]}" \
  >second.out 2>second.err || status=$?
[[ $status == 2 ]] || fail "second job: exit $status, expected 2 ($(cat second.err))"
[[ "$(grep -c 'wpg: error' second.err)" == 1 ]] || fail "second job: not one error line: $(cat second.err)"
grep -q "in use by another wpg" second.err || fail "second job: $(cat second.err)"
[[ "$(stat -c %i out.shards/rank-0.h5) $(stat -c %i out.shards/rank-1.h5)" == "$before" ]] ||
  fail "the second job replaced the first job's shards"
[[ ! -e out.shards/rank-0.h5.damaged && ! -e out.shards/rank-1.h5.damaged ]] ||
  fail "the second job moved a shard in use aside"
first_status=0
wait "$first" || first_status=$?
[[ $first_status == 0 ]] || fail "the first job: exit $first_status ($(cat first.err))"
"$PYTHON" - out.h5 <<'PY' || fail "the first job's index is not complete"
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    done = f["batch/summary/done"][:]
    assert done.all() and len(f["runs"]) == len(done), (int(done.sum()), len(done))
    for name in f["runs"]:
        assert f["runs"][name]["time"].shape[0] > 0
PY
