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
  # A study whose last run the reader refuses (its com cut to 1 column): refused after the
  # first run's page data was spooled (study_dashboard.cpp), and still nothing written in the
  # page's folder, no run page, no temporary file.
  "$wpg" batch "$HERE/studies/tiny_batch.yaml" -o "$WORKDIR/study/tiny.h5" --no-plot \
    >/dev/null 2>&1 || fail "batch: exit status $?"
  "$PYTHON" - "$WORKDIR/study/tiny.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    run = f["runs"][sorted(f["runs"])[-1]]
    com = run["com"][:, :1]
    del run["com"]
    run["com"] = com
PY
  ls -A "$WORKDIR/study" >"$WORKDIR/study.before"
  expect_bad "a study with a damaged run" "tiny_1/com" "$WORKDIR/study/tiny.h5"
  ls -A "$WORKDIR/study" | diff "$WORKDIR/study.before" - ||
    fail "a study with a damaged run: files left in its folder"
  # Route plans are bounded (datasets/SCHEMA.md, "Reading"): 2000 plans each naming all 1000
  # rows of routes (a 2 M-waypoint page from a small file), and 10001 plans.
  plans() {  # plans FILE PLANS ROUTE_ROWS SAME_ROWS: a plans/ group in the run of FILE
    "$PYTHON" - "$@" <<'PY'
import sys, h5py, numpy as np
path, p, r, same = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4] == "1"
with h5py.File(path, "r+") as f:
    g = f["runs"][list(f["runs"])[0]].create_group("plans")
    g["time"] = np.zeros(p); g["trigger"] = np.zeros(p, "i4"); g["status"] = np.zeros(p, "i4")
    g["routes"] = np.zeros((r, 3))
    g["route_start"] = np.zeros(p, "i4") if same else np.arange(p, dtype="i4") * (r // p)
    g["route_count"] = np.full(p, r if same else r // p, "i4")
PY
  }
  cp "$WORKDIR/walk.h5" "$WORKDIR/plans_same.h5" && plans "$WORKDIR/plans_same.h5" 2000 1000 1
  expect_bad "plans sharing their rows" "route_start row 1: expected 1000" "$WORKDIR/plans_same.h5"
  cp "$WORKDIR/walk.h5" "$WORKDIR/plans_many.h5" && plans "$WORKDIR/plans_many.h5" 10001 10001 0
  expect_bad "10001 plans" "plans/time declares 10001 rows: expected at most 10000" "$WORKDIR/plans_many.h5"
fi
expect_bad "output over the input" "an input of the command" "$WORKDIR/walk.h5" -o "$WORKDIR/walk.h5"
WPG_VIEWER_DIR="$WORKDIR/no_bundle" expect_bad "no bundle" "the viewer is not built" "$WORKDIR/walk.h5"
grep -qF "cmake --build" "$WORKDIR/stderr" || fail "no bundle: the message does not say how to build it"
