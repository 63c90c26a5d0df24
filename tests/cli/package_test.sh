#!/usr/bin/env bash
# package_test.sh CMAKE BUILD_DIR DOWNSTREAM_SOURCE [CMAKE_ARG...]: installs the existing build
# tree into a temporary prefix (no rebuild), then configures, builds and runs a downstream
# project that uses find_package(wpg), one beside it (downstream_core/) that asks for the
# core component only with every other dependency of wpg unfindable, and one that extends the
# NMPC with its own family and cost term (downstream_extensions/); finally checks that the
# installed wpg finds its installed data. The CMAKE_ARGs go to the downstream configure.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
cmake="$1"; build_dir="$2"; downstream="$3"
shift 3
make_workdir
prefix="$WORKDIR/prefix"
# The downstream projects compile through ccache when it is installed, from copies of their
# sources in this test's folder, with ccache's base folder there: every run compiles the same
# relative paths, so that a warm cache compiles nothing (their three builds were 12 of the
# test's 21 s on 2 cores).
projects="$(dirname "$downstream")"
mkdir "$WORKDIR/src"
cp -r "$downstream" "$projects/downstream_core" "$projects/downstream_extensions" "$WORKDIR/src/"
downstream="$WORKDIR/src/$(basename "$downstream")"
if command -v ccache >/dev/null; then
  set -- -DCMAKE_CXX_COMPILER_LAUNCHER=ccache "$@"
  export CCACHE_BASEDIR="$WORKDIR" CCACHE_NOHASHDIR=1
fi
"$cmake" --install "$build_dir" --prefix "$prefix" >"$WORKDIR/install.log" 2>&1 \
  || { cat "$WORKDIR/install.log"; fail "cmake --install"; }
[[ -f "$prefix/lib/cmake/wpg/wpgConfig.cmake" || -n "$(find "$prefix" -name wpgConfig.cmake)" ]] \
  || fail "no wpgConfig.cmake installed"
"$cmake" -S "$downstream" -B "$WORKDIR/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" "$@" >"$WORKDIR/configure.log" 2>&1 \
  || { cat "$WORKDIR/configure.log"; fail "configuring the downstream project"; }
"$cmake" --build "$WORKDIR/build" -j2 >"$WORKDIR/build.log" 2>&1 \
  || { cat "$WORKDIR/build.log"; fail "building the downstream project"; }
"$WORKDIR/build/wpg_downstream" || fail "the downstream executable failed"

# find_package(wpg COMPONENTS core) needs Eigen alone: configured with HDF5, yaml-cpp, FCL,
# OMPL, Simbody, urdfdom and MPI unfindable (CMAKE_DISABLE_FIND_PACKAGE_<name>: find_package
# fails for them as on a machine without them), built, linked and run; its compile and link
# lines name none of them.
hidden=()
for package in HDF5 yaml-cpp fcl ompl Simbody urdfdom MPI; do
  hidden+=("-DCMAKE_DISABLE_FIND_PACKAGE_$package=ON")
done
version="$(sed -n 's/^#define WPG_VERSION_STRING "\(.*\)"$/\1/p' "$prefix/include/wpg/version.hpp")"
[[ -n "$version" ]] || fail "no WPG_VERSION_STRING in the installed wpg/version.hpp"
"$cmake" -S "$(dirname "$downstream")/downstream_core" -B "$WORKDIR/core" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" "${hidden[@]}" "$@" \
  >"$WORKDIR/core-configure.log" 2>&1 \
  || { cat "$WORKDIR/core-configure.log"; fail "configuring the core-only downstream project"; }
"$cmake" --build "$WORKDIR/core" -j2 >"$WORKDIR/core-build.log" 2>&1 \
  || { cat "$WORKDIR/core-build.log"; fail "building the core-only downstream project"; }
if cat <(grep -E '^CXX_(INCLUDES|DEFINES)' "$WORKDIR/core/CMakeFiles/wpg_downstream_core.dir/flags.make") \
       "$WORKDIR/core/CMakeFiles/wpg_downstream_core.dir/link.txt" \
     | grep -Ei 'hdf5|simbody|simtk|fcl|ompl|yaml|urdf|deflate|libmpi|openmpi'; then
  fail "the core-only project compiles or links against a dependency of another component"
fi
"$WORKDIR/core/wpg_downstream_core" "$version" || fail "the core-only downstream executable failed"

# A project that extends the NMPC through the public API (docs/extending.md): its own family
# and cost term registered by name, their finite-difference checks, a walk with both.
"$cmake" -S "$(dirname "$downstream")/downstream_extensions" -B "$WORKDIR/extensions" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" "${hidden[@]}" "$@" \
  >"$WORKDIR/extensions-configure.log" 2>&1 \
  || { cat "$WORKDIR/extensions-configure.log"; fail "configuring the extensions project"; }
"$cmake" --build "$WORKDIR/extensions" -j2 >"$WORKDIR/extensions-build.log" 2>&1 \
  || { cat "$WORKDIR/extensions-build.log"; fail "building the extensions project"; }
"$WORKDIR/extensions/wpg_downstream_extensions" || fail "the extensions project's checks failed"

# The installed executable with the installed data (robots, scenarios, plot script).
data="$(dirname "$(find "$prefix" -path '*/wpg/robots' -not -path '*/doc/*' -type d | head -n1)")"
[[ -d "$data/robots" && -d "$data/datasets/scenarios" && -f "$data/analysis/plot_run.py" ]] \
  || fail "installed data incomplete under $prefix/share/wpg"
WPG_DATA_DIR="$data" "$prefix/bin/wpg" run walk_forward --set duration=2 \
  -o "$WORKDIR/installed.h5" || fail "installed wpg run: exit status $?"
check_run_file "$WORKDIR/installed.h5"
check_png "$WORKDIR/installed.png"

# The documentation is installed, and the links between its pages hold there.
docs="$(dirname "$(find "$prefix" -path '*/doc/wpg/docs' -type d | head -n1)")"
for page in README.md CHANGELOG.md LICENSE docs/README.md docs/commands.md datasets/SCHEMA.md; do
  [[ -s "$docs/$page" ]] || fail "documentation not installed: $page (under $prefix/share/doc/wpg)"
done
"$PYTHON" "$HERE/check_doc_links.py" "$docs" --pages-only || fail "broken links in the installed documentation"
echo "ok"
