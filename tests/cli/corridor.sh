#!/usr/bin/env bash
# corridor.sh WPG: the shipped corridor scenario (walls y = +0.25 and -0.35 m, command
# [0.2, 0.05, 0] m/s for 20 s) exits 0 with every footstep centre and every CoP sample (the
# executed CoP at every 5 ms sample and every previewed one of mpc/plan) between the walls,
# and walks on along x; without the walls (--set of another scenario's command, no
# `constraints:`) the same command crosses y = 0.25.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
"$wpg" run corridor --no-plot -o "$WORKDIR/corridor.h5" >/dev/null || fail "corridor: exit $?"
"$PYTHON" - "$WORKDIR/corridor.h5" <<'PY' || fail "the corridor did not hold its walls"
import sys
import h5py
import numpy as np
left, right, tolerance = 0.25, -0.35, 1e-9
with h5py.File(sys.argv[1], "r") as f:
    run = f["runs/corridor"]
    feet = run["footsteps"][()]
    # every sample of the executed CoP, between the NMPC samples too (the family's cop_margin)
    cop = run["cop"][()]
    previewed = run["mpc/plan/cop"][()]
    status = run["mpc/status"][()]
    x_end = run["com"][-1, 0]
for name, y in (("footstep", feet[:, 2]), ("cop", cop[:, 1]), ("previewed cop", previewed[:, 1])):
    assert y.max() <= left + tolerance and y.min() >= right - tolerance, (name, y.min(), y.max())
assert len(feet) >= 20, len(feet)
assert x_end > 3.0, x_end
# the left wall is reached: the walls held the drift, they were not just far away
assert feet[:, 2].max() > left - 0.01, feet[:, 2].max()
print(f"steps {len(feet)}, x {x_end:.2f} m, feet y in [{feet[:, 2].min():.4f}, {feet[:, 2].max():.4f}],"
      f" cop y in [{cop[:, 1].min():.4f}, {cop[:, 1].max():.4f}]")
PY
# The same walk without the walls: a scenario of its own, the corridor's lines less the section.
grep -v -e '^constraints:' -e '^  corridor:' "$(dirname "$0")/../../datasets/scenarios/corridor.yaml" |
  sed 's/^name: corridor/name: open_floor/' >"$WORKDIR/open_floor.yaml"
"$wpg" run "$WORKDIR/open_floor.yaml" --no-plot -o "$WORKDIR/open.h5" >/dev/null
"$PYTHON" - "$WORKDIR/open.h5" <<'PY' || fail "without the walls the robot stays inside anyway"
import sys
import h5py
with h5py.File(sys.argv[1], "r") as f:
    y = f["runs/open_floor/footsteps"][:, 2]
assert y.max() > 0.25 + 0.1, y.max()
print(f"without walls: feet up to y = {y.max():.3f} m")
PY
echo "ok"
