#!/usr/bin/env bash
# lazy_slices.sh WPG STUDY: a study's run i is made from i alone, the same bits whatever the
# slicing:
#  - a study of 10^7 runs: its slice 7/10000000 and 7/9999993 (each holds run 7 only) hold the
#    same run, bit for bit but the wall times; each is one process of at most 100 MB that takes
#    at most 2 s of CPU (measured: 0.6 s, 39 MB; main expanded 10^4 runs in 6.4 s);
#  - STUDY (grid, zip and random keys) as 5 slices merged, and as 2 slices of which one is
#    resumed after its file lost its last runs, give the runs of `wpg batch -j 1`.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; study="$2"
make_workdir
cd "$WORKDIR"

cat >big.yaml <<'YAML'
name: big
base: walk_forward
sweep:
  random:
    samples: 10000000
    seed: 1
    keys: {walking.com_height: {uniform: [0.78, 0.84]}, walking.weight_cop: {uniform: [300.0, 10000.0]}}
YAML
for slice in 7/10000000 7/9999993; do
  file="big-${slice//\//-}.h5"
  /usr/bin/time -f "%M %U %S" -o usage "$wpg" batch big.yaml --shard "$slice" -o "$file" \
    --no-plot >stdout 2>stderr || fail "--shard $slice: exit $? ($(cat stderr))"
  read -r kilobytes user system <usage
  echo "--shard $slice: $kilobytes kB, $user s + $system s of CPU"
  # Not under the sanitizers (WPG_SANITIZED): their memory and time are not the build's.
  if [[ "${WPG_SANITIZED:-0}" != 1 ]]; then
    (( kilobytes <= 100 * 1024 )) || fail "--shard $slice: $kilobytes kB, over 100 MB"
    (( $(echo "$user + $system <= 2" | bc -l) )) || fail "--shard $slice: $user s + $system s of CPU"
  fi
done
"$PYTHON" - big-7-10000000.h5 big-7-9999993.h5 <<'PY' || fail "run 7 differs between slicings"
import sys
import h5py, numpy as np
WALL_TIME = {"solve_time", "timing", "nmpc_time_mean", "nmpc_time_std", "nmpc_time_min",
             "nmpc_time_max", "nmpc_time_p99"}
a, b = (h5py.File(path, "r") for path in sys.argv[1:])
assert list(a["runs"]) == list(b["runs"]) == ["big_0000007"], (list(a["runs"]), list(b["runs"]))
assert a["batch/summary/index"][:].tolist() == [7] == b["batch/summary/index"][:].tolist()
def same(x, y, where):
    assert dict(x.attrs).keys() == dict(y.attrs).keys(), where
    for key in x.attrs:
        if key not in WALL_TIME:
            assert np.array_equal(np.asarray(x.attrs[key]), np.asarray(y.attrs[key])), (where, key)
    if isinstance(x, h5py.Dataset):
        assert x.dtype == y.dtype and x.shape == y.shape, where
        assert x[()].tobytes() == y[()].tobytes() if x.dtype.kind != "O" else \
            list(x[()].flat) == list(y[()].flat), where
        return
    assert sorted(x) == sorted(y), where
    for name in x:
        if name not in WALL_TIME:
            same(x[name], y[name], where + "/" + name)
same(a["runs/big_0000007"], b["runs/big_0000007"], "runs/big_0000007")
for column in a["batch/summary"]:
    if column not in WALL_TIME:
        same(a["batch/summary"][column], b["batch/summary"][column], column)
PY

"$wpg" batch "$study" -o one.h5 -j 1 --no-plot >/dev/null 2>&1 || fail "batch -j 1: exit $?"
for k in 0 1 2 3 4; do
  "$wpg" batch "$study" -o "five/part-$k.h5" --shard "$k/5" -j 2 --no-plot >/dev/null 2>stderr ||
    fail "--shard $k/5: exit $? ($(cat stderr))"
done
"$wpg" merge five.h5 five/part-*.h5 --no-plot >/dev/null 2>stderr || fail "merge of 5: $(cat stderr)"
oracle compare_batch_files.py one.h5 five.h5 || fail "5 slices merged differ from -j 1"

# Slice 1/2 loses its last 3 runs (their groups removed, their rows not done): --resume runs
# them again, and the merged slices are -j 1's runs.
for k in 0 1; do
  "$wpg" batch "$study" -o "two/part-$k.h5" --shard "$k/2" --no-plot >/dev/null 2>stderr ||
    fail "--shard $k/2: exit $? ($(cat stderr))"
done
"$PYTHON" - two/part-1.h5 <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    table = f["batch/summary"]
    done = table["done"][:]
    for row in range(len(done) - 3, len(done)):
        del f["runs"][table["name"][row].decode()]
        done[row] = 0
    table["done"][:] = done
PY
"$wpg" batch "$study" -o two/part-1.h5 --shard 1/2 --resume --no-plot >stdout 2>stderr ||
  fail "--resume of 1/2: exit $? ($(cat stderr))"
"$wpg" merge two.h5 two/part-*.h5 --no-plot >/dev/null 2>stderr || fail "merge of 2: $(cat stderr)"
oracle compare_batch_files.py one.h5 two.h5 || fail "a resumed slice merged differs from -j 1"
echo ok
