#!/usr/bin/env bash
# help_exit_codes.sh WPG COMMANDS.md: every subcommand's --help lists the exit codes that
# subcommand returns (read from its code paths: `diff` returns 1 for "different", `analyze`,
# `plot`, `replay`, `compare`, `push-sweep` and `view` never return 1), and the table of
# docs/commands.md, "Exit codes", lists the same ones; and a few of them seen: run 1 and
# analyze 0 on a walk that falls, diff 1 and 0, plot and analyze 2 on a file that is not one.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
docs="$2"
make_workdir
# subcommand -> the codes its code paths return (1: a walk failed, or the files differ).
declare -A expected=(
  [run]="0 1 2 3" [replay]="0 2 3" [bench]="0 1 2 3" [batch]="0 1 2 3" [merge]="0 1 2 3"
  [compare]="0 2 3" [analyze]="0 2 3" [diff]="0 1 2 3" [push-sweep]="0 2 3" [plot]="0 2 3"
  [view]="0 2 3" [robot]="0 2 3")
# The codes of the "Exit codes: 0 ..., 1 ..." line of a help text (items "N meaning", separated
# by ", "; a meaning may hold commas in parentheses).
codes_of_help() {
  "$PYTHON" - "$1" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
lines = [l for l in text.splitlines() if l.startswith("Exit codes:")]
if len(lines) != 1:
    sys.exit(f"{len(lines)} 'Exit codes:' lines")
print(" ".join(sorted(set(re.findall(r"(?:: |, )(\d) ", lines[0])))))
PY
}
codes_of_docs() {
  "$PYTHON" - "$docs" "$1" <<'PY'
import re, sys
rows = [l for l in open(sys.argv[1]) if l.startswith(f"| `wpg {sys.argv[2]}` |")]
if len(rows) != 1:
    sys.exit(f"{len(rows)} rows for wpg {sys.argv[2]} in the exit code table")
print(" ".join(sorted(set(re.findall(r"\b(\d)\b", rows[0].split("|")[2])))))
PY
}
for sub in "${!expected[@]}"; do
  "$wpg" "$sub" --help >"$WORKDIR/help_$sub" || fail "$sub --help: exit status $?"
  listed="$(codes_of_help "$WORKDIR/help_$sub")" || fail "$sub --help: no single exit code line"
  [[ "$listed" == "${expected[$sub]}" ]] \
    || fail "$sub --help lists exit codes '$listed', expected '${expected[$sub]}': $(grep '^Exit codes' "$WORKDIR/help_$sub")"
  documented="$(codes_of_docs "$sub")" || fail "docs: no exit code row for $sub"
  [[ "$documented" == "${expected[$sub]}" ]] \
    || fail "docs/commands.md lists exit codes '$documented' for $sub, expected '${expected[$sub]}'"
done
# Every subcommand of `wpg --help` is checked above.
"$wpg" --help >"$WORKDIR/help"
for sub in $(sed -n '/^SUBCOMMANDS:/,$p' "$WORKDIR/help" | awk 'NR > 1 && NF {print $1}'); do
  [[ -n "${expected[$sub]+x}" ]] || fail "subcommand $sub has no expected exit codes in this test"
done
# And the codes are the commands' own: a walk that fails is exit 1 for `run` but a result for
# `analyze` (0); `diff` says 1 for "different"; `plot` of a file that is not a dataset is 2.
run_status() { local status=0; "$@" >/dev/null 2>&1 || status=$?; echo "$status"; }
[[ "$(run_status "$wpg" run walk_forward --no-plot --set duration=5 --set walking.com_height=81.4 \
  -o "$WORKDIR/fell.h5")" == 1 ]] || fail "run: a walk that falls is not exit 1"
[[ "$(run_status "$wpg" run walk_forward --no-plot --set duration=2 -o "$WORKDIR/ok.h5")" == 0 ]] \
  || fail "run: a walk that succeeds is not exit 0"
[[ "$(run_status "$wpg" analyze "$WORKDIR/fell.h5")" == 0 ]] || fail "analyze of a failed walk is not 0"
[[ "$(run_status "$wpg" diff "$WORKDIR/fell.h5" "$WORKDIR/ok.h5")" == 1 ]] || fail "diff of two walks is not 1"
[[ "$(run_status "$wpg" diff "$WORKDIR/ok.h5" "$WORKDIR/ok.h5")" == 0 ]] || fail "diff of a file with itself is not 0"
echo "not a dataset" >"$WORKDIR/text.h5"
[[ "$(run_status "$wpg" plot "$WORKDIR/text.h5")" == 2 ]] || fail "plot of a text file is not 2"
[[ "$(run_status "$wpg" analyze "$WORKDIR/text.h5")" == 2 ]] || fail "analyze of a text file is not 2"
echo "ok"
