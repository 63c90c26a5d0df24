#!/usr/bin/env bash
# compare_resume_shard.sh WPG STUDY: `wpg compare --resume` and `--shard K/N`:
#  - a comparison killed (SIGKILL) half-way and finished with --resume gives the study.h5 of an
#    uninterrupted run (runs, /batch/summary and /compare/summary; wall times aside,
#    compare_batch_files.py) and the same summary.csv but its wall-time columns; --resume of a
#    complete study runs nothing and changes nothing; --resume of a study file written for
#    another study is refused (exit 2, one line, the file untouched);
#  - `--shard K/3` for K = 0, 1, 2 into DIR/study.shards/ and `wpg merge DIR/study.h5
#    DIR/study.shards` give the same study as one unsharded run, with summary.csv/.md beside it;
#  - a goal walk's velocity metrics: `wpg analyze` of the study file gives the numbers of its
#    /batch/summary (computed at run time) and those check_metrics.py recomputes from the raw
#    fields (against mpc/command, datasets/METRICS.md).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; study="$2"
make_workdir
cd "$WORKDIR"

"$wpg" compare "$study" -o one -j 2 --no-plot >/dev/null 2>stderr || fail "compare: exit $? ($(cat stderr))"
total="$("$PYTHON" -c "import h5py,sys; print(h5py.File(sys.argv[1])['batch/summary/done'].size)" one/study.h5)"

# Velocity metrics of the goal walks: analyze = the run-time summary = the recomputation.
"$wpg" analyze one/study.h5 --format json >metrics.json || fail "wpg analyze: exit $?"
oracle check_metrics.py one/study.h5 metrics.json || fail "metrics disagree with check_metrics.py"
"$PYTHON" - one/study.h5 metrics.json <<'PY' || fail "analyze differs from the run-time summary"
import json, math, sys, h5py
metrics = json.load(open(sys.argv[2]))
with h5py.File(sys.argv[1], "r") as f:
    s = f["batch/summary"]
    for i, name in enumerate(s["name"].asstr()[:]):
        for key in ("velocity_error_rms", "velocity_error_max"):
            stored, analyzed = float(s[key][i]), metrics[name][key]
            assert math.isfinite(stored), (name, key, stored)  # measured, not NaN
            assert stored == analyzed, (name, key, stored, analyzed)
        assert "command" in f["runs"][name]["mpc"], name
PY

keep_columns() {  # summary.csv without its wall-time columns (planning and NMPC times)
  "$PYTHON" -c "
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
keep = [i for i, name in enumerate(rows[0]) if 'time' not in name or 'time_to_goal' in name]
for row in rows: print(','.join(row[i] for i in keep))" "$1"
}

# Kill half-way: the delay is adjusted until the kill lands with some but not all runs done.
delay=0.4
partial=""
for attempt in 1 2 3 4 5 6 7 8; do
  rm -rf killed
  "$wpg" compare "$study" -o killed -j 2 --no-plot >/dev/null 2>&1 &
  pid=$!
  sleep "$delay"
  kill -KILL "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  [[ -f killed/study.h5 ]] || { delay="$(echo "$delay * 2" | bc -l)"; continue; }
  done_runs="$("$PYTHON" - killed/study.h5 <<'PY'
import sys, h5py
try:
    with h5py.File(sys.argv[1], "r") as f:
        f.visit(lambda name: None)
        print(int(f["batch/summary/done"][:].sum()))
except Exception:
    print("damaged")  # killed inside HDF5's write of a run: --resume starts again
PY
)"
  echo "attempt $attempt: killed after ${delay}s: $done_runs of $total runs done"
  if [[ "$done_runs" == damaged ]]; then partial=damaged; break; fi
  if (( done_runs == 0 )); then delay="$(echo "$delay * 1.6" | bc -l)"
  elif (( done_runs == total )); then delay="$(echo "$delay * 0.5" | bc -l)"
  else partial=yes; break; fi
done
[[ -n "$partial" ]] || fail "could not kill the comparison half-way"
[[ ! -e killed/summary.csv ]] || fail "a killed comparison wrote its table"
"$wpg" compare "$study" -o killed -j 2 --resume --no-plot >/dev/null 2>resume.err ||
  fail "--resume: exit $? ($(cat resume.err))"
if [[ "$partial" == yes ]]; then
  grep -q "resuming, $done_runs of $total runs already" resume.err || fail "resume: $(cat resume.err)"
fi
oracle compare_batch_files.py one/study.h5 killed/study.h5 || fail "killed + resumed differs"
diff <(keep_columns one/summary.csv) <(keep_columns killed/summary.csv) || fail "summary.csv differs"

# --resume of a complete study: nothing run, the same contents.
"$wpg" compare "$study" -o killed -j 2 --resume --no-plot >/dev/null 2>resume.err ||
  fail "--resume of a complete study: exit $?"
grep -q "0/0 runs" resume.err || fail "--resume of a complete study ran something: $(cat resume.err)"
oracle compare_batch_files.py one/study.h5 killed/study.h5 || fail "complete study changed by --resume"

# --resume of a study file of another study (other seeds): refused, the file untouched.
sed -e 's/^seeds: .*/seeds: [7, 8]/' "$study" >other_seeds.yaml
before="$(md5sum <killed/study.h5)"
status=0
"$wpg" compare other_seeds.yaml -o killed --resume --no-plot >/dev/null 2>stderr || status=$?
[[ $status == 2 && "$(wc -l <stderr)" == 1 ]] || fail "resume of another study: exit $status, $(cat stderr)"
grep -q "killed/study.h5" stderr || fail "resume of another study: $(cat stderr)"
[[ "$(md5sum <killed/study.h5)" == "$before" ]] || fail "resume of another study changed the file"

# Slices into DIR/study.shards/, merged: the study of one unsharded run.
for k in 0 1 2; do
  "$wpg" compare "$study" -o sharded --shard "$k/3" -j 2 >stdout 2>stderr ||
    fail "--shard $k/3: exit $? ($(cat stderr))"
  grep -q "shard $k/3: " stdout || fail "--shard $k/3: $(cat stdout)"
  [[ -f "sharded/study.shards/slice-$k-of-3.h5" ]] || fail "--shard $k/3: no shard file"
done
[[ ! -e sharded/study.h5 && ! -e sharded/summary.csv ]] || fail "a slice wrote the study file"
"$PYTHON" - sharded/study.shards/slice-*.h5 <<'PY' || fail "the slices do not hold runs i mod 3 = k"
import sys, h5py
for k, path in enumerate(sys.argv[1:]):
    with h5py.File(path, "r") as f:
        assert f.attrs["shard"] == f"{k}/3", f.attrs["shard"]
        assert "compare" not in f
        done = f["batch/summary/done"][:]
        assert [i for i, d in enumerate(done) if d] == list(range(k, len(done), 3)), done
PY
"$wpg" merge sharded/study.h5 sharded/study.shards --no-plot >stdout 2>stderr ||
  fail "merge: exit $? ($(cat stderr))"
grep -q "wrote sharded/study.h5 ($total runs)" stdout || fail "merge: $(cat stdout)"
oracle compare_batch_files.py one/study.h5 sharded/study.h5 || fail "merged slices differ from one run"
diff <(keep_columns one/summary.csv) <(keep_columns sharded/summary.csv) || fail "merged summary.csv differs"
[[ -s sharded/summary.md ]] || fail "no summary.md beside the merged study"
oracle check_compare_table.py sharded/study.h5 sharded/summary.csv || fail "the merged table disagrees with the runs"

# --ompl-log with --shard is a usage error (the logs describe the whole study).
status=0
"$wpg" compare "$study" -o sharded --shard 0/3 --ompl-log logs >/dev/null 2>stderr || status=$?
[[ $status == 2 && ! -e logs ]] || fail "--shard with --ompl-log: exit $status, $(cat stderr)"
echo "ok"
