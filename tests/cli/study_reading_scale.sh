#!/usr/bin/env bash
# study_reading_scale.sh WPG: reading a study is linear in its runs: `wpg analyze` and `wpg
# view` of a 2000-run study take at most 6 times the CPU time of a 500-run one (4 times the
# runs; a constant time per run gives 3 to 4 times, reading every run with a listing of all
# of /runs gave 7.6 times the CPU time: 1.9 s and 14.2 s).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$(readlink -f "$1")"
# Not in the sanitizer tree (WPG_SANITIZED): it has no viewer bundle, and CPU-time ratios under
# ASan measure the sanitizer.
[[ "${WPG_SANITIZED:-0}" != 1 ]] || { echo "skipped in the sanitizer tree"; exit 77; }
make_workdir
cd "$WORKDIR"
"$wpg" batch "$HERE/studies/tiny_batch.yaml" -o tiny.h5 --no-plot >/dev/null 2>&1
for n in 500 2000; do
  "$PYTHON" "$HERE/large_study.py" tiny.h5 "$n" "s$n.h5" || fail "large_study.py $n"
done
# The CPU time (user + system) of `wpg ARGS`, which must succeed: on shared cores the wall
# time is the other jobs' as much as wpg's.
seconds() {
  timeout 600 /usr/bin/time -f "%U %S" -o cpu "$wpg" "$@" >/dev/null 2>stderr ||
    fail "wpg $*: $(cat stderr)"
  awk '{print $1 + $2}' cpu
}
for command in analyze view; do
  args=()
  [[ $command == view ]] && args=(-o page.html)
  small=$(seconds "$command" s500.h5 "${args[@]}")
  large=$(seconds "$command" s2000.h5 "${args[@]}")
  echo "$command: 500 runs ${small} s, 2000 runs ${large} s of CPU"
  # Not under the sanitizers (WPG_SANITIZED): their cost per read is not the build's.
  [[ "${WPG_SANITIZED:-0}" == 1 ]] || (( $(echo "$large <= 6 * $small" | bc -l) )) ||
    fail "$command: 4 times the runs took $(echo "$large / $small" | bc -l) times as long"
done
echo ok
