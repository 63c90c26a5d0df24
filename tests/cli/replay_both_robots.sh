#!/usr/bin/env bash
# replay_both_robots.sh WPG: walk_forward, curve, walk_sideways and paper_experiment_a run with
# `--replay --filter` on HRP-2 and on TALOS: exit 0, the IK solved on every sample within the
# joint limits, the dynamic filter cuts the multibody ZMP error (RMS and max) at least 3 times
# (6.7 to 9.2 times measured on TALOS, docs/robots.md).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
for robot in hrp2 talos; do
  for scenario in walk_forward curve walk_sideways paper_experiment_a; do
    out="$WORKDIR/${robot}_$scenario"
    status=0
    "$wpg" run "$scenario" --set "robot=$robot" --replay --filter --no-plot -o "$out.h5" \
      >"$out.stdout" 2>"$out.stderr" || status=$?
    [[ $status == 0 ]] || fail "$scenario on $robot: exit status $status: $(cat "$out.stderr")"
    [[ ! -s "$out.stderr" ]] || fail "$scenario on $robot: $(cat "$out.stderr")"
    grep -q "robot $robot, " "$out.stdout" || fail "$scenario: the summary does not name $robot"
    grep -q '^IK        solved on every sample .*; joint limits respected$' "$out.stdout" \
      || fail "$scenario on $robot: $(grep '^IK' "$out.stdout")"
    check_multibody "$out.h5" --filtered --min-reduction 3
    grep '^multibody' "$out.stdout" | sed "s/^/$robot $scenario: /"
  done
done
echo "ok"
