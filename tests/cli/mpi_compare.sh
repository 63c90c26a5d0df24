#!/usr/bin/env bash
# mpi_compare.sh WPG MPIRUN STUDY: `wpg compare` under MPI (added when WPG_WITH_MPI):
# `mpirun --oversubscribe -np 3` gives the same study.h5 as `wpg compare -j 1` (runs and the
# /compare/summary table, wall times aside), the same summary.csv but its wall-time columns, and
# a table that agrees with its runs (check_compare_table.py); --resume under MPI of the complete
# study runs nothing and gives the same study.h5 again (its table written anew from the runs).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; mpirun="$2"; study="$3"
make_workdir
cd "$WORKDIR"

"$wpg" compare "$study" -o one -j 1 --no-plot >/dev/null 2>&1 || fail "compare -j 1: exit $?"
"$mpirun" --oversubscribe -np 3 "$wpg" compare "$study" -o mpi --no-plot >stdout 2>stderr ||
  fail "mpirun -np 3 compare: exit $? ($(cat stderr))"
[[ -d mpi/study.shards ]] || fail "no shard folder"
oracle compare_batch_files.py one/study.h5 mpi/study.h5 || fail "MPI compare differs from -j 1"
oracle check_compare_table.py mpi/study.h5 mpi/summary.csv || fail "the table disagrees with the runs"
# summary.csv: the same but the wall-time columns (planning and NMPC times).
keep() {
  "$PYTHON" -c "
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
keep = [i for i, name in enumerate(rows[0]) if 'time' not in name or 'time_to_goal' in name]
for row in rows: print(','.join(row[i] for i in keep))" "$1"
}
diff <(keep one/summary.csv) <(keep mpi/summary.csv) || fail "summary.csv differs"
"$mpirun" --oversubscribe -np 2 "$wpg" compare "$study" -o mpi --resume --no-plot >stdout 2>stderr ||
  fail "mpirun -np 2 compare --resume: exit $? ($(cat stderr))"
total="$("$PYTHON" -c "import h5py,sys; print(h5py.File(sys.argv[1])['batch/summary/done'].size)" one/study.h5)"
grep -q "resuming, $total of $total" stderr || fail "--resume of a complete MPI study: $(cat stderr)"
oracle compare_batch_files.py one/study.h5 mpi/study.h5 || fail "MPI --resume changed the study"
echo "ok"
