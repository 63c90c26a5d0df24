#!/usr/bin/env bash
# replay_failure.sh WPG: with the filter offline and online, a walk the multibody replay cannot follow (a CoM height of 1e-300 m:
# the filter's LIPM and the multibody ZMP overflow) fails the run (exit 1) and the dataset is
# still written, with success = 0, a message naming the replay, no multibody fields and no
# non-finite number anywhere (before, exit 0 with NaN in
# zmp_multibody_filtered).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
for mode in offline online; do
rm -f "$WORKDIR/run.h5"
status=0
"$wpg" run walk_forward --filter --no-plot --set duration=2 --set walking.com_height=1e-300 \
  --set filter_settings.mode=$mode \
  -o "$WORKDIR/run.h5" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
echo "$mode: stderr: $(cat "$WORKDIR/stderr")"
[[ $status == 1 ]] || fail "$mode: exit status $status, expected 1"
[[ -s "$WORKDIR/run.h5" ]] || fail "no dataset written"
"$PYTHON" - "$WORKDIR/run.h5" <<'PY' || fail "bad dataset"
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    run = f["runs/walk_forward"]
    assert run.attrs["success"] == 0, "success is not 0"
    message = run.attrs["message"]
    message = message.decode() if isinstance(message, bytes) else str(message)
    assert "cannot replay the walk" in message, message
    assert "q" not in run and "zmp_multibody" not in run, "multibody fields written"
    bad = []
    def visit(name, item):
        if isinstance(item, h5py.Dataset) and item.dtype.kind == "f":
            if not np.all(np.isfinite(item[()])):
                bad.append(name)
    f.visititems(visit)
    assert not bad, f"non-finite numbers in {bad}"
PY
done
echo "ok"
