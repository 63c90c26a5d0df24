#!/usr/bin/env bash
# The table of docs/results.md, "Dynamic filter: no filter, online, closed loop": the
# multibody ZMP error (|WPG CoP - multibody ZMP|, RMS / max in mm) of every shipped scenario
# without the filter (`--replay`), with the offline pass, the online loop (open), the closed
# loop (`filter_settings.mode: closed_loop`) and the paper's Fig. 3 read literally (online +
# `reinitialize_wpg: true`), measured with the wpg of the build tree (built first). Prints the
# Markdown table on stdout; the datasets go to a temporary folder, removed at the end.
#
#   scripts/filter-loop-table.sh [scenario ...]     (default: every shipped scenario)
#   WPG_ROBOT=talos scripts/filter-loop-table.sh     (another robot: --set robot=talos)
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  echo "filter-loop-table: error: no build in $build (run scripts/setup.sh first)" >&2
  exit 2
fi
cmake --build "$build" --target wpg -j2 >/dev/null
wpg="$build/cli/wpg"
robot="${WPG_ROBOT:-hrp2}"
work="$(mktemp -d "${TMPDIR:-/tmp}/wpg-filter-table.XXXXXX")"
trap 'rm -rf -- "$work"' EXIT

if [[ $# -gt 0 ]]; then
  scenarios=("$@")
else
  scenarios=()
  for file in "$repo"/datasets/scenarios/*.yaml; do scenarios+=("$(basename "$file" .yaml)"); done
fi

# One cell: "RMS / max" after the filter (before it for --replay), "falls at T s" when the
# robot fell; a walk to a goal that did not reach it says so (" (goal not reached)"), a walk
# that ended blocked too (" (blocked, exit 1)").
cell() {
  local scenario=$1 status=0 out
  shift
  out="$("$wpg" run "$scenario" --no-plot -o "$work/run.h5" --set "robot=$robot" "$@" 2>&1)" \
    || status=$?
  if grep -q "fallen" <<<"$out"; then
    local iterations
    iterations="$(sed -n 's/.*(\([0-9]*\) NMPC iterations).*/\1/p' <<<"$out" | head -1)"
    # the shipped robots' sampling period, 0.1 s per NMPC iteration
    echo "falls at $(awk -v n="$iterations" 'BEGIN { printf "%.1f", n * 0.1 }') s"
    return
  fi
  local line
  line="$(grep "multibody ZMP error" <<<"$out" || true)"
  if [[ -z $line ]]; then
    echo "exit $status"
    return
  fi
  if grep -q -- "->" <<<"$line"; then
    sed -E 's/.*RMS [0-9.]+ mm -> ([0-9.]+) mm, max [0-9.]+ mm -> ([0-9.]+) mm.*/\1 \/ \2/' <<<"$line"
  else
    sed -E 's/.*RMS ([0-9.]+) mm, max ([0-9.]+) mm.*/\1 \/ \2/' <<<"$line"
  fi
  if grep -q "^goal " <<<"$out" && ! grep -q "^goal      reached" <<<"$out"; then
    echo " (goal not reached)"
  fi
  if grep -q "the robot is blocked: " <<<"$out"; then
    echo " (blocked, exit $status)"
    return
  fi
  [[ $status == 0 ]] || echo " (exit $status)"
}

echo "| scenario | no filter | offline | online (open loop) | closed loop | Fig. 3 literal |"
echo "|---|---|---|---|---|---|"
for scenario in "${scenarios[@]}"; do
  none="$(cell "$scenario" --replay)"
  offline="$(cell "$scenario" --filter --set filter_settings.mode=offline)"
  online="$(cell "$scenario" --filter --set filter_settings.mode=online)"
  closed="$(cell "$scenario" --filter --set filter_settings.mode=closed_loop)"
  literal="$(cell "$scenario" --filter --set filter_settings.mode=online \
    --set filter_settings.reinitialize_wpg=true)"
  echo "| \`$scenario\` | $none | $offline | $online | $closed | $literal |" | tr -d '\n'
  echo
done
