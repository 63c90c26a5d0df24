#!/usr/bin/env bash
# scripts/fuzz.sh [SECONDS] [TARGET...]: runs each libFuzzer target (tests/fuzz/README.md) for
# SECONDS (default 30; CI's smoke run gives 5) in the sanitizer tree build-sanitize/ (or
# $WPG_SANITIZE_BUILD_DIR; built when needed). Targets: fuzz_scenario_loader,
# fuzz_run_dataset_reader, fuzz_study_loader, fuzz_shard_reader, fuzz_view_page (default: all five). The corpus grows in BUILD/fuzz/<target>/corpus and is
# kept between runs; the seeds and tests/fuzz/regressions/<target>/ are run first. Fails on a
# crash, hang (> 10 s for one input), leak, sanitizer report or allocation over 1 GB; the
# input that did it is BUILD/fuzz/<target>/crash-* (or timeout-*, leak-*, oom-*).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_SANITIZE_BUILD_DIR:-$repo/build-sanitize}")"
# shellcheck source=scripts/sanitizer-env.sh
source "$repo/scripts/sanitizer-env.sh"

seconds="${1:-30}"
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || { echo "fuzz: error: SECONDS must be a positive integer, got '$seconds'" >&2; exit 2; }
shift $(($# > 0 ? 1 : 0))
targets=("$@")
all_targets=(fuzz_scenario_loader fuzz_run_dataset_reader fuzz_study_loader fuzz_shard_reader
             fuzz_view_page)
((${#targets[@]})) || targets=("${all_targets[@]}")
for target in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $target "* ]] \
    || { echo "fuzz: error: unknown target '$target' (${all_targets[*]})" >&2; exit 2; }
done

wpg_sanitizer_tree "$build"
wpg_sanitizer_build "$build" "$build/build-fuzz.log" "${targets[@]}" make_dataset_seeds
wpg_sanitizer_env ""  # reports on stderr, in the fuzzer's log with the input that caused them

# Seeds of the dataset reader: real run datasets (the regression references), every dataset cut
# to 40 stored rows (make_dataset_seeds.cpp): small inputs, the real shapes and attributes.
dataset_seeds="$build/fuzz/seeds/fuzz_run_dataset_reader"
"$build/tests/fuzz/make_dataset_seeds" "$dataset_seeds" 40 \
  "$repo"/datasets/references/{walk_forward,push,goal_with_yaw,obstacle_cluttered}.h5 >/dev/null

# Seeds with global heap damage (tests/fuzz/heap_damage.hpp): each seed of the two HDF5
# targets with one damage entry appended (a zeroed collection, 0xff over its objects, a heap
# ID's length 0xffffffff, ...), so that the fuzzer starts from the heap checks' refusals.
heap_seeds() {  # heap_seeds OUT SEED_FOLDER...
  /usr/bin/python3 - "$@" <<'PY'
import os, struct, sys
out = sys.argv[1]
os.makedirs(out, exist_ok=True)
# target (0 a collection, 1 a heap ID), which, offset, mode (0 zeros, 1 0xff, 2 bytes, 3 add),
# length
damages = [(0, 0, 16, 0, 64), (0, 0, 24, 1, 64), (1, 0, 0, 1, 4), (1, 1, 4, 0, 8),
           (0, 1, 32, 3, 8), (1, 2, 12, 2, 4)]
for folder in sys.argv[2:]:
    for name in sorted(os.listdir(folder)):
        with open(os.path.join(folder, name), "rb") as f:
            data = f.read()
        for k, (target, which, offset, mode, length) in enumerate(damages):
            entry = (b"\x20" + struct.pack("<H", 0) + bytes([target]) +
                     struct.pack("<HHBB", which, offset, mode, length - 1) +
                     struct.pack("<H", 1) + b"\x01")
            with open(os.path.join(out, "%s.heap%d" % (name, k)), "wb") as f:
                f.write(data + entry)
PY
}
heap_seeds "$build/fuzz/seeds/fuzz_run_dataset_reader-heaps" "$dataset_seeds"
heap_seeds "$build/fuzz/seeds/fuzz_shard_reader-heaps" "$repo/tests/fuzz/seeds/shard_reader"

# One target: its seeds and regression inputs, then new inputs for SECONDS; its report in
# $work/report, printed by the caller (the targets run side by side).
fuzz_one() {  # fuzz_one TARGET
  local target=$1 work="$build/fuzz/$1"
  mkdir -p "$work/corpus"
  local seeds=() extra=()
  case "$target" in
    fuzz_scenario_loader)
      seeds=("$repo/datasets/scenarios" "$repo/tests/fuzz/seeds/scenario_loader")
      extra=(-dict="$repo/tests/fuzz/scenario_loader.dict") ;;
    fuzz_run_dataset_reader|fuzz_view_page)
      seeds=("$dataset_seeds" "$build/fuzz/seeds/fuzz_run_dataset_reader-heaps") ;;
    fuzz_study_loader)
      seeds=("$repo/datasets/studies" "$repo/tests/cli/studies" "$repo/tests/cli/bad_studies"
             "$repo/tests/cli/bad_compare_studies" "$repo/tests/fuzz/seeds/study_loader")
      extra=(-dict="$repo/tests/fuzz/study_loader.dict") ;;
    fuzz_shard_reader)
      seeds=("$repo/tests/fuzz/seeds/shard_reader" "$build/fuzz/seeds/fuzz_shard_reader-heaps") ;;
  esac
  [[ -d "$repo/tests/fuzz/regressions/$target" ]] && seeds+=("$repo/tests/fuzz/regressions/$target")
  # -malloc_limit_mb: a dataset declaring more rows than memory must be refused, not allocated.
  if "$build/tests/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
       -malloc_limit_mb=1024 -print_final_stats=1 -artifact_prefix="$work/" "${extra[@]}" \
       "$work/corpus" "${seeds[@]}" >"$work/fuzz.log" 2>&1; then
    echo "fuzz: $target: ok, $(grep -m1 -o 'number_of_executed_units: [0-9]*' "$work/fuzz.log" \
      | grep -o '[0-9]*$') executions, corpus $(find "$work/corpus" -type f | wc -l) inputs" \
      >"$work/report"
  else
    { tail -n 80 "$work/fuzz.log"
      echo "fuzz: error: $target failed (log: $work/fuzz.log; inputs: $work/crash-*, timeout-*, leak-*, oom-*)"
    } >"$work/report"
    return 1
  fi
}

# The targets side by side, as many at a time as there are cores: each is one process on one
# core: CI's five runs of 5 s took 30 s of wall time on two cores, 38 s at 10 s each (the shard
# reader's seeds alone take 15 s: libFuzzer runs every seed whatever SECONDS says).
status=0
jobs_at_once="$(nproc)"
for target in "${targets[@]}"; do
  echo "fuzz: $target for ${seconds} s (log: $build/fuzz/$target/fuzz.log)"
  rm -f "$build/fuzz/$target/report"
  fuzz_one "$target" &
  while (($(jobs -rp | wc -l) >= jobs_at_once)); do wait -n || true; done
done
wait || true
# Each target's outcome is its report's (a job's exit status may be collected by `wait -n`).
for target in "${targets[@]}"; do
  report="$build/fuzz/$target/report"
  if [[ ! -f "$report" ]]; then
    echo "fuzz: error: $target ended without a report" >&2
    status=1
  elif grep -q '^fuzz: error:' "$report"; then
    cat "$report" >&2
    status=1
  else
    cat "$report"
  fi
done
exit "$status"
