#!/usr/bin/env bash
# compare_ompl_log.sh WPG STUDY.yaml: `wpg compare --ompl-log DIR` writes one OMPL benchmark log
# per world that a reader written from OMPL's documented grammar parses, with every run of the
# study (check_ompl_log.py), and their Planner Arena database (check_ompl_database.py); an
# --ompl-log that is a file is refused before anything runs.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1" study="$2"
make_workdir
"$wpg" compare "$study" -o "$WORKDIR/out" -j 2 --no-plot --ompl-log "$WORKDIR/logs" >"$WORKDIR/stdout" \
  || fail "compare --ompl-log: exit status $?"
grep -q "OMPL logs" "$WORKDIR/stdout" || fail "compare does not name the logs: $(cat "$WORKDIR/stdout")"
oracle check_ompl_log.py "$WORKDIR/logs" "$WORKDIR/out/study.h5" || fail "the OMPL logs"
grep -q "database $WORKDIR/logs/benchmark.db" "$WORKDIR/stdout" || fail "compare does not name the database"
"$PYTHON" "$HERE/check_ompl_database.py" "$WORKDIR/logs" || fail "the Planner Arena database"

touch "$WORKDIR/a_file"
status=0
"$wpg" compare "$study" -o "$WORKDIR/out2" --no-plot --ompl-log "$WORKDIR/a_file" 2>"$WORKDIR/stderr" || status=$?
[[ $status == 2 ]] || fail "--ompl-log over a file: exit status $status, expected 2"
grep -q -- "--ompl-log" "$WORKDIR/stderr" || fail "--ompl-log over a file: $(cat "$WORKDIR/stderr")"
[[ ! -e "$WORKDIR/out2" ]] || fail "--ompl-log over a file: the study was run"

# A log folder that cannot be made (below a folder no one may write in; as root, below /proc,
# which makes none): refused before the study runs, nothing written.
if [[ $(id -u) == 0 ]]; then unmakeable=/proc/wpg_ompl_logs/logs; else
  mkdir "$WORKDIR/read_only" && chmod 555 "$WORKDIR/read_only"
  unmakeable="$WORKDIR/read_only/logs"
fi
status=0
"$wpg" compare "$study" -o "$WORKDIR/out3" --no-plot --ompl-log "$unmakeable" 2>"$WORKDIR/stderr" || status=$?
[[ $status == 2 ]] || fail "--ompl-log below a read-only folder: exit status $status, expected 2"
[[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] && grep -q -- "--ompl-log: cannot create '$unmakeable'" "$WORKDIR/stderr" ||
  fail "--ompl-log below a read-only folder: $(cat "$WORKDIR/stderr")"
[[ ! -e "$WORKDIR/out3" ]] || fail "--ompl-log below a read-only folder: the study was run"
