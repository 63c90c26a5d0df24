#!/usr/bin/env bash
# bench.sh WPG: `wpg bench walk_forward --json FILE` prints the paper's Sec. V-C table (average,
# standard deviation, minimum, maximum of the control chain per NMPC iteration, stage medians,
# real-time factor) and writes the same numbers as JSON; an unknown scenario exits 2.
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
for row in Average 'Standard deviation' Minimum Maximum '  NMPC' '  IK' '  multibody ZMP' \
           '  filter' 'Replay \+ filter real-time factor'; do
  grep -Eq "^${row}.* [0-9]+\.?[0-9]*x?\$" "$WORKDIR/stdout" || fail "no row '$row' with a number"
done
"$PYTHON" - "$WORKDIR/bench.json" <<'PY' || fail "bad JSON"
import json, sys
data = json.load(open(sys.argv[1]))
[row] = data["scenarios"]
assert row["name"] == "walk_forward", row
chain = row["chain_time"]
assert 0 < chain["min"] <= chain["average"] <= chain["max"], chain
assert chain["std"] >= 0, chain
assert row["nmpc_iterations"] == 100, row
assert row["real_time_factor"] > 1, row
assert row["zmp_error"]["rms_after"] * 3 < row["zmp_error"]["rms_before"], row
PY
status=0
"$wpg" bench no_such_scenario 2>"$WORKDIR/stderr" >/dev/null || status=$?
[[ $status == 2 ]] || fail "unknown scenario: exit status $status, expected 2"
[[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "unknown scenario: not one line on stderr"
echo "ok"
