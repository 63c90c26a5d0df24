#!/usr/bin/env bash
# robot_folder.sh WPG: a robot folder of one's own, made as docs/robots.md says ("Add your
# robot"): HRP-2's model under other names (URDF file, sole links, standing posture) in a data
# directory of its own. `wpg robot check` passes, and walk_forward walks, replays and filters
# on it with exactly HRP-2's configurations and multibody ZMP: the walking file's `multibody:`
# names are all the replay needs.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
data="$WORKDIR/data"
mkdir -p "$data/robots/mybot" "$data/datasets"
cp -r "$WPG_DATA_DIR/datasets/scenarios" "$data/datasets/"
cp -r "$WPG_DATA_DIR/analysis" "$data/"
hrp2="$WPG_DATA_DIR/robots/hrp2"
sed -e 's/LLEG_SOLE/left_sole/g' -e 's/RLEG_SOLE/right_sole/g' "$hrp2/hrp2.urdf" \
  >"$data/robots/mybot/mybot_model.urdf"
sed -e 's/half_sitting/ready/' "$hrp2/hrp2.srdf" >"$data/robots/mybot/mybot_model.srdf"
sed -e 's/urdf: hrp2.urdf/urdf: mybot_model.urdf/' -e 's/LLEG_SOLE/left_sole/' \
  -e 's/RLEG_SOLE/right_sole/' -e 's/standing_posture: half_sitting/standing_posture: ready/' \
  "$hrp2/walking.yaml" >"$data/robots/mybot/walking.yaml"
for name in mybot_model.urdf left_sole right_sole ready; do
  grep -q "$name" "$data/robots/mybot/walking.yaml" || fail "test bug: $name not in walking.yaml"
done

WPG_DATA_DIR="$data" "$wpg" robot check mybot >"$WORKDIR/check.txt" || fail "robot check: exit $?"
grep -qF "left_sole 6 joints, right_sole 6 joints" "$WORKDIR/check.txt" || fail "robot check: $(cat "$WORKDIR/check.txt")"

run() {  # run ROBOT OUT.h5: walk_forward, 4 s, replayed with the filter
  WPG_DATA_DIR="$data" "$wpg" run walk_forward --set "robot=$1" --set duration=4 --filter \
    --no-plot -o "$2" >/dev/null || fail "run on $1: exit status $?"
}
cp -r "$hrp2" "$data/robots/hrp2"
run mybot "$WORKDIR/mybot.h5"
run hrp2 "$WORKDIR/hrp2.h5"
"$PYTHON" - "$WORKDIR/mybot.h5" "$WORKDIR/hrp2.h5" <<'PY'
import sys
import h5py
import numpy as np
mine, theirs = (h5py.File(p, "r")["runs/walk_forward"] for p in sys.argv[1:])
for name in ("q", "com_filtered", "zmp_multibody", "zmp_multibody_filtered"):
    a, b = mine[name][()], theirs[name][()]
    assert a.shape == b.shape and a.shape[0] > 700, (name, a.shape, b.shape)
    assert np.array_equal(a, b), f"{name} differs by {np.abs(a - b).max()}"
print(f"q {mine['q'].shape}: identical to HRP-2's")
PY
echo "ok"
