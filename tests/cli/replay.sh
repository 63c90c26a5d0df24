#!/usr/bin/env bash
# replay.sh WPG: `wpg replay` adds the multibody fields to a dataset written by `wpg run`:
# with -o (new file and its figure), in place (--no-filter: replay only), atomically; a
# missing file or one that is not HDF5 exits 2 with one line on stderr.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
"$wpg" run walk_forward --set duration=4 --no-plot -o "$WORKDIR/run.h5" >/dev/null \
  || fail "run: exit status $?"
"$PYTHON" -c 'import sys, h5py; sys.exit("q" in h5py.File(sys.argv[1], "r")["runs/walk_forward"])' \
  "$WORKDIR/run.h5" || fail "a run without --replay has q"

# -o: a new dataset and its figure; the input is untouched.
before="$(md5sum <"$WORKDIR/run.h5")"
"$wpg" replay "$WORKDIR/run.h5" -o "$WORKDIR/replayed/filtered.h5" >"$WORKDIR/stdout" \
  || fail "replay -o: exit status $?"
cat "$WORKDIR/stdout"
grep -Eq '^multibody ZMP error  RMS .* -> ' "$WORKDIR/stdout" || fail "replay prints no ZMP error line"
[[ "$(md5sum <"$WORKDIR/run.h5")" == "$before" ]] || fail "replay -o changed its input"
check_run_file "$WORKDIR/replayed/filtered.h5"
check_multibody "$WORKDIR/replayed/filtered.h5" --filtered --min-reduction 3
check_png "$WORKDIR/replayed/filtered.png"

# In place, replay only.
"$wpg" replay "$WORKDIR/run.h5" --no-filter --no-plot >/dev/null || fail "replay in place: exit status $?"
check_run_file "$WORKDIR/run.h5"
check_multibody "$WORKDIR/run.h5" --not-filtered
[[ ! -e "$WORKDIR/run.png" ]] || fail "--no-plot drew a figure"
leftovers="$(find "$WORKDIR" -name '*.tmp-*')"
[[ -z "$leftovers" ]] || fail "temporary files left: $leftovers"

expect_bad() {  # expect_bad NAME FILE: exit 2, one line on stderr naming NAME, nothing written
  local name="$1" status=0
  "$wpg" replay "$2" -o "$WORKDIR/bad/out.h5" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
  echo "stderr: $(cat "$WORKDIR/stderr")"
  [[ $status == 2 ]] || fail "replay $2: exit status $status, expected 2"
  [[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "replay $2: not one line on stderr"
  grep -q '^wpg: error: ' "$WORKDIR/stderr" || fail "replay $2: stderr does not start with 'wpg: error: '"
  grep -qF "$name" "$WORKDIR/stderr" || fail "replay $2: stderr does not name $name"
  [[ ! -s "$WORKDIR/stdout" ]] || fail "replay $2: unexpected stdout"
  [[ ! -e "$WORKDIR/bad" ]] || fail "replay $2: something was written"
}
expect_bad missing.h5 "$WORKDIR/missing.h5"
echo "not an HDF5 file" >"$WORKDIR/text.h5"
expect_bad text.h5 "$WORKDIR/text.h5"
"$PYTHON" -c 'import sys, h5py; h5py.File(sys.argv[1], "w").attrs["x"] = 1' "$WORKDIR/other.h5"
expect_bad other.h5 "$WORKDIR/other.h5"
echo "ok"
