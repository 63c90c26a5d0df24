#!/usr/bin/env bash
# analyze.sh WPG: `wpg analyze` of run files (obstacles; multibody replay with the filter)
# agrees with check_metrics.py's recomputation from the raw fields; table and csv formats
# list every metric; a non-HDF5 file and an unknown format exit 2 with one line.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
cd "$WORKDIR"
"$wpg" run obstacle_cluttered --no-plot -o obstacles.h5 >/dev/null || fail "run obstacle_cluttered: exit $?"
"$wpg" run walk_forward --filter --set duration=4 --no-plot -o filtered.h5 >/dev/null ||
  fail "run --filter: exit $?"
for file in obstacles.h5 filtered.h5; do
  "$wpg" analyze "$file" --format json >"$file.json" || fail "analyze $file: exit $?"
  oracle check_metrics.py "$file" "$file.json" || fail "metrics of $file disagree"
done
grep -q '"obstacle_clearance_min": -\?[0-9]' obstacles.h5.json || fail "no obstacle clearance"
grep -q '"zmp_error_rms_after": [0-9]' filtered.h5.json || fail "no ZMP error after the filter"
"$wpg" analyze filtered.h5 >table.txt || fail "analyze (table): exit $?"
for metric in velocity_error_rms cop_margin_min nmpc_time_p99 zmp_error_max_before; do
  grep -q "^  $metric " table.txt || fail "table lacks $metric"
done
# A run replayed but never filtered has no ZMP error after the filter: absent, not "before".
"$wpg" run walk_forward --set replay=true --set duration=4 --no-plot -o replayed.h5 >/dev/null ||
  fail "run replay=true: exit $?"
"$wpg" analyze replayed.h5 --format json >replayed.json || fail "analyze replayed.h5: exit $?"
grep -q '"zmp_error_rms_before": [0-9]' replayed.json || fail "no ZMP error before: $(cat replayed.json)"
grep -q '"zmp_error_rms_after": null' replayed.json || fail "an unfiltered run has a ZMP error after"
echo "not hdf5" >bad.h5
status=0; "$wpg" analyze bad.h5 2>stderr || status=$?
[[ $status == 2 && "$(wc -l <stderr)" == 1 ]] || fail "non-HDF5 file: exit $status, $(cat stderr)"
status=0; "$wpg" analyze filtered.h5 --format xml 2>stderr || status=$?
[[ $status == 2 && "$(wc -l <stderr)" == 1 ]] || fail "--format xml: exit $status, $(cat stderr)"
echo "ok"
