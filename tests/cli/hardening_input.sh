#!/usr/bin/env bash
# hardening_input.sh WPG CASE: hostile files and values given to the study commands end in
# bounded time with one clear line (exit 2 bad input, exit 3 could not complete), never a hang
# or unbounded work (datasets/SCENARIOS.md "Limits", datasets/SCHEMA.md "Reading").
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$(readlink -f "$1")"
case_name="$2"
make_workdir
cd "$WORKDIR"
cp "$HERE/studies/tiny_batch.yaml" study.yaml
cp "$HERE/studies/tiny_compare.yaml" compare.yaml

# refused STATUS PATTERN ARGS...: exit STATUS within 20 s, one line on stderr matching PATTERN.
refused() {
  local expected="$1" pattern="$2" status=0
  shift 2
  timeout 20 "$wpg" "$@" >stdout 2>stderr || status=$?
  [[ $status == "$expected" ]] || fail "wpg $*: exit $status, expected $expected ($(cat stderr))"
  [[ "$(wc -l <stderr)" == 1 ]] || fail "wpg $*: not one line on stderr: $(cat stderr)"
  grep -q -- "$pattern" stderr || fail "wpg $*: expected '$pattern': $(cat stderr)"
}

case "$case_name" in
external_link_special)
  # An index whose links lead to a FIFO, a device, a missing file: refused, naming the run and
  # the link, never opened (a FIFO would block analyze and diff forever).
  "$wpg" batch study.yaml -o s0.h5 --shard 0/1 --no-plot >/dev/null 2>&1
  "$wpg" merge idx.h5 s0.h5 --no-plot >/dev/null
  mv s0.h5 real.h5
  mkfifo s0.h5
  refused 2 "/runs/tiny_0: external link to 's0.h5': expected a regular file, got a FIFO" analyze idx.h5
  refused 2 "/runs/tiny_0: external link to 's0.h5': expected a regular file, got a FIFO" diff idx.h5 real.h5
  "$PYTHON" - <<'PY'
import h5py
with h5py.File("device.h5", "w") as f:
    for name, value in h5py.File("idx.h5", "r").attrs.items():
        f.attrs[name] = value
    f.create_group("runs")["tiny_0"] = h5py.ExternalLink("/dev/zero", "/runs/tiny_0")
PY
  refused 2 "/runs/tiny_0: external link to '/dev/zero': expected a regular file, got a character device" \
    diff device.h5 real.h5
  rm s0.h5
  refused 2 "/runs/tiny_0: external link to 's0.h5': no such file" analyze idx.h5
  ;;
expansion_cap)
  # Runs are counted before anything is computed, against a cap of 2^31 - 1 (the batch files'
  # int32 run numbers), without wrapping; keys are checked first.
  values() { "$PYTHON" -c "print('[' + ', '.join(str($2 + i) for i in range($1)) + ']')"; }
  # 7 keys of 1001 values: 1.007 x 10^21 runs, over 2^63 (and 2^64).
  { echo "name: huge"; echo "base: walk_forward"; echo "sweep:"; echo "  grid:"
    for key in walking.weight_cop walking.weight_jerk walking.weight_velocity walking.weight_yaw \
               walking.com_height robot_mass duration; do
      start=100; [[ $key == walking.com_height ]] && start=0.8  # run 0 is checked first
      echo "    $key: $(values 1001 $start)"
    done
  } >grid.yaml
  refused 2 "grid.yaml: key .sweep.: expected at most 2147483647 runs (2^31 - 1), got more" \
    batch grid.yaml -o grid.h5 --no-plot
  # 16 keys of 16 values: 2^64 runs, a product that wraps to 0 in 64 bits.
  { echo "name: wraps"; echo "base: walk_forward"; echo "sweep:"; echo "  grid:"
    for k in $(seq 0 15); do echo "    no_such_key_$k: $(values 16 0)"; done
  } >wrap.yaml
  refused 2 "no_such_key_0" batch wrap.yaml -o wrap.h5 --no-plot
  # 2 x 2^30 = 2^31 runs: one over the cap.
  sed -e 's/^name: tiny/name: samples/' study.yaml >samples.yaml
  printf '  random: {samples: 1073741824, seed: 1, keys: {walking.com_height: {uniform: [0.78, 0.84]}}}\n' >>samples.yaml
  refused 2 "samples.yaml: key .sweep.: expected at most 2147483647 runs" batch samples.yaml -o samples.h5 --no-plot
  # More samples than the cap on their own: the message gives the cap, not "positive".
  sed -e 's/^name: tiny/name: many_samples/' study.yaml >many.yaml
  printf '  random: {samples: 4611686018427387904, seed: 1, keys: {walking.com_height: {uniform: [0.78, 0.84]}}}\n' >>many.yaml
  refused 2 "many.yaml: key 'sweep.random.samples': expected a number of samples from 1 to 2147483647 (2^31 - 1, the cap on a study's runs), got 4611686018427387904" \
    batch many.yaml -o many.h5 --no-plot
  # 2 x 10^7 runs: a study, but over one batch file's 10^7 rows: in slices.
  sed -e 's/^name: tiny/name: twenty_million/' study.yaml >slices.yaml
  printf '  random: {samples: 10000000, seed: 1, keys: {walking.com_height: {uniform: [0.78, 0.84]}}}\n' >>slices.yaml
  refused 2 "at most 10000000 per batch file (run it in slices: --shard K/N with N >= 2)" \
    batch slices.yaml -o slices.h5 --no-plot
  sed -e 's/^seeds: 1$/seeds: 2000000/' compare.yaml >seeds.yaml
  refused 2 "seeds.*at most 1000000" compare seeds.yaml -o seeds --no-plot
  [[ ! -e slices.h5 ]] || fail "an output was written"
  [[ ! -e grid.h5 && ! -e wrap.h5 && ! -e samples.h5 && ! -e seeds ]] || fail "an output was written"
  ;;
run_name_collision)
  # World 'a.b' x variant 'c' and world 'a' x variant 'b.c' would both be run 'a.b.c.1':
  # refused before any walk.
  cat >collide.yaml <<'YAML'
name: collide
base: {robot: hrp2, duration: 3.0, generator: {algorithm: nmpc, sqp_iterations: 1}}
seeds: 1
worlds:
  - {name: a.b, u_trap: {}}
  - {name: a, u_trap: {}}
variants:
  c: {planner.algorithm: none}
  b.c: {planner.algorithm: none}
YAML
  refused 2 "gives the run name 'a.b.c.1'" compare collide.yaml -o out --no-plot
  [[ ! -e out ]] || fail "compare wrote out/ before refusing"
  ;;
planner_time_limit)
  # An unreachable goal with a planner time limit of 10^9 s planned forever: the key is capped
  # (600 s), and the walk's duration (3 s) bounds all its planning.
  cp "$HERE/studies/goal_boxed_in.yaml" boxed.yaml
  refused 2 "planner.time_limit.*at most 600" run boxed.yaml --set planner.time_limit=1e9 -o a.h5 --no-plot
  status=0
  timeout 60 "$wpg" run boxed.yaml -o b.h5 --no-plot >stdout 2>stderr || status=$?
  [[ $status == 1 ]] || fail "the boxed-in walk: exit $status, expected 1 ($(cat stderr))"
  planning_ms="$(sed -n 's/.*planning \([0-9]*\) ms.*/\1/p' stdout)"
  [[ -n "$planning_ms" && "$planning_ms" -le 4000 ]] || fail "planning took ${planning_ms:-?} ms, over the walk's 3 s"
  ;;
malformed_shard_column)
  # A shard whose summary column holds text where numbers are: bad input naming the shard and
  # the column, whichever place the shard is given in; no index written.
  "$wpg" batch study.yaml -o s0.h5 --shard 0/2 --no-plot >/dev/null 2>&1
  "$wpg" batch study.yaml -o s1.h5 --shard 1/2 --no-plot >/dev/null 2>&1
  "$PYTHON" - <<'PY'
import h5py
with h5py.File("s1.h5", "r+") as f:
    table = f["batch/summary"]
    attrs = dict(table["exit_status"].attrs)
    del table["exit_status"]
    column = table.create_dataset("exit_status", data=[b"x"] * len(table["done"]))
    for name, value in attrs.items():
        column.attrs[name] = value
PY
  refused 2 "s1.h5: /batch/summary/exit_status: expected numbers" merge idx.h5 s0.h5 s1.h5 --no-plot
  refused 2 "s1.h5: /batch/summary/exit_status: expected numbers" merge idx.h5 s1.h5 s0.h5 --copy --no-plot
  [[ ! -e idx.h5 ]] || fail "an index was written"
  ;;
huge_shard_names)
  # A shard whose /batch/summary/name declares 2^40 runs in a few kB (found by
  # fuzz_shard_reader): refused before anything is allocated (8 TB of pointers), naming the
  # shard and the dataset; no index written. Its `done` too.
  "$wpg" batch study.yaml -o s0.h5 --shard 0/2 --no-plot >/dev/null 2>&1
  cp s0.h5 s1.h5
  "$PYTHON" - <<'PY'
import h5py
for path, name in (("s0.h5", "name"), ("s1.h5", "done")):
    with h5py.File(path, "r+") as f:
        table = f["batch/summary"]
        dtype = table[name].dtype
        del table[name]
        table.create_dataset(name, shape=(2**40,), dtype=dtype, chunks=(1024,))
PY
  refused 2 "s0.h5: /batch/summary/name: expected at most 10000000 runs" merge idx.h5 s0.h5 --no-plot
  refused 2 "s1.h5: /batch/summary/done: expected at most 10000000 runs" merge idx.h5 s1.h5 --no-plot
  [[ ! -e idx.h5 ]] || fail "an index was written"
  ;;
shard_attribute_shapes)
  # A shard's root attributes of another shape or type: refused, naming the shard and the
  # attribute. A study_name of three strings was read into one (HDF5's C++ API writes the
  # three pointers over one: memory past it overwritten).
  "$wpg" batch study.yaml -o s0.h5 --shard 0/1 --no-plot >/dev/null 2>&1
  cp s0.h5 s1.h5
  cp s0.h5 s2.h5
  "$PYTHON" - <<'PY'
import h5py
import numpy as np
with h5py.File("s0.h5", "r+") as f:
    name = f.attrs["study_name"]
    del f.attrs["study_name"]
    f.attrs.create("study_name", [name] * 3, dtype=h5py.string_dtype())
with h5py.File("s1.h5", "r+") as f:
    del f.attrs["study_fingerprint"]
    f.attrs["study_fingerprint"] = np.arange(5.0)
with h5py.File("s2.h5", "r+") as f:
    table = f["batch/summary"]
    columns = list(table.attrs["columns"])
    del table.attrs["columns"]
    table.attrs.create("columns", np.array(columns * 2).reshape(2, -1), dtype=h5py.string_dtype())
PY
  refused 2 "s0.h5: attribute /:study_name: expected one value, got 3" merge idx.h5 s0.h5 --no-plot
  refused 2 "s1.h5: attribute /:study_fingerprint: expected a string" merge idx.h5 s1.h5 --no-plot
  refused 2 "s2.h5: attribute /batch/summary:columns: expected a list of strings, got a 2-D array" \
    merge idx.h5 s2.h5 --no-plot
  [[ ! -e idx.h5 ]] || fail "an index was written"
  ;;
messages)
  # Values as given, never rounded away: 1e-320 s is not "0.000000".
  refused 2 "got 1e-320" run walk_forward --set duration=1e-320 -o a.h5 --no-plot
  # A value checked with others (libwpg's validate()) names the --set that set it, every key.
  refused 2 "'duration': expected .*, got 2.2e+04 (set by --set 'duration=22000')$" \
    run walk_forward --set duration=22000 -o a.h5 --no-plot
  refused 2 "'duration': expected at least half a sampling period.* (set by --set 'duration=0.01')$" \
    run walk_forward --set duration=0.01 -o a.h5 --no-plot
  refused 2 "'single_support_samples'.* (set by --set 'walking.single_support_samples=5000')$" \
    run walk_forward --set walking.single_support_samples=5000 -o a.h5 --no-plot
  # A `base:` naming a system file: refused without a line of it in the message.
  printf 'name: sys\nbase: /etc/passwd\nsweep: {grid: {duration: [1.0]}}\n' >sys.yaml
  refused 2 "/etc/passwd: expected a map of scenario keys" batch sys.yaml -o sys.h5 --no-plot
  if grep -q "root:" stderr; then fail "a line of /etc/passwd was echoed: $(cat stderr)"; fi
  # A batch file of a later layout (batch_schema_version 2) is not resumed into.
  "$wpg" batch study.yaml -o future.h5 --no-plot >/dev/null 2>&1
  "$PYTHON" -c "import h5py; h5py.File('future.h5', 'r+').attrs['batch_schema_version'] = 2"
  sum="$(md5sum <future.h5)"
  refused 2 "batch_schema_version is 2, this wpg writes 1" batch study.yaml -o future.h5 --resume --no-plot
  [[ "$(md5sum <future.h5)" == "$sum" ]] || fail "the file of a later layout was modified"
  ;;
fifo_inputs)
  # Every input file is checked to be a regular file before anything opens it: a FIFO given
  # to any command that reads a dataset is refused at once, naming it (opening it would wait
  # for a writer forever).
  mkfifo pipe.h5
  "$wpg" run walk_forward --set duration=1 -o real.h5 --no-plot >/dev/null
  expected="pipe.h5: cannot read: expected a regular file, got a FIFO (pipe)"
  refused 2 "$expected" analyze pipe.h5
  refused 2 "$expected" diff pipe.h5 real.h5
  refused 2 "$expected" diff real.h5 pipe.h5
  refused 2 "$expected" replay pipe.h5 -o replayed.h5 --no-plot
  refused 2 "$expected" view pipe.h5 -o page.html
  refused 2 "$expected" view pipe.h5 --run x -o page.html
  refused 2 "$expected" plot pipe.h5 -o figure.png
  refused 2 "$expected" merge idx.h5 pipe.h5 --no-plot
  mkdir compared && mkfifo compared/study.h5
  refused 2 "compared/study.h5: cannot read: expected a regular file, got a FIFO (pipe)" \
    view compared -o page.html
  [[ ! -e replayed.h5 && ! -e page.html && ! -e figure.png && ! -e idx.h5 ]] ||
    fail "an output was written"
  ;;
long_folder)
  # A working folder whose absolute name is over PATH_MAX (4096 bytes): merge works there as
  # every other command does, both layouts, the links found from the index's folder.
  name="$(printf 'd%.0s' $(seq 250))"
  for _ in $(seq 18); do mkdir "$name" && cd "$name"; done
  [[ ${#PWD} -gt 4096 ]] || fail "the folder's name is ${#PWD} bytes, not over 4096"
  cp "$WORKDIR/study.yaml" . && mkdir shards
  "$wpg" batch study.yaml -o shards/s0.h5 --shard 0/2 --no-plot >/dev/null 2>&1
  "$wpg" batch study.yaml -o shards/s1.h5 --shard 1/2 --no-plot >/dev/null 2>&1
  "$wpg" merge idx.h5 shards --no-plot >stdout 2>stderr || fail "merge: $(cat stderr)"
  "$wpg" merge copy.h5 shards/s0.h5 shards/s1.h5 --copy --no-plot >stdout 2>stderr ||
    fail "merge --copy: $(cat stderr)"
  "$wpg" analyze idx.h5 --format csv >links.csv 2>stderr || fail "analyze idx.h5: $(cat stderr)"
  "$wpg" analyze copy.h5 --format csv >copies.csv 2>stderr || fail "analyze copy.h5: $(cat stderr)"
  [[ "$(wc -l <links.csv)" == 3 ]] || fail "the index does not give 2 runs: $(cat links.csv)"
  cmp -s links.csv copies.csv || fail "the two layouts differ"
  ;;
*) fail "unknown case $case_name" ;;
esac
echo ok
