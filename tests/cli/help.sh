#!/usr/bin/env bash
# help.sh WPG: --help and every subcommand's --help exit 0 and show the defaults; --version.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
"$wpg" --help >"$WORKDIR/help" || fail "--help: exit status $?"
grep -q walk_forward "$WORKDIR/help" || fail "--help does not show the default scenario"
grep -q '\brun\b' "$WORKDIR/help" || fail "--help lacks the run subcommand"
grep -q '\bplot\b' "$WORKDIR/help" || fail "--help lacks the plot subcommand"
env -u WPG_DATA_DIR "$wpg" run --help >"$WORKDIR/run_help" || fail "run --help: exit status $?"
cat "$WORKDIR/run_help"
grep -q walk_forward "$WORKDIR/run_help" || fail "run --help does not show the default scenario"
grep -q 'out/<scenario name>.h5' "$WORKDIR/run_help" || fail "run --help does not show the default output"
grep -q -- '--filter' "$WORKDIR/run_help" || fail "run --help lacks --filter"
grep -q -- '--replay' "$WORKDIR/run_help" || fail "run --help lacks --replay"
grep -q '\breplay\b' "$WORKDIR/help" || fail "--help lacks the replay subcommand"
grep -q '\bbench\b' "$WORKDIR/help" || fail "--help lacks the bench subcommand"
"$wpg" replay --help >"$WORKDIR/replay_help" || fail "replay --help: exit status $?"
grep -q 'overwritten atomically' "$WORKDIR/replay_help" || fail "replay --help does not show the default output"
grep -q -- '--no-filter' "$WORKDIR/replay_help" || fail "replay --help lacks --no-filter"
"$wpg" bench --help >"$WORKDIR/bench_help" || fail "bench --help: exit status $?"
grep -q 'walk_forward paper_experiment_a paper_experiment_b' "$WORKDIR/bench_help" \
  || fail "bench --help does not show the default scenarios"
"$wpg" plot --help >"$WORKDIR/plot_help" || fail "plot --help: exit status $?"
grep -q 'RUN.png' "$WORKDIR/plot_help" || fail "plot --help does not show the default figure"
grep -q '\bbatch\b' "$WORKDIR/help" || fail "--help lacks the batch subcommand"
grep -q '\banalyze\b' "$WORKDIR/help" || fail "--help lacks the analyze subcommand"
"$wpg" batch --help >"$WORKDIR/batch_help" || fail "batch --help: exit status $?"
grep -q -- '--resume' "$WORKDIR/batch_help" || fail "batch --help lacks --resume"
grep -q 'the number of cores' "$WORKDIR/batch_help" || fail "batch --help does not show the default -j"
grep -q '\bcompare\b' "$WORKDIR/help" || fail "--help lacks the compare subcommand"
"$wpg" compare --help >"$WORKDIR/compare_help" || fail "compare --help: exit status $?"
grep -q 'the number of cores' "$WORKDIR/compare_help" || fail "compare --help does not show the default -j"
"$wpg" analyze --help >"$WORKDIR/analyze_help" || fail "analyze --help: exit status $?"
grep -q 'table, csv or json' "$WORKDIR/analyze_help" || fail "analyze --help lacks the formats"
"$wpg" --version | grep -Eq '^wpg [0-9]+\.[0-9]+\.[0-9]+' || fail "--version"
status=0; "$wpg" 2>/dev/null >/dev/null || status=$?
[[ $status == 2 ]] || fail "no subcommand: exit status $status, expected 2"
status=0; "$wpg" run --no-such-option 2>/dev/null >/dev/null || status=$?
[[ $status == 2 ]] || fail "unknown option: exit status $status, expected 2"
echo "ok"
