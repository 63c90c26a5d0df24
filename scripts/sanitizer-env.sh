# shellcheck shell=bash
# Sourced by scripts/test-sanitizers.sh and scripts/fuzz.sh: the instrumented build tree and the
# sanitizer runtime options. Expects $repo (the source tree).
repo="${repo:?}"

# wpg_sanitizer_tree BUILD: installs clang 14 and what the tests need when missing (setup.sh
# --with-clang --with-tests), configures BUILD once (clang 14, Release, -DWPG_SANITIZE=ON
# -DWPG_FUZZ=ON: one tree serves the test suite and the fuzz targets;
# cmake/wpg_sanitizers.cmake), through ccache when it is installed.
wpg_sanitizer_tree() {
  local build="$1" launcher=()
  "$repo/scripts/setup.sh" --with-clang --with-tests --packages-only
  mkdir -p "$build"
  if [[ ! -f "$build/CMakeCache.txt" ]]; then
    echo "sanitizers: configuring $build (clang 14, ASan + UBSan, fuzz targets)"
    command -v ccache >/dev/null \
      && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    CC=clang-14 CXX=clang++-14 cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release \
      -DWPG_SANITIZE=ON -DWPG_FUZZ=ON -DWPG_WITH_MPI=OFF \
      -DWPG_BUILD_PYTHON=OFF -DWPG_BUILD_VIEWER=OFF "${launcher[@]}" \
      >"$build/configure.log" 2>&1 \
      || { cat "$build/configure.log" >&2; echo "sanitizers: error: configure failed" >&2; return 1; }
  fi
}

# wpg_sanitizer_build BUILD LOG [TARGET...]: builds (everything without targets), log in LOG.
wpg_sanitizer_build() {
  local build="$1" log="$2"; shift 2
  local targets=()
  (($#)) && targets=(--target "$@")
  echo "sanitizers: building ${*:-everything} (-j$(nproc); log: $log)"
  # Paths relative to the clone in ccache's keys (-g1 objects: the folder is left out of them).
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$repo}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
  cmake --build "$build" -j"$(nproc)" "${targets[@]}" >"$log" 2>&1 \
    || { tail -n 60 "$log" >&2; echo "sanitizers: error: build failed" >&2; return 1; }
}

# wpg_sanitizer_env [REPORT_DIR]: the runtime options: halt at the first report, leaks checked,
# suppressions (third-party code only) from tests/sanitizers/. With REPORT_DIR, every
# instrumented process writes its reports to REPORT_DIR/<sanitizer>.<pid> instead of stderr:
# also the processes run by test scripts, whose exit status a test may not look at.
wpg_sanitizer_env() {
  local reports="${1:-}" log_asan="" log_ubsan=""
  if [[ -n "$reports" ]]; then
    rm -rf "$reports"
    mkdir -p "$reports"
    log_asan="log_path=$reports/asan:"
    log_ubsan="log_path=$reports/ubsan:"
  fi
  # quarantine_size_mb=64: a freed block stays poisoned (a use after free reported) until 64 MB
  # more have been freed after it; ASan's default is 256 MB, more than most of these processes
  # free in their life, so none of their memory was ever reused and every allocation touched
  # fresh pages. Page faults are costly on the 2-core VM: batch, run, compare, analyze, replay
  # and diff under ASan took 7.2 s of CPU with the default and 6.0 s with 64 MB (three
  # interleaved runs each, 2026-12-04). A use after free later than 64 MB of frees goes unseen.
  export ASAN_OPTIONS="${log_asan}detect_leaks=1:halt_on_error=1:strict_string_checks=1:check_initialization_order=1:quarantine_size_mb=64"
  export UBSAN_OPTIONS="${log_ubsan}print_stacktrace=1:halt_on_error=1:suppressions=$repo/tests/sanitizers/ubsan.supp"
  export LSAN_OPTIONS="suppressions=$repo/tests/sanitizers/lsan.supp:print_suppressions=0"
}

# wpg_sanitizer_reports REPORT_DIR: prints every report written there; fails if there is one.
wpg_sanitizer_reports() {
  local reports="$1" found=0 file
  for file in "$reports"/*; do
    [[ -f "$file" ]] || continue
    found=1
    echo "==== sanitizer report $file" >&2
    cat "$file" >&2
  done
  if ((found)); then
    echo "sanitizers: error: the reports above (in $reports)" >&2
    return 1
  fi
}
