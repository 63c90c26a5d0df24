#!/usr/bin/env bash
# Installs the missing Debian packages, then configures (Release) and builds wpg in build/
# (or in $WPG_BUILD_DIR). Idempotent: quiet when everything is already installed and built.
# Works from any folder.
#
#   scripts/setup.sh                 the default (scripts/run-default.sh): everything `wpg`
#                                    needs, no MPI, clang, Node.js nor Chromium
#   scripts/setup.sh --with-mpi      also Open MPI (openmpi-bin, libopenmpi-dev) and a build with
#                                    WPG_WITH_MPI=ON: `mpirun -np R wpg batch ...` (README,
#                                    "Running on a cluster")
#   scripts/setup.sh --with-python   also pybind11, numpy, pandas and pytest (Debian's), and a
#                                    build with WPG_BUILD_PYTHON=ON: the Python package wpg
#                                    (docs/python.md) and its tests
#   scripts/setup.sh --with-clang    also clang 14 and its sanitizer/libFuzzer runtimes
#                                    (scripts/test-sanitizers.sh, scripts/fuzz.sh)
#   scripts/setup.sh --packages-only install the packages, do not build build/
#   scripts/setup.sh --with-viewer   also Node.js and npm (Debian's, when none is on PATH) and
#                                    a build with WPG_BUILD_VIEWER=ON: the page of `wpg view`
#                                    (docs/viewer.md; without them `wpg` builds and runs, and
#                                    `wpg view` says how to get its page)
#   scripts/setup.sh --for-tests     what every test needs (scripts/test.sh): --with-viewer,
#                                    --with-python and Chromium (opens the pages headless)
set -euo pipefail

with_mpi=""
with_clang=0
with_python=0
with_viewer=0
with_chromium=0
packages_only=0
for argument in "$@"; do
  case "$argument" in
    --with-mpi) with_mpi=yes ;;
    --with-clang) with_clang=1 ;;
    --with-python) with_python=1 ;;
    --packages-only) packages_only=1 ;;
    --with-viewer) with_viewer=1 ;;
    --for-tests) with_viewer=1 with_chromium=1 with_python=1 ;;
    *) echo "setup: error: unknown option '$argument' (expected --with-mpi, --with-python, --with-clang, --packages-only, --with-viewer, --for-tests)" >&2
       exit 2 ;;
  esac
done

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"

# The toolchain: Eigen (libwpg), HDF5 + yaml-cpp + libdeflate (datasets), CLI11 (cli), FCL and OMPL with the
# Boost libraries its CMake configuration names (planning), Simbody + urdfdom (robots),
# GoogleTest + Google Benchmark (tests), h5py + matplotlib + PyYAML (analysis figures, run by
# Debian's /usr/bin/python3; PyYAML reads the scenario stored in the dataset: obstacles,
# command, foot size).
packages=(build-essential cmake libeigen3-dev libhdf5-dev libdeflate-dev libcli11-dev libgtest-dev
          libbenchmark-dev libyaml-cpp-dev libfcl-dev libsimbody-dev liburdfdom-dev
          libompl-dev libboost-serialization-dev libboost-filesystem-dev libboost-system-dev
          python3-h5py python3-matplotlib python3-yaml)
if [[ -n "$with_mpi" ]]; then packages+=(openmpi-bin libopenmpi-dev); fi
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

jobs="$(nproc)"
log="$build/setup-build.log"
mkdir -p "$build"
: >"$log"
cmake_options=()
[[ -z "$with_mpi" ]] || cmake_options+=(-DWPG_WITH_MPI=ON)
((!with_viewer)) || cmake_options+=(-DWPG_BUILD_VIEWER=ON)
((!with_python)) || cmake_options+=(-DWPG_BUILD_PYTHON=ON)
# A build tree configured before MPI, Node.js and npm, or pybind11 were installed has
# WPG_WITH_MPI, WPG_BUILD_VIEWER or WPG_BUILD_PYTHON OFF in its cache.
if [[ -f "$build/CMakeCache.txt" ]]; then
  turned_on=()
  if [[ -n "$with_mpi" ]] && ! grep -q '^WPG_WITH_MPI:BOOL=ON' "$build/CMakeCache.txt"; then
    turned_on+=(WPG_WITH_MPI=ON)
  fi
  if ((with_viewer)) && ! grep -q '^WPG_BUILD_VIEWER:BOOL=ON' "$build/CMakeCache.txt"; then
    turned_on+=(WPG_BUILD_VIEWER=ON)
  fi
  if ((with_python)) && ! grep -q '^WPG_BUILD_PYTHON:BOOL=ON' "$build/CMakeCache.txt"; then
    turned_on+=(WPG_BUILD_PYTHON=ON)
  fi
  if ((${#turned_on[@]})); then
    echo "setup: configuring $build with ${turned_on[*]}"
    if ! cmake -S "$repo" -B "$build" "${cmake_options[@]}" >>"$log" 2>&1; then
      cat "$log" >&2
      echo "setup: error: cmake configure with ${turned_on[*]} failed (output above)" >&2
      exit 1
    fi
  fi
fi
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  echo "setup: configuring and building wpg in $build (Release, -j$jobs; log: $log)"
  if ! cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release "${cmake_options[@]}" >>"$log" 2>&1; then
    cat "$log" >&2
    echo "setup: error: cmake configure failed (output above)" >&2
    exit 1
  fi
fi
if ! cmake --build "$build" -j"$jobs" >>"$log" 2>&1; then
  cat "$log" >&2
  echo "setup: error: build failed (output above; log: $log)" >&2
  exit 1
fi
# One progress line when something was (re)built, nothing when the build was up to date.
rebuilt="$(grep -c 'Building CXX object' "$log" || true)"
if ((rebuilt > 0)); then
  echo "setup: built wpg in $build ($rebuilt files compiled)"
fi
