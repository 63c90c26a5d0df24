#!/usr/bin/env bash
# Builds wpg and the test programs that start threads with clang 14 + ThreadSanitizer in
# build-tsan/ (or $WPG_TSAN_BUILD_DIR; WPG_TSAN in cmake/wpg_sanitizers.cmake), then runs the
# threaded tests only: the factor cache shared by threads, the study loader's threads, the
# prepared runs and the batch writer, the parallel replay, the route planner and world queried
# from two threads, the study executor's workers and its ordered delivery, and `wpg batch -j 2`,
# `wpg compare -j 2` and `wpg run --replay --filter` (two threads, the run's image built on
# the second). Fails on a failing test and on any data race or lock-order report, also from a
# process whose exit status a test does not look at (reports go to files, printed at the end).
# Suppressions, for third-party libraries only: tests/sanitizers/tsan.supp. Works from any folder.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_TSAN_BUILD_DIR:-$repo/build-tsan}")"
# shellcheck source=scripts/sanitizer-env.sh
source "$repo/scripts/sanitizer-env.sh"

"$repo/scripts/setup.sh" --with-clang --with-tests --packages-only
mkdir -p "$build"
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  echo "tsan: configuring $build (clang 14, ThreadSanitizer)"
  launcher=()
  command -v ccache >/dev/null \
    && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  CC=clang-14 CXX=clang++-14 cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DWPG_TSAN=ON -DWPG_WITH_MPI=OFF -DWPG_BUILD_PYTHON=OFF -DWPG_BUILD_VIEWER=OFF \
    "${launcher[@]}" >"$build/configure.log" 2>&1 \
    || { cat "$build/configure.log" >&2; echo "tsan: error: configure failed" >&2; exit 1; }
fi
tests=(wpg_libwpg_tests wpg_datasets_tests wpg_planning_tests wpg_robots_tests wpg_engine_tests)
wpg_sanitizer_build "$build" "$build/build.log" wpg "${tests[@]}"

reports="$build/tsan-reports"
rm -rf "$reports"
mkdir -p "$reports"
export TSAN_OPTIONS="log_path=$reports/tsan:halt_on_error=1:second_deadlock_stack=1:suppressions=$repo/tests/sanitizers/tsan.supp"
export TMPDIR="$build/tmp"
rm -rf "$TMPDIR"
mkdir -p "$TMPDIR"
status=0
run() {
  echo "tsan: $*"
  "$@" >"$TMPDIR/last.log" 2>&1 || { cat "$TMPDIR/last.log" >&2; status=1; }
}
# run_tests PROGRAM FILTER: a test program's tests that FILTER selects; a filter that selects no
# test (a renamed test) fails too, as GoogleTest would pass it.
run_tests() {
  run "$build/tests/$1" --gtest_filter="$2"
  local ran
  ran="$(grep -c '^\[       OK \]' "$TMPDIR/last.log" || true)"
  echo "tsan:   $ran tests passed"
  ((ran > 0)) || { echo "tsan: error: no test of $1 matches '$2'" >&2; status=1; }
}
run_tests wpg_libwpg_tests 'HessianFactorCache.*'
run_tests wpg_datasets_tests 'RunDatasetFiles.APreparedWalkWritesTheSameChunks:StudyFiles.ThreadsDoNotChangeTheRunsNorTheError:ComparisonFiles.RandomFieldsAreDrawnPerSeedAndReproducible:BatchFiles.*'
run_tests wpg_planning_tests 'RoutePlanner.SameSeedGivesTheSameRouteAgainAndOnOtherThreads:World.ConcurrentQueriesAgreeWithSequentialOnes'
run_tests wpg_robots_tests 'MultibodyReplay.ThreadsGiveTheSameRows:MultibodyReplay.PreparedSystemsGiveTheSameRows'
run_tests wpg_engine_tests 'OrderedParallel.*:StudyExecution.*'
wpg="$build/cli/wpg"
export WPG_DATA_DIR="$repo"
run "$wpg" batch "$repo/tests/cli/studies/tiny_batch.yaml" -j 2 --no-plot -o "$TMPDIR/batch.h5"
run "$wpg" compare "$repo/tests/cli/studies/tiny_compare.yaml" -j 2 --no-plot -o "$TMPDIR/compare"
run "$wpg" run walk_forward --set duration=4 --replay --filter --no-plot -o "$TMPDIR/run.h5"
wpg_sanitizer_reports "$reports" || status=1
exit "$status"
