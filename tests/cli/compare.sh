#!/usr/bin/env bash
# compare.sh WPG STUDY: `wpg compare` on a tiny comparison study (2 worlds x 2 variants x 2
# seeds):
#  - -j 1 and -j 2 give the same study.h5 (every field but the wall times,
#    compare_batch_files.py), exit 0, with summary.csv/.md (one row per world x variant) and
#    the figures;
#  - the table agrees with the per-run rows (check_compare_table.py): success rate, time to
#    goal median and IQR, least clearance;
#  - a study run again into the same folder replaces its files.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; study="$2"
make_workdir
cd "$WORKDIR"

"$wpg" compare "$study" -o one -j 1 >stdout 2>stderr || fail "-j 1: exit $? ($(cat stderr))"
grep -q "8/8 runs" stderr || fail "no progress line: $(cat stderr)"
"$wpg" compare "$study" -o two -j 2 --no-plot >/dev/null 2>&1 || fail "-j 2: exit $?"
for file in study.h5 summary.csv summary.md; do
  [[ -s "one/$file" ]] || fail "one/$file missing"
done
for figure in success_rates time_to_goal top_field top_trap; do check_png "one/$figure.png"; done
[[ ! -e two/success_rates.png ]] || fail "--no-plot drew figures"
oracle compare_batch_files.py one/study.h5 two/study.h5 || fail "-j 1 and -j 2 differ"
[[ "$(($(wc -l <one/summary.csv) - 1))" == 4 ]] || fail "summary.csv has not 4 rows (2 worlds x 2 variants)"
oracle check_compare_table.py one/study.h5 one/summary.csv || fail "the table disagrees with the runs"
# The console never rounds a failure away: a run whose step centre entered a margin by
# 1.07e-5 m (its shard's summary edited, then merged, which prints the table as compare does)
# is printed below zero, as summary.csv has it, not as 0.000 m; a clearance within the
# tolerance of 1e-9 m (compare_small's trap x nmpc_only ends at -9e-16 m) is 0.000.
"$wpg" compare "$study" -o sharded --shard 0/1 --no-plot >/dev/null 2>&1 || fail "--shard 0/1: exit $?"
"$PYTHON" - sharded/study.shards/slice-0-of-1.h5 <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    table = f["batch/summary"]
    names = [n.decode() if isinstance(n, bytes) else n for n in table["name"][()]]
    column = table["step_centre_clearance_min"]
    column[names.index(next(n for n in names if n.startswith("field.nmpc_only")))] = -1.07e-5
PY
"$wpg" merge sharded/study.h5 sharded/study.shards/slice-0-of-1.h5 --no-plot >merged.out 2>&1 ||
  fail "merge: $(cat merged.out)"
"$PYTHON" - sharded/summary.csv merged.out <<'PY' || fail "the table rounds a failure away: $(cat merged.out)"
import csv, sys
rows = {(r["world"], r["variant"]): r for r in csv.DictReader(open(sys.argv[1]))}
printed = {tuple(t[:2]): t[t.index("m") - 1] for t in map(str.split, open(sys.argv[2]))
           if tuple(t[:2]) in rows}
assert float(rows["field", "nmpc_only"]["clearance_min"]) == -1.07e-5, rows["field", "nmpc_only"]
assert rows["field", "nmpc_only"]["margin_entered"] == "1", rows["field", "nmpc_only"]
assert printed["field", "nmpc_only"] == "-1.1e-05", printed
assert -1e-9 < float(rows["trap", "nmpc_only"]["clearance_min"]) < 0, rows["trap", "nmpc_only"]
assert printed["trap", "nmpc_only"] == "0.000", printed
PY
"$wpg" compare "$study" -o one -j 2 --no-plot >/dev/null 2>&1 || fail "again into one/: exit $?"
oracle compare_batch_files.py one/study.h5 two/study.h5 || fail "rerun differs"
echo "ok"
