#!/usr/bin/env bash
# obstacle_scenes.sh WPG: five walks of the obstacle-scenes study
# (studies/obstacle_scenes_small.yaml; the whole study: datasets/studies/obstacle_scenes.yaml,
# docs/obstacle_scenes.md) through `wpg batch` and analysis/plot_obstacle_scenes.py: the wall and
# the U have no passage and block the robot, the wide doorway, the circle met while turning and
# the one beside the diagonal command have one and are passed: every walk correct. The table
# names each scene with its passage and shortest free path, and counts them per kind.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
cd "$WORKDIR"
# The wall and the U end blocked, a walk that failed: the batch exits 1, and says so.
status=0
"$wpg" batch "$HERE/studies/obstacle_scenes_small.yaml" -o small.h5 -j 2 --no-plot >/dev/null \
  2>batch.err || status=$?
[[ $status == 1 ]] || fail "batch: exit $status, expected 1 (two walks blocked)"
grep -q "2 of 5 runs failed" batch.err || fail "batch: $(cat batch.err)"
"$PYTHON" "$WPG_DATA_DIR/analysis/plot_obstacle_scenes.py" small.h5 -o small.png \
  --table small.md >out.txt || fail "plot_obstacle_scenes.py: exit $?"
cat out.txt
check_png small.png
grep -q "^5 walks: 3 passed, 2 blocked; 5 of 5 correct$" out.txt || fail "not every walk correct"
grep -q "^| closed_wall_d1.5_y0.0_v0.3 | \[0.3, 0, 0\] | 1 | no | - |" small.md ||
  fail "the wall has a passage"
grep -q "^| gap_w1.6_c0.0_v0.3 | \[0.3, 0, 0\] | 2 | yes | 3.44 |" small.md ||
  fail "the doorway's shortest free path is not 3.44 m"
grep -q "^| closed | 2 | 0 | 0 | 0 | 2 | 0 | 2 |$" small.md || fail "the summary's closed row"
echo "ok"
