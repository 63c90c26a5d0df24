#!/usr/bin/env bash
# bench.sh WPG: `wpg bench walk_forward --json FILE` prints the paper's Sec. V-C table (average,
# standard deviation, minimum, maximum of one 5 ms control tick that contains an NMPC
# iteration, the paper's numbers beside, the stages, every tick, real-time factor, this
# machine's CPU and OS) and writes the same numbers as JSON; an unknown scenario exits 2.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
"$wpg" bench walk_forward --json "$WORKDIR/bench.json" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" \
  || fail "exit status $?"
cat "$WORKDIR/stdout"
[[ ! -s "$WORKDIR/stderr" ]] || fail "unexpected stderr: $(cat "$WORKDIR/stderr")"
grep -q 'walk_forward' "$WORKDIR/stdout" || fail "no column for walk_forward"
grep -Eq '^Average .* 3\.950 +4\.000$' "$WORKDIR/stdout" || fail "no paper numbers beside the average"
grep -q '^machine   this run: ' "$WORKDIR/stdout" || fail "no line about this machine"
grep -q 'Core2 Duo E7500' "$WORKDIR/stdout" || fail "no line about the paper's machine"
for row in Average 'Standard deviation' Minimum Maximum '  WPG' '  IK' '  multibody ZMP' \
           '  filter' 'Loop real-time factor'; do
  grep -Eq "^${row}.* [0-9]+\.?[0-9]*x?\$" "$WORKDIR/stdout" || fail "no row '$row' with a number"
done
"$PYTHON" - "$WORKDIR/bench.json" <<'PY' || fail "bad JSON"
import json, sys
data = json.load(open(sys.argv[1]))
[row] = data["scenarios"]
assert row["name"] == "walk_forward", row
tick = row["nmpc_tick_time"]
assert 0 < tick["min"] <= tick["average"] <= tick["max"], tick
assert tick["std"] >= 0, tick
assert tick["count"] == 100, tick
every = row["tick_time"]
assert every["count"] == 2000, every
assert every["average"] < tick["average"], (every, tick)  # the NMPC ticks are the heavy ones
assert set(row["nmpc_tick_stage_mean"]) == {"wpg", "ik", "multibody_zmp", "filter"}, row
# Faster than real time, but under the sanitizers (WPG_SANITIZED, tests/cli/CMakeLists.txt).
import os
assert row["real_time_factor"] > 1 or os.environ.get("WPG_SANITIZED") == "1", row
assert [p["name"] for p in data["paper"]] == ["paper A", "paper B"], data["paper"]
assert data["cpu"] and data["os"], data
assert row["zmp_error"]["rms_after"] * 3 < row["zmp_error"]["rms_before"], row
PY
status=0
"$wpg" bench no_such_scenario 2>"$WORKDIR/stderr" >/dev/null || status=$?
[[ $status == 2 ]] || fail "unknown scenario: exit status $status, expected 2"
[[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "unknown scenario: not one line on stderr"
echo "ok"
