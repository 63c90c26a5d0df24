#!/usr/bin/env bash
# hardening_heaps.sh WPG CASE: files whose global heaps (where HDF5 keeps variable-length
# strings: run names, summary columns, stored scenarios) are damaged, given to every reader:
# exit 2 within 20 s with one line naming the file, nothing written; `batch --resume` moves
# the file aside as damaged and runs the study again. Before, HDF5 looped forever on a zeroed
# heap, aborted or segfaulted on 0xff bytes, and allocated 4 GiB for one bad string length
# (damage_heaps.py says how each file is damaged).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$(readlink -f "$1")"
case_name="$2"
make_workdir
cd "$WORKDIR"
cp "$HERE/studies/tiny_batch.yaml" study.yaml

# refused FILE ARGS...: exit 2 within 20 s (in 2 GB of address space), one line on stderr
# naming FILE, nothing on stdout.
refused() {
  local file="$1" status=0
  shift
  # The sanitizer tree (WPG_SANITIZED) has no viewer bundle: `view` says so before reading.
  [[ "${WPG_SANITIZED:-0}" != 1 || "$1" != view ]] || return 0
  # Not under ASan (WPG_SANITIZED): its shadow memory cannot be mapped under ulimit -v; the
  # sanitizer reports any huge allocation itself.
  if [[ "${WPG_SANITIZED:-0}" == 1 ]]; then
    (timeout 60 "$wpg" "$@") >stdout 2>stderr || status=$?
  else
    (ulimit -v 2000000 && timeout 20 "$wpg" "$@") >stdout 2>stderr || status=$?
  fi
  [[ $status == 2 ]] || fail "wpg $*: exit $status, expected 2 (124: timed out) ($(cat stderr))"
  [[ "$(wc -l <stderr)" == 1 ]] || fail "wpg $*: not one line on stderr: $(cat stderr)"
  grep -q "^wpg: error: $file: " stderr || fail "wpg $*: the line does not name $file: $(cat stderr)"
  [[ ! -s stdout ]] || fail "wpg $*: unexpected stdout: $(cat stdout)"
}

# every_reader MODE: the batch file, a shard and a run file damaged by MODE, refused by every
# command that reads them.
every_reader() {
  local mode="$1"
  "$wpg" batch study.yaml -o batch.h5 --no-plot >/dev/null 2>&1
  "$wpg" batch study.yaml -o shard.h5 --shard 0/1 --no-plot >/dev/null 2>&1
  "$wpg" run walk_forward --set duration=1 -o run.h5 --no-plot >/dev/null
  cp batch.h5 good.h5
  for file in batch.h5 shard.h5 run.h5; do
    "$PYTHON" "$HERE/damage_heaps.py" "$mode" "$file" >/dev/null || fail "damage_heaps.py $mode $file"
  done
  refused batch.h5 analyze batch.h5
  refused batch.h5 diff batch.h5 good.h5
  refused batch.h5 diff good.h5 batch.h5
  refused batch.h5 view batch.h5 -o page.html
  refused batch.h5 view batch.h5 --run tiny_0 -o page.html
  refused batch.h5 plot batch.h5 -o figure.png
  refused shard.h5 merge idx.h5 shard.h5 --no-plot
  refused run.h5 analyze run.h5
  refused run.h5 replay run.h5 -o replayed.h5 --no-plot
  refused run.h5 view run.h5 -o page.html
  refused run.h5 plot run.h5 -o figure.png
  [[ ! -e page.html && ! -e figure.png && ! -e idx.h5 && ! -e replayed.h5 ]] ||
    fail "an output was written"
  # --resume judges the file damaged, moves it aside and runs the study again.
  local status=0
  timeout 60 "$wpg" batch study.yaml -o batch.h5 --resume --no-plot >stdout 2>stderr || status=$?
  [[ $status == 0 ]] || fail "batch --resume: exit $status (124: timed out) ($(cat stderr))"
  [[ -f batch.h5.damaged ]] || fail "batch --resume did not move the damaged file aside"
  "$wpg" analyze batch.h5 >/dev/null 2>stderr || fail "the study run again: $(cat stderr)"
}

case "$case_name" in
zeroed_heap) every_reader zero ;;
ff_heap) every_reader ff ;;
string_length)
  # One string's length in /batch/summary/name set to 2^32 - 1: refused before HDF5 reads it.
  "$wpg" batch study.yaml -o batch.h5 --no-plot >/dev/null 2>&1
  "$PYTHON" "$HERE/damage_heaps.py" length batch.h5 >/dev/null || fail "damage_heaps.py length"
  cp batch.h5 shard.h5
  "$wpg" batch study.yaml -o good.h5 --no-plot >/dev/null 2>&1
  refused batch.h5 view batch.h5 -o page.html
  refused batch.h5 diff batch.h5 good.h5
  refused batch.h5 plot batch.h5 -o figure.png
  refused shard.h5 merge idx.h5 shard.h5 --no-plot
  [[ ! -e page.html && ! -e figure.png && ! -e idx.h5 ]] || fail "an output was written"
  ;;
*) fail "unknown case $case_name" ;;
esac
echo ok
