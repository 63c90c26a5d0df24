#!/usr/bin/env bash
# Installs the missing Debian packages, then configures (Release) and builds wpg in build/
# (or in $WPG_BUILD_DIR). Idempotent: quiet when everything is already installed and built.
# Works from any folder.
#
#   scripts/setup.sh                 the default: everything but MPI and clang
#   scripts/setup.sh --with-mpi      also Open MPI (openmpi-bin, libopenmpi-dev) and a build with
#                                    WPG_WITH_MPI=ON: `mpirun -np R wpg batch ...` (README,
#                                    "Running on a cluster")
#   scripts/setup.sh --with-clang    also clang 14 and its sanitizer/libFuzzer runtimes
#                                    (scripts/test-sanitizers.sh, scripts/fuzz.sh)
#   scripts/setup.sh --packages-only install the packages, do not build build/
#   scripts/setup.sh --without-viewer no Node.js, npm nor Chromium: build without the page of
#                                    `wpg view` (WPG_BUILD_VIEWER=OFF) and without its tests
set -euo pipefail

with_mpi=""
with_clang=0
with_viewer=1
packages_only=0
for argument in "$@"; do
  case "$argument" in
    --with-mpi) with_mpi=yes ;;
    --with-clang) with_clang=1 ;;
    --packages-only) packages_only=1 ;;
    --without-viewer) with_viewer=0 ;;
    *) echo "setup: error: unknown option '$argument' (expected --with-mpi, --with-clang, --packages-only, --without-viewer)" >&2
       exit 2 ;;
  esac
done

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"

# ../shared/TOOLCHAIN.md: Eigen (libwpg), HDF5 + yaml-cpp (datasets), CLI11 (cli), FCL and
# OMPL with the Boost libraries its CMake configuration names (planning), Simbody + urdfdom (robots), GoogleTest + Google Benchmark (tests), h5py +
# matplotlib + PyYAML (analysis figures, run by Debian's /usr/bin/python3; PyYAML reads the
# scenario stored in the dataset: obstacles, command, foot size).
packages=(build-essential cmake libeigen3-dev libhdf5-dev libcli11-dev libgtest-dev
          libbenchmark-dev libyaml-cpp-dev libfcl-dev libsimbody-dev liburdfdom-dev
          libompl-dev libboost-serialization-dev libboost-filesystem-dev libboost-system-dev
          python3-h5py python3-matplotlib python3-yaml)
if [[ -n "$with_mpi" ]]; then packages+=(openmpi-bin libopenmpi-dev); fi
if ((with_clang)); then packages+=(clang-14 libclang-rt-14-dev); fi
# `wpg view` (docs/viewer.md): Node.js and npm bundle its page at build time (npm ci from
# analysis/viewer/package-lock.json), Debian's when no node and npm are on PATH (a NodeSource
# Node.js brings its own npm); Chromium opens the pages in the tests, headless.
if ((with_viewer)); then
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then packages+=(nodejs npm); fi
  packages+=(chromium)
fi

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
((with_viewer)) || cmake_options+=(-DWPG_BUILD_VIEWER=OFF)
if [[ -n "$with_mpi" ]]; then
  cmake_options+=(-DWPG_WITH_MPI=ON)
  # A build tree configured before MPI was installed has WPG_WITH_MPI=OFF in its cache.
  if [[ -f "$build/CMakeCache.txt" ]] && ! grep -q '^WPG_WITH_MPI:BOOL=ON' "$build/CMakeCache.txt"; then
    echo "setup: configuring $build with MPI (WPG_WITH_MPI=ON)"
    if ! cmake -S "$repo" -B "$build" "${cmake_options[@]}" >>"$log" 2>&1; then
      cat "$log" >&2
      echo "setup: error: cmake configure with MPI failed (output above)" >&2
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
