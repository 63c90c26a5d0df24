#!/usr/bin/env bash
# plot_many_runs.sh WPG: `wpg plot` of a file holding more runs than one figure draws (51 > 50)
# refuses to draw them all, says how to draw one (`--run NAME`), and `--run NAME` then draws
# that run (default name FILE.NAME.png); an unknown run is exit 2 naming it.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
"$wpg" run walk_forward --set duration=2 --no-plot -o "$WORKDIR/walk.h5" >/dev/null || fail "run: exit status $?"
# 51 runs: hard links to the one run group (each a run of the schema; the figure needs 51 rows).
"$PYTHON" - "$WORKDIR/walk.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    runs = f["runs"]
    for i in range(50):
        runs["copy_%02d" % i] = runs["walk_forward"]
    assert len(runs) == 51
PY
status=0
"$wpg" plot "$WORKDIR/walk.h5" -o "$WORKDIR/all.png" 2>"$WORKDIR/stderr" || status=$?
echo "all runs: $(cat "$WORKDIR/stderr")"
[[ $status == 2 ]] || fail "plot of 51 runs: exit status $status, expected 2"
grep -qF -- "--run NAME" "$WORKDIR/stderr" || fail "plot of 51 runs: the message does not say --run NAME"
[[ ! -e "$WORKDIR/all.png" ]] || fail "plot of 51 runs: a figure was written"

"$wpg" plot "$WORKDIR/walk.h5" --run copy_07 >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" \
  || fail "plot --run copy_07: exit status $? ($(cat "$WORKDIR/stderr"))"
check_png "$WORKDIR/walk.copy_07.png"
"$wpg" plot "$WORKDIR/walk.h5" --run copy_08 -o "$WORKDIR/one.png" >/dev/null || fail "plot --run -o: exit status $?"
check_png "$WORKDIR/one.png"

status=0
"$wpg" plot "$WORKDIR/walk.h5" --run nobody -o "$WORKDIR/none.png" 2>"$WORKDIR/stderr" || status=$?
[[ $status == 2 ]] || fail "plot --run nobody: exit status $status, expected 2"
grep -qF "nobody" "$WORKDIR/stderr" || fail "plot --run nobody: stderr does not name the run: $(cat "$WORKDIR/stderr")"
[[ ! -e "$WORKDIR/none.png" ]] || fail "plot --run nobody: a figure was written"
echo ok
