#!/usr/bin/env bash
# plot_many_runs.sh WPG: `wpg plot` of a batch holding more runs than one figure draws (51 > 50)
# refuses to draw them all, says how to draw one (`--run NAME`), and `--run NAME` then draws
# that run (default name FILE.NAME.png); an unknown run is exit 2 naming it.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
# A batch of 51 walks of 2 s (three durations x 17 random CoP weights).
cat >"$WORKDIR/many.yaml" <<'YAML'
name: many
base: walk_forward
sweep:
  grid:
    duration: [2.0, 2.1, 2.2]
  random:
    samples: 17
    seed: 5
    keys: {walking.weight_cop: {uniform: [500.0, 2000.0]}}
YAML
status=0
"$wpg" batch "$WORKDIR/many.yaml" -o "$WORKDIR/walk.h5" -j 2 --no-plot >/dev/null 2>&1 || status=$?
[[ $status == 0 ]] || fail "batch of 51 runs: exit status $status"
status=0
"$wpg" plot "$WORKDIR/walk.h5" -o "$WORKDIR/all.png" 2>"$WORKDIR/stderr" || status=$?
echo "all runs: $(cat "$WORKDIR/stderr")"
[[ $status == 2 ]] || fail "plot of 51 runs: exit status $status, expected 2"
grep -qF -- "--run NAME" "$WORKDIR/stderr" || fail "plot of 51 runs: the message does not say --run NAME"
[[ ! -e "$WORKDIR/all.png" ]] || fail "plot of 51 runs: a figure was written"

"$wpg" plot "$WORKDIR/walk.h5" --run many_07 >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" \
  || fail "plot --run many_07: exit status $? ($(cat "$WORKDIR/stderr"))"
check_png "$WORKDIR/walk.many_07.png"
"$wpg" plot "$WORKDIR/walk.h5" --run many_08 -o "$WORKDIR/one.png" >/dev/null || fail "plot --run -o: exit status $?"
check_png "$WORKDIR/one.png"

status=0
"$wpg" plot "$WORKDIR/walk.h5" --run nobody -o "$WORKDIR/none.png" 2>"$WORKDIR/stderr" || status=$?
[[ $status == 2 ]] || fail "plot --run nobody: exit status $status, expected 2"
grep -qF "nobody" "$WORKDIR/stderr" || fail "plot --run nobody: stderr does not name the run: $(cat "$WORKDIR/stderr")"
[[ ! -e "$WORKDIR/none.png" ]] || fail "plot --run nobody: a figure was written"
echo ok
