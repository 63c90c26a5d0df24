#!/usr/bin/env bash
# plot.sh WPG: `wpg plot` draws a PNG from a run file (default name and -o), and exits 2 with
# one line on stderr for a missing file and for a file that is not HDF5.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
"$wpg" run walk_forward --set duration=4 --no-plot -o "$WORKDIR/walk.h5" >/dev/null || fail "run: exit status $?"
"$wpg" plot "$WORKDIR/walk.h5" || fail "plot: exit status $?"
check_png "$WORKDIR/walk.png"
"$wpg" plot "$WORKDIR/walk.h5" -o "$WORKDIR/figures/other.png" || fail "plot -o: exit status $?"
check_png "$WORKDIR/figures/other.png"
[[ "$(ls -A "$WORKDIR/figures")" == other.png ]] || fail "temporary files left: $(ls -A "$WORKDIR/figures")"

expect_bad() {  # expect_bad NAME ARGS...: exit 2, one line on stderr naming NAME, no figure
  local name="$1" status=0; shift
  "$wpg" plot "$@" 2>"$WORKDIR/stderr" || status=$?
  echo "stderr: $(cat "$WORKDIR/stderr")"
  [[ $status == 2 ]] || fail "plot $*: exit status $status, expected 2"
  [[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "plot $*: not one line on stderr"
  grep -qF "$name" "$WORKDIR/stderr" || fail "plot $*: stderr does not name $name"
}
expect_bad missing.h5 "$WORKDIR/missing.h5"
[[ ! -e "$WORKDIR/missing.png" ]] || fail "figure drawn for a missing file"
echo "not an HDF5 file" >"$WORKDIR/text.h5"
expect_bad text.h5 "$WORKDIR/text.h5"
[[ ! -e "$WORKDIR/text.png" ]] || fail "figure drawn for a bad file"
echo "ok"
