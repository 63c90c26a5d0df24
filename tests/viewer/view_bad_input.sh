#!/usr/bin/env bash
# view_bad_input.sh WPG: `wpg view` on bad input exits 2 with one line naming what is wrong and
# writes nothing: a missing file, a folder without study.h5, a file that is not HDF5, a run
# that is not in the file, an output over the input, and a build without the viewer bundle
# (WPG_VIEWER_DIR pointing at an empty folder: the message says how to build it).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
"$wpg" run walk_forward --no-plot --set duration=2 -o "$WORKDIR/walk.h5" >/dev/null || fail "run: exit status $?"
mkdir "$WORKDIR/empty" "$WORKDIR/no_bundle"
echo "not HDF5" >"$WORKDIR/text.h5"

expect_bad() {  # expect_bad WHAT EXPECTED_TEXT ARGS...: exit 2, one line with the text, no page
  local what="$1" expected="$2"
  shift 2
  local status=0
  "$wpg" view "$@" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
  [[ $status == 2 ]] || fail "$what: exit status $status, expected 2 ($(cat "$WORKDIR/stderr"))"
  [[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "$what: not one line on stderr: $(cat "$WORKDIR/stderr")"
  grep -qF -- "$expected" "$WORKDIR/stderr" || fail "$what: stderr does not say '$expected': $(cat "$WORKDIR/stderr")"
  [[ -z "$(find "$WORKDIR" -name '*.html')" ]] || fail "$what: a page was written: $(find "$WORKDIR" -name '*.html')"
  echo "$what: $(cat "$WORKDIR/stderr")"
}
expect_bad "missing file" "no such file" "$WORKDIR/missing.h5"
expect_bad "folder without study.h5" "without study.h5" "$WORKDIR/empty"
expect_bad "not HDF5" "not an HDF5 file" "$WORKDIR/text.h5"
# A tree built without the bundle (the sanitizer tree) says so before it looks for the run.
"$wpg" view "$WORKDIR/walk.h5" -o "$WORKDIR/probe/page.html" >/dev/null 2>"$WORKDIR/probe.err" || true
if grep -q "the viewer is not built" "$WORKDIR/probe.err"; then
  echo "unknown run: not checked, this tree has no viewer bundle"
  rm -rf "$WORKDIR/probe" "$WORKDIR/probe.err"
else
  rm -rf "$WORKDIR/probe" "$WORKDIR/probe.err"
  expect_bad "unknown run" "no run /runs/nobody" "$WORKDIR/walk.h5" --run nobody
fi
expect_bad "output over the input" "an input of the command" "$WORKDIR/walk.h5" -o "$WORKDIR/walk.h5"
WPG_VIEWER_DIR="$WORKDIR/no_bundle" expect_bad "no bundle" "the viewer is not built" "$WORKDIR/walk.h5"
grep -qF "cmake --build" "$WORKDIR/stderr" || fail "no bundle: the message does not say how to build it"
