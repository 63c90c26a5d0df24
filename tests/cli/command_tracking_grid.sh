#!/usr/bin/env bash
# command_tracking_grid.sh WPG: seven cells of the command-tracking study
# (studies/command_tracking_small.yaml; the whole grid: datasets/studies/command_tracking.yaml,
# docs/command_tracking.md). `wpg batch` stores the steady_* metrics in /batch/summary; every
# cell is tracked (steady_tracking <= 1: each component within 10 % of the command, 0.01 of a
# zero one), the cell beyond the lateral reach of HRP-2's 0.8 s steps (0.125 m/s) too, with the
# adaptive step timing's shorter steps, and analysis/plot_command_tracking.py draws the figure
# and the table from the file, counts no missed cell, shows the shorter steps of that cell
# (and refuses a file that is not a batch file).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
cd "$WORKDIR"
"$wpg" batch "$HERE/studies/command_tracking_small.yaml" -o small.h5 -j 2 --no-plot >/dev/null ||
  fail "batch: exit $?"
"$PYTHON" - small.h5 <<'PY' || fail "a command is not tracked"
import sys
import h5py
import numpy as np
import yaml
with h5py.File(sys.argv[1], "r") as f:
    table = f["batch/summary"]
    names = [n.decode() if isinstance(n, bytes) else n for n in table["name"][()]]
    for i, name in enumerate(names):
        command = yaml.safe_load(f["runs"][name].attrs["scenario"])["reference"][1]["v"]
        v = [float(table[k][i]) for k in ("steady_vx", "steady_vy", "steady_omega")]
        score = float(table["steady_tracking"][i])
        print("command %s: steady %s, score %.2f" % (command, np.round(v, 3), score))
        assert int(table["exit_status"][i]) == 0, name
        assert score <= 1.0, (command, v, score)
PY
"$PYTHON" "$WPG_DATA_DIR/analysis/plot_command_tracking.py" small.h5 -o small.png --table small.md \
  >out.txt || fail "plot_command_tracking.py: exit $?"
cat out.txt
check_png small.png
grep -q "^7 cells, 7 tracked, 0 missed" out.txt || fail "plot_command_tracking.py's count"
grep -q "| 0 | 0.15 | 0 | .* | 0.83 / 0.83 | 0.60 | tracked |" small.md ||
  fail "the table lacks the cell beyond the 0.8 s reach, walked with 0.6 s steps"
grep -q "| 0.3 | 0 | 0 | .* | 0.80 | tracked |" small.md ||
  fail "the table lacks a cell walked with the paper's 0.8 s steps"
# A run file is not a batch file: one line naming it, exit 2.
"$wpg" run walk_forward --set duration=2 --no-plot -o run.h5 >/dev/null || fail "run: exit $?"
status=0
"$PYTHON" "$WPG_DATA_DIR/analysis/plot_command_tracking.py" run.h5 -o bad.png 2>stderr || status=$?
[[ $status == 2 && "$(wc -l <stderr)" == 1 ]] && grep -q "run.h5: /batch" stderr ||
  fail "a run file: exit $status, $(cat stderr)"
[[ ! -e bad.png ]] || fail "a figure was written for a bad file"
echo "ok"
