#!/usr/bin/env bash
# layers.sh CHECKER SOURCE: the module order holds in the source tree (scripts/check-layers.py
# exits 0), and the checker catches what it is for: in a small tree, an include from a lower
# module into a higher one, between two modules of one level, out of a module through "..",
# and a link to a higher target, each one line naming the file; the includes that go down pass.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
checker="$(readlink -f "$1")"
source_tree="$(readlink -f "$2")"
"$PYTHON" "$checker" --root "$source_tree" >out 2>&1 || fail "the source tree: $(cat out)"
make_workdir
cd "$WORKDIR"
mkdir -p tree/libwpg/include/wpg tree/datasets/input/src tree/cli/engine/src tree/cli/commands \
  tree/planning
echo '#include "wpg/engine/scenario_run.hpp"' >tree/libwpg/include/wpg/up.hpp
echo '#include "wpg/planning/world.hpp"' >tree/datasets/input/src/sibling.cpp
echo '#include "../../commands/options.hpp"' >tree/cli/engine/src/climbs.cpp
touch tree/cli/commands/options.hpp
echo 'target_link_libraries(wpg_planning PUBLIC wpg_core wpg_engine)' >tree/planning/CMakeLists.txt
printf '#include "wpg/engine/scenario_run.hpp"\n#include "wpg/walk_generator.hpp"\n#include "options.hpp"\n' \
  >tree/cli/commands/down.cpp
status=0
"$PYTHON" "$checker" --root tree >out 2>&1 || status=$?
[[ $status == 1 ]] || fail "planted violations: exit $status, expected 1 ($(cat out))"
for expected in "libwpg/include/wpg/up.hpp:1: libwpg (level 0) includes wpg/engine/scenario_run.hpp" \
                "datasets/input/src/sibling.cpp:1: datasets/input (level 1) includes wpg/planning/world.hpp of planning (level 1)" \
                "cli/engine/src/climbs.cpp:1: cli/engine (level 4) includes ../../commands/options.hpp of cli/commands" \
                "planning/CMakeLists.txt:1: planning (level 1) links wpg_engine"; do
  grep -qF -- "$expected" out || fail "not reported: $expected ($(cat out))"
done
[[ "$(wc -l <out)" == 4 ]] || fail "expected 4 lines: $(cat out)"
echo ok
