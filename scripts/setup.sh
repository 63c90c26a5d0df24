#!/usr/bin/env bash
# Installs the missing Debian packages, then configures (Release) and builds wpg in build/ (or in
# $WPG_BUILD_DIR). Idempotent: quiet when everything is already installed and built. Works from
# any folder.
#
#   scripts/setup.sh                   the `wpg` tool and its libraries (scripts/run-default.sh)
#   scripts/setup.sh --with-tests      also GoogleTest, and builds the tests (scripts/test.sh)
#   scripts/setup.sh --with-benchmarks also Google Benchmark, and builds tests/benchmarks
#   scripts/setup.sh --with-mpi        also Open MPI (openmpi-bin, libopenmpi-dev), built with
#                                      WPG_WITH_MPI=ON: `mpirun -np R wpg batch ...`
#                                      (docs/studies.md, "Running on a cluster")
#   scripts/setup.sh --with-clang      also clang 14 and its sanitizer/libFuzzer runtimes
#                                      (scripts/test-sanitizers.sh, scripts/fuzz.sh)
#   scripts/setup.sh --with-python     also pybind11, numpy, pandas and pytest (Debian's), built
#                                      with WPG_BUILD_PYTHON=ON: the Python package wpg
#                                      (docs/python.md)
#   scripts/setup.sh --with-viewer     also Node.js and npm (Debian's, when none is on PATH),
#                                      built with WPG_BUILD_VIEWER=ON: the page of `wpg view`
#                                      (docs/viewer.md; without them `wpg view` says how to get it)
#   scripts/setup.sh --for-tests       what every test needs (scripts/test.sh): --with-tests,
#                                      --with-python, --with-viewer and Chromium (the tests open
#                                      the pages headless)
#   scripts/setup.sh --packages-only   install the packages, do not build
#
# A tree only gains what is asked: a later call without --with-tests or --with-mpi keeps them.
# Compiles through ccache (installed here; its cache is ccache's own, outside the clone).
set -euo pipefail

with_tests=0
with_benchmarks=0
with_mpi=0
with_clang=0
with_python=0
with_viewer=0
with_chromium=0
packages_only=0
for argument in "$@"; do
  case "$argument" in
    --with-tests) with_tests=1 ;;
    --with-benchmarks) with_benchmarks=1 ;;
    --with-mpi) with_mpi=1 ;;
    --with-clang) with_clang=1 ;;
    --with-python) with_python=1 ;;
    --with-viewer) with_viewer=1 ;;
    --for-tests) with_tests=1 with_python=1 with_viewer=1 with_chromium=1 ;;
    --packages-only) packages_only=1 ;;
    *) echo "setup: error: unknown option '$argument' (expected --with-tests, --with-benchmarks," \
            "--with-mpi, --with-clang, --with-python, --with-viewer, --for-tests, --packages-only)" >&2
       exit 2 ;;
  esac
done

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"

# docs/dependencies.md says what each is for: Eigen (libwpg), HDF5 + yaml-cpp + libdeflate (datasets), CLI11
# (cli), FCL and OMPL with the Boost libraries OMPL's CMake configuration names (planning),
# Simbody + urdfdom (robots), h5py + matplotlib + PyYAML (the figures, drawn by Debian's
# /usr/bin/python3; PyYAML reads the scenario stored in a dataset), ccache (rebuilds), lld (the
# linker, faster than GNU ld: cmake/wpg_linker.cmake).
packages=(build-essential cmake ccache lld libeigen3-dev libhdf5-dev libdeflate-dev libcli11-dev libyaml-cpp-dev
          libfcl-dev libsimbody-dev liburdfdom-dev libompl-dev libboost-serialization-dev
          libboost-filesystem-dev libboost-system-dev python3-h5py python3-matplotlib
          python3-yaml)
if ((with_tests)); then packages+=(libgtest-dev); fi
if ((with_benchmarks)); then packages+=(libbenchmark-dev); fi
if ((with_mpi)); then packages+=(openmpi-bin libopenmpi-dev); fi
if ((with_clang)); then packages+=(clang-14 libclang-rt-14-dev); fi
if ((with_python)); then packages+=(python3-dev python3-pybind11 python3-numpy python3-pandas python3-pytest); fi
# `wpg view` (docs/viewer.md): Node.js and npm bundle its page at build time (npm ci from
# analysis/viewer/package-lock.json), Debian's when no node and npm are on PATH (a NodeSource
# Node.js brings its own npm); Chromium opens the pages in the tests, headless. Neither is
# needed to build or run the rest of wpg.
if ((with_viewer)); then
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then packages+=(nodejs npm); fi
fi
if ((with_chromium)); then packages+=(chromium); fi

missing=()
for package in "${packages[@]}"; do
  status="$(dpkg-query -W -f='${db:Status-Status}' "$package" 2>/dev/null || true)"
  [[ "$status" == installed ]] || missing+=("$package")
done
if ((${#missing[@]})); then
  echo "setup: installing Debian packages: ${missing[*]}"
  sudo=()
  if [[ "$(id -u)" != 0 ]]; then
    command -v sudo >/dev/null || { echo "setup: error: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
  fi
  log="$(mktemp)"
  if ! { "${sudo[@]}" apt-get update && "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
           apt-get install -y --no-install-recommends "${missing[@]}"; } >"$log" 2>&1; then
    cat "$log" >&2
    rm -f "$log"
    echo "setup: error: apt-get failed (output above)" >&2
    exit 1
  fi
  rm -f "$log"
fi
((packages_only)) && exit 0

mkdir -p "$build"
log="$build/setup-build.log"
: >"$log"

# The settings this call needs, against those of the tree: configure when there is no tree or
# when it lacks one of them (a tree is never switched back: tests stay once built).
cached() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt" 2>/dev/null; }
settings=()
reason=""
need() { [[ -n "$reason" ]] || reason="$1"; shift; settings+=("$@"); }
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  need "configuring" -DCMAKE_BUILD_TYPE=Release \
    "-DWPG_BUILD_TESTS=$( ((with_tests)) && echo ON || echo OFF)"
elif ((with_tests)) && [[ "$(cached WPG_BUILD_TESTS)" != ON ]]; then
  need "adding the tests to" -DWPG_BUILD_TESTS=ON
fi
if ((with_benchmarks)) && [[ "$(cached WPG_BUILD_BENCHMARKS)" != ON ]]; then
  need "adding the benchmarks to" -DWPG_BUILD_BENCHMARKS=ON
fi
# Also a tree configured before MPI was installed (WPG_WITH_MPI=OFF in its cache).
if ((with_mpi)) && [[ "$(cached WPG_WITH_MPI)" != ON ]]; then
  need "configuring MPI (WPG_WITH_MPI=ON) in" -DWPG_WITH_MPI=ON
fi
if ((with_python)) &&
   [[ "$(cached WPG_BUILD_PYTHON)" != ON || "$(cached WPG_STATIC_HDF5)" != OFF ]]; then
  # Its extension needs the shared HDF5 (cmake/wpg_startup.cmake).
  need "adding the Python package (WPG_BUILD_PYTHON=ON) to" -DWPG_BUILD_PYTHON=ON \
    -DWPG_STATIC_HDF5=OFF
fi
if ((with_viewer)) && [[ "$(cached WPG_BUILD_VIEWER)" != ON ]]; then
  need "adding the viewer's page (WPG_BUILD_VIEWER=ON) to" -DWPG_BUILD_VIEWER=ON
fi
if command -v ccache >/dev/null && [[ -z "$(cached CMAKE_CXX_COMPILER_LAUNCHER)" ]]; then
  need "adding ccache to" -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache
fi
if ((${#settings[@]})); then
  echo "setup: $reason $build (log: $log)"
  if ! cmake -S "$repo" -B "$build" "${settings[@]}" >>"$log" 2>&1; then
    cat "$log" >&2
    echo "setup: error: cmake configure failed (output above)" >&2
    exit 1
  fi
fi

# Paths relative to the clone in ccache's keys: another clone of the same commit hits the cache.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$repo}"
# Only what the caller runs: `wpg` (its libraries with it), or everything the tree holds.
targets=(--target wpg)
if ((with_tests || with_benchmarks || with_python || with_viewer)); then targets=(); fi
jobs="$(nproc)"
if ! cmake --build "$build" -j"$jobs" "${targets[@]}" >>"$log" 2>&1; then
  cat "$log" >&2
  echo "setup: error: build failed (output above; log: $log)" >&2
  exit 1
fi
# One progress line when something was (re)built, nothing when the build was up to date.
rebuilt="$(grep -c 'Building CXX object' "$log" || true)"
if ((rebuilt > 0)); then
  what="wpg"
  ((${#targets[@]})) || what="wpg and its tests"
  echo "setup: built $what in $build ($rebuilt files compiled, -j$jobs)"
fi
