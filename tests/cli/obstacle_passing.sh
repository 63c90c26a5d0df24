#!/usr/bin/env bash
# obstacle_passing.sh WPG: four cells of the obstacle-passing study
# (studies/obstacle_passing_small.yaml; the whole sweep: datasets/studies/obstacle_passing.yaml,
# docs/obstacle_passing.md) through `wpg batch` and analysis/plot_obstacle_passing.py: with the
# defaults every one is passed (past the margin circle within 10 s of reaching it, 20 s at
# 0.1 m/s, at >= 0.1 m/s, no step centre inside the margin, walking on along the command); with
# the paper's linearization at the step (and its J1) the obstacle dead ahead blocks the robot.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
cd "$WORKDIR"
"$wpg" batch "$HERE/studies/obstacle_passing_small.yaml" -o small.h5 -j 2 --no-plot >/dev/null ||
  fail "batch: exit $?"
"$PYTHON" "$WPG_DATA_DIR/analysis/plot_obstacle_passing.py" small.h5 -o small.png \
  --table small.md >out.txt || fail "plot_obstacle_passing.py: exit $?"
cat out.txt
check_png small.png
grep -q "^4 walks: 4 passed$" out.txt || fail "not every obstacle passed"
sed 's|^  generator: {algorithm: nmpc, sqp_iterations: 1}|&\n  walking: {obstacle_linearization: step, velocity_tracking: instantaneous}|' \
  "$HERE/studies/obstacle_passing_small.yaml" >paper.yaml
"$wpg" batch paper.yaml -o paper.h5 -j 2 --no-plot >/dev/null || true
"$PYTHON" "$WPG_DATA_DIR/analysis/plot_obstacle_passing.py" paper.h5 -o paper.png \
  --table paper.md >out.txt || fail "plot_obstacle_passing.py (paper): exit $?"
cat out.txt
grep -q "| 0.2 | 0.25 | 0.25 | 1.5 | 0 | blocked |" paper.md || fail "the paper's keys passed dead ahead"
echo "ok"
