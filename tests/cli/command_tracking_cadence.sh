#!/usr/bin/env bash
# command_tracking_cadence.sh WPG: a command beyond the reach of the paper's 0.8 s steps is
# tracked with the adaptive step timing (walking.step_timing, docs/command_tracking.md "Step
# timing"). `walk_sideways` at 0.15 m/s for 30 s (0.8 s steps reach at most 0.125 m/s
# sideways): by default steady_tracking <= 1 (every component within 10 %), walked with steps
# shorter than 0.8 s, recorded as such (footstep_lift_off: single supports below 0.7 s), and
# `wpg analyze` agrees with check_metrics.py; with `step_timing: fixed` (the paper's timing) it
# is not tracked and every step lasts 0.8 s. The shipped walk_sideways (0.1 m/s, within the
# reach) keeps 0.8 s steps.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
cd "$WORKDIR"
fast=(--set duration=30 --set 'reference[1].v[1]=0.15')
"$wpg" run walk_sideways "${fast[@]}" --no-plot -o adaptive.h5 >/dev/null || fail "run: exit $?"
"$wpg" run walk_sideways "${fast[@]}" --set walking.step_timing=fixed --no-plot -o fixed.h5 \
  >/dev/null || fail "run (fixed timing): exit $?"
"$wpg" run walk_sideways --no-plot -o shipped.h5 >/dev/null || fail "run (shipped): exit $?"
for file in adaptive.h5 fixed.h5; do
  "$wpg" analyze "$file" --format json >"$file.json" || fail "analyze $file: exit $?"
  oracle check_metrics.py "$file" "$file.json" || fail "metrics of $file disagree"
done
"$PYTHON" - adaptive.h5.json fixed.h5.json adaptive.h5 fixed.h5 shipped.h5 <<'PY' || fail "the command beyond the 0.8 s reach is not tracked"
import json, sys
import h5py
import numpy as np
run = json.load(open(sys.argv[1]))["walk_sideways"]
fixed = json.load(open(sys.argv[2]))["walk_sideways"]
print("steady vy %.4f m/s, score %.2f (fixed timing: %.4f m/s, score %.2f)"
      % (run["steady_vy"], run["steady_tracking"], fixed["steady_vy"], fixed["steady_tracking"]))
assert run["steady_tracking"] <= 1.0 and run["steady_vy"] >= 0.135, run
assert fixed["steady_tracking"] > 1.0 and fixed["steady_vy"] <= 0.126, fixed


def timing(path):
    with h5py.File(path, "r") as f:
        steps = f["runs/walk_sideways/footsteps"][2:, 0]
        lift_off = f["runs/walk_sideways/footstep_lift_off"][2:]
    return np.diff(steps), steps - lift_off


for path, shortest in ((sys.argv[3], None), (sys.argv[4], 0.8), (sys.argv[5], 0.8)):
    period, single = timing(path)
    print("%s: steps %.2f to %.2f s, single support %.2f to %.2f s"
          % (path, period.min(), period.max(), single.min(), single.max()))
    if shortest is None:
        assert period[-10:].max() < 0.8 - 1e-6 and single[-10:].max() < 0.7 - 1e-6, period
    else:
        assert abs(period.min() - shortest) < 1e-6 and abs(single.min() - 0.7) < 1e-6, period
PY
echo "ok"
