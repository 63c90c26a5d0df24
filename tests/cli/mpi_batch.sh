#!/usr/bin/env bash
# mpi_batch.sh WPG MPIRUN STUDY: `wpg batch` under MPI (added when WPG_WITH_MPI):
#  - `mpirun --oversubscribe -np 3 wpg batch STUDY -o OUT.h5` gives the same runs as
#    `wpg batch -j 1`, bit for bit but the wall times (compare_batch_files.py), in OUT.h5 (the
#    index) and OUT.shards/rank-{0,1,2}.h5, every rank having run some of them;
#  - the ranks killed (SIGKILL) mid-study, as a lost node: mpirun aborts the job; `--resume`
#    (on 2 ranks) runs the runs done in no shard (a shard HDF5 cannot open is moved to .damaged and redone), and the
#    index holds the same runs as the uninterrupted batch; a complete study resumed runs nothing;
#    a shard truncated by hand is moved aside and its runs redone;
#  - bad input under mpirun: exit 2, one `wpg: error:` line (rank 0's), nothing written: a bad
#    study, and --resume with a shard of another study in OUT.shards/ (left as it is).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; mpirun="$2"; study="$3"
make_workdir
cd "$WORKDIR"
mpi=("$mpirun" --oversubscribe)

# The processes whose parent is $1 (mpirun's ranks), from /proc (no procps needed).
children() {
  local stat pid comm state ppid
  for stat in /proc/[0-9]*/stat; do
    read -r pid comm state ppid _ <"$stat" 2>/dev/null || continue
    [[ "$ppid" == "$1" ]] && echo "$pid"
  done
  return 0
}

"$wpg" batch "$study" -o one.h5 -j 1 --no-plot >/dev/null 2>&1 || fail "batch -j 1: exit $?"
total="$("$PYTHON" -c "import h5py,sys; print(h5py.File(sys.argv[1])['batch/summary/done'].size)" one.h5)"

"${mpi[@]}" -np 3 "$wpg" batch "$study" -o mpi/out.h5 --no-plot >stdout 2>stderr ||
  fail "mpirun -np 3: exit $? ($(cat stderr))"
grep -q "3 ranks x 1 workers; rank 0 answered" stderr || fail "no rank 0 statistics: $(cat stderr)"
[[ -s mpi/out.summary.csv ]] || fail "no summary.csv beside the index"
oracle compare_batch_files.py one.h5 mpi/out.h5 || fail "mpirun -np 3 differs from -j 1"
"$PYTHON" - mpi/out.h5 <<'PY' || fail "bad shard layout"
import sys, h5py
ranks = set()
with h5py.File(sys.argv[1], "r") as f:
    for name in f["runs"]:
        link = f["runs"].get(name, getlink=True)
        assert isinstance(link, h5py.ExternalLink), (name, link)
        ranks.add(link.filename)
assert ranks == {f"out.shards/rank-{r}.h5" for r in range(3)}, ranks  # every rank ran runs
for r in range(3):
    with h5py.File(f"mpi/out.shards/rank-{r}.h5", "r") as shard:
        assert shard.attrs["shard"] == f"rank {r} of 3"
PY

# The ranks killed mid-study. The delay after rank 0 has opened its shard is adjusted until
# the kill lands with some, not all, runs done.
delay=0.1
partial=""
for attempt in 1 2 3 4 5 6 7 8; do
  rm -rf killed
  "${mpi[@]}" -np 3 "$wpg" batch "$study" -o killed/out.h5 --no-plot >killed.log 2>&1 &
  pid=$!
  # From rank 0's first shard on (not the last rank's: rank 0 runs before the other ranks are
  # up, and on an idle machine it had done 143 of the 144 runs by then).
  for _ in $(seq 200); do [[ -f killed/out.shards/rank-0.h5 ]] && break; sleep 0.01; done
  sleep "$delay"
  # Every rank at once (a node lost): killing one rank left the others time to finish the
  # study (~0.5 s on an idle machine) before mpirun aborted them.
  for victim in $(children "$pid"); do kill -KILL "$victim" 2>/dev/null || true; done
  status=0
  wait "$pid" 2>/dev/null || status=$?
  if [[ $status == 0 ]]; then  # finished before the kill
    delay="$(echo "$delay * 0.5" | bc -l)"; continue
  fi
  [[ ! -e killed/out.h5 ]] || fail "an aborted job left an index"
  done_runs="$("$PYTHON" - killed/out.shards/*.h5 <<'PY'
import sys, h5py
done = set()
for path in sys.argv[1:]:
    try:
        with h5py.File(path, "r") as f:
            f.visit(lambda name: None)
            runs = set(f["runs"])
            for name, d in zip(f["batch/summary/name"].asstr()[:], f["batch/summary/done"][:]):
                if d and name in runs:
                    done.add(name)
    except Exception:
        pass  # killed inside HDF5's write: --resume moves it aside
print(len(done))
PY
)"
  echo "attempt $attempt: ranks killed after ${delay}s, $done_runs of $total runs done"
  # At least a few runs left, so that the resume has real work (the killed rank's run among it).
  if (( done_runs == 0 )); then delay="$(echo "$delay * 1.6" | bc -l)"
  elif (( done_runs > total - 4 )); then delay="$(echo "$delay * 0.5" | bc -l)"
  else partial=yes; break; fi
done
[[ -n "$partial" ]] || fail "could not kill the ranks mid-study"
"${mpi[@]}" -np 2 "$wpg" batch "$study" -o killed/out.h5 --resume --no-plot >/dev/null 2>resume.err ||
  fail "--resume: exit $? ($(cat resume.err))"
grep -Eq "resuming, [0-9]+ of $total runs already" resume.err || fail "resume: $(cat resume.err)"
if ! grep -q "moved to" resume.err; then
  grep -q "resuming, $done_runs of $total runs already" resume.err || fail "resume: $(cat resume.err)"
fi
oracle compare_batch_files.py one.h5 killed/out.h5 || fail "killed + resumed differs"

"${mpi[@]}" -np 2 "$wpg" batch "$study" -o killed/out.h5 --resume --no-plot >/dev/null 2>resume.err ||
  fail "--resume of a complete study: exit $?"
grep -q "resuming, $total of $total" resume.err || fail "--resume of a complete study: $(cat resume.err)"
oracle compare_batch_files.py one.h5 killed/out.h5 || fail "complete study changed by --resume"

# A shard HDF5 cannot open (what a kill inside a write may leave: truncated here) is moved
# aside and its runs are run again.
head -c 4096 killed/out.shards/rank-1.h5 >truncated.h5
mv truncated.h5 killed/out.shards/rank-1.h5
"${mpi[@]}" -np 3 "$wpg" batch "$study" -o killed/out.h5 --resume --no-plot >/dev/null 2>resume.err ||
  fail "--resume with a damaged shard: exit $? ($(cat resume.err))"
grep -q "rank-1.h5 cannot be read by HDF5.*moved to killed/out.shards/rank-1.h5.damaged" resume.err ||
  fail "the damaged shard was not moved aside: $(cat resume.err)"
[[ -f killed/out.shards/rank-1.h5.damaged ]] || fail "no rank-1.h5.damaged"
oracle compare_batch_files.py one.h5 killed/out.h5 || fail "resumed without the damaged shard differs"

refused() {  # refused EXPECTED ARGS...: exit 2, one error line naming EXPECTED
  local expected="$1"; shift
  status=0
  "${mpi[@]}" -np 2 "$wpg" batch "$@" --no-plot >stdout 2>stderr || status=$?
  [[ $status == 2 ]] || fail "batch $*: exit $status, expected 2 ($(cat stderr))"
  [[ "$(grep -c '^wpg: error:' stderr)" == 1 ]] || fail "batch $*: not one error line: $(cat stderr)"
  grep '^wpg: error:' stderr | grep -qF -- "$expected" || fail "batch $*: does not name '$expected'"
}
refused "empty sweep" "$HERE/bad_studies/empty_sweep.yaml" -o bad/out.h5
[[ ! -e bad ]] || fail "a bad study under mpirun wrote something"
"$wpg" batch "$HERE/studies/other_study.yaml" -o killed/out.shards/stray.h5 --shard 0/1 >/dev/null 2>&1 ||
  fail "other study: exit $?"
sums="$(md5sum killed/out.shards/* killed/out.h5)"
refused "other_study" "$study" -o killed/out.h5 --resume
[[ "$(md5sum killed/out.shards/* killed/out.h5)" == "$sums" ]] || fail "a refused --resume changed files"
echo "ok"
