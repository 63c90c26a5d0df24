#!/usr/bin/env bash
# run_scenario.sh WPG SCENARIO.yaml: `wpg run SCENARIO -o <tmp>/run.h5` exits 0, prints its
# summary, writes a dataset with the schema's datasets and the figure next to it.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; scenario="$2"
make_workdir
# In the sanitizer tree (WPG_SANITIZED), the walk only: the figure and the dataset's check are
# Python, which the sanitizers do not instrument, and the Release tree draws and checks them
# for every scenario: about 2 s of CPU a scenario (the figure 1.7 s, the check 0.4 s).
sanitized="${WPG_SANITIZED:-0}"
options=() words=(walked status solve dataset figure) files="run.h5 run.png stderr stdout "
if [[ $sanitized == 1 ]]; then
  options=(--no-plot) words=(walked status solve dataset) files="run.h5 stderr stdout "
fi
status=0
"$wpg" run "$scenario" "${options[@]}" -o "$WORKDIR/run.h5" >"$WORKDIR/stdout" \
  2>"$WORKDIR/stderr" || status=$?
cat "$WORKDIR/stdout"; cat "$WORKDIR/stderr" >&2
[[ $status == 0 ]] || fail "exit status $status"
[[ ! -s "$WORKDIR/stderr" ]] || fail "unexpected output on stderr"
for word in "${words[@]}"; do
  grep -q "^$word " "$WORKDIR/stdout" || fail "summary lacks the '$word' line"
done
if [[ $sanitized != 1 ]]; then
  check_run_file "$WORKDIR/run.h5"
  check_png "$WORKDIR/run.png"
fi
[[ "$(ls -A "$WORKDIR" | sort | tr '\n' ' ')" == "$files" ]] \
  || fail "unexpected files: $(ls -A "$WORKDIR")"
echo "ok"
