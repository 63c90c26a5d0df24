#!/usr/bin/env bash
# talos_model.sh WPG: robots/talos/talos.urdf and .srdf are what make_urdf.py writes (run on a
# copy: byte for byte), and what `wpg robot check talos` derives from them agrees with an
# independent forward kinematics of the URDF (check_talos_model.py: numpy, its own parser):
# the links' mass, the straight leg, and the half-sitting CoM height above the soles.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
talos="$WPG_DATA_DIR/robots/talos"
cp "$talos/make_urdf.py" "$WORKDIR/"
"$PYTHON" "$WORKDIR/make_urdf.py" >/dev/null || fail "make_urdf.py: exit $?"
for file in talos.urdf talos.srdf; do
  cmp "$WORKDIR/$file" "$talos/$file" || fail "$file is not what make_urdf.py writes"
done
"$wpg" robot check talos >"$WORKDIR/check.txt" || fail "robot check: exit $?"
"$PYTHON" "$HERE/check_talos_model.py" "$talos/talos.urdf" "$talos/talos.srdf" \
  "$WORKDIR/check.txt" || fail "wpg robot check disagrees with the independent model"
echo "ok"
