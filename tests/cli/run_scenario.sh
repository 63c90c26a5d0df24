#!/usr/bin/env bash
# run_scenario.sh WPG SCENARIO.yaml: `wpg run SCENARIO -o <tmp>/run.h5` exits 0, prints its
# summary, writes a dataset with the schema's datasets and the figure next to it.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; scenario="$2"
make_workdir
status=0
"$wpg" run "$scenario" -o "$WORKDIR/run.h5" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
cat "$WORKDIR/stdout"; cat "$WORKDIR/stderr" >&2
[[ $status == 0 ]] || fail "exit status $status"
[[ ! -s "$WORKDIR/stderr" ]] || fail "unexpected output on stderr"
for word in walked status solve dataset figure; do
  grep -q "^$word " "$WORKDIR/stdout" || fail "summary lacks the '$word' line"
done
check_run_file "$WORKDIR/run.h5"
check_png "$WORKDIR/run.png"
[[ "$(ls -A "$WORKDIR" | sort | tr '\n' ' ')" == "run.h5 run.png stderr stdout " ]] \
  || fail "unexpected files: $(ls -A "$WORKDIR")"
echo "ok"
