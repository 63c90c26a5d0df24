#!/usr/bin/env bash
# run_scene_outcome.sh WPG SCENARIO EXPECTED: one shipped scene of the obstacle-scenes study
# (docs/obstacle_scenes.md) ends as expected with the defaults. `passed`: exit 0, not blocked,
# no NMPC iteration with a relaxed obstacle row, no step centre inside a margin, and at least
# 60 % of the commanded displacement walked along the command (progress_ratio). `blocked` (a
# scene with no passage): exit 1, the one line saying where and since when, `blocked` 1 in the
# dataset, and still no step centre inside a margin.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; scenario="$2"; expected="$3"
make_workdir
status=0
"$wpg" run "$scenario" --no-plot -o "$WORKDIR/run.h5" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" ||
  status=$?
cat "$WORKDIR/stdout"; cat "$WORKDIR/stderr" >&2
case "$expected" in
  passed) [[ $status == 0 ]] || fail "exit status $status, expected 0" ;;
  blocked)
    [[ $status == 1 ]] || fail "exit status $status, expected 1"
    grep -q "^wpg: error: the walk failed: the robot is blocked: .* since t = .* at (.*) m (dataset written)$" \
      "$WORKDIR/stderr" || fail "no blocked line" ;;
  *) fail "expected outcome '$expected': passed or blocked" ;;
esac
"$PYTHON" - "$WORKDIR/run.h5" "$expected" <<'PY' || fail "the dataset does not say $expected"
import sys
import h5py
with h5py.File(sys.argv[1], "r") as f:
    (name,) = f["runs"].keys()
    run = f["runs"][name]
    blocked = int(run.attrs["blocked"])
    assert blocked == (sys.argv[2] == "blocked"), blocked
    codes = dict(c.split("=") for c in run["mpc/status"].attrs["codes"].split(", "))
    relaxed = int([k for k, v in codes.items() if v == "relaxed_obstacle"][0])
    assert (run["mpc/status"][:] != relaxed).all(), "a relaxed obstacle row"
    clearance = float(run["checks"].attrs["min_step_centre_clearance"])
    assert clearance >= -1e-9, clearance
    if sys.argv[2] == "passed":
        assert float(run.attrs["progress_ratio"]) >= 0.6, run.attrs["progress_ratio"]
PY
echo "ok"
