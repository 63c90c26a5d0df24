#!/usr/bin/env bash
# hostile_dataset.sh WPG CASE: a run file of `wpg run walk_forward` edited by edit_dataset.py
# CASE (NaN or non-monotonic time, NaN footstep, a stored scenario of another control period,
# 2e8 declared rows) is refused by `wpg replay` and `wpg analyze` (and `wpg diff` for huge_rows):
# exit 2 within the time bound, one line on stderr naming the file and the dataset, nothing
# written. Before, replay copied the NaN footstep to its output (exit 0),
# filtered the 10 ms scenario into NaN, and allocated gigabytes for the declared rows.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; case="$2"
make_workdir
"$wpg" run walk_forward --set duration=4 --no-plot -o "$WORKDIR/run.h5" >/dev/null \
  || fail "run: exit status $?"
"$PYTHON" "$HERE/edit_dataset.py" "$case" "$WORKDIR/run.h5" || fail "edit_dataset.py $case failed"
case "$case" in
  nan_time) name="/runs/walk_forward/time row 12" ;;
  time_backwards) name="/runs/walk_forward/time row 30" ;;
  nan_footstep) name="/runs/walk_forward/footsteps row 3" ;;
  other_period) name="/runs/walk_forward/time row 1" ;;
  huge_rows) name="/runs/walk_forward/com declares 200000000 rows" ;;
  *) fail "unknown case $case" ;;
esac

expect_bad() {  # expect_bad NAME COMMAND ARGS...: exit 2 within 30 s, one line naming NAME
  local name="$1" status=0; shift
  timeout 30 "$wpg" "$@" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
  echo "$1 stderr: $(cat "$WORKDIR/stderr")"
  [[ $status == 2 ]] || fail "$*: exit status $status, expected 2 (124: timed out)"
  [[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "$*: not one line on stderr"
  grep -q '^wpg: error: ' "$WORKDIR/stderr" || fail "$*: stderr does not start with 'wpg: error: '"
  grep -qF -- "run.h5" "$WORKDIR/stderr" || fail "$*: stderr does not name the file"
  grep -qF -- "$name" "$WORKDIR/stderr" || fail "$*: stderr does not name $name"
  [[ ! -s "$WORKDIR/stdout" ]] || fail "$*: unexpected stdout: $(cat "$WORKDIR/stdout")"
}
before="$(md5sum <"$WORKDIR/run.h5")"
expect_bad "$name" replay "$WORKDIR/run.h5" -o "$WORKDIR/out/replayed.h5"
[[ ! -e "$WORKDIR/out" ]] || fail "replay wrote something: $(ls -R "$WORKDIR/out")"
expect_bad "$name" replay "$WORKDIR/run.h5" --no-plot
[[ "$(md5sum <"$WORKDIR/run.h5")" == "$before" ]] || fail "replay in place changed the file"
expect_bad "$name" analyze "$WORKDIR/run.h5"
if [[ $case == huge_rows ]]; then
  "$wpg" run walk_forward --set duration=4 --no-plot -o "$WORKDIR/good.h5" >/dev/null
  expect_bad "dataset /runs/walk_forward/com declares 200000000 x 3 elements" \
    diff "$WORKDIR/good.h5" "$WORKDIR/run.h5"
fi
leftovers="$(find "$WORKDIR" -name '*.tmp*')"
[[ -z "$leftovers" ]] || fail "temporary files left: $leftovers"
echo "ok"
