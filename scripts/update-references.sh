#!/usr/bin/env bash
# Regenerates the regression references datasets/references/<scenario>.h5 with the wpg of the
# build tree (building it first): `wpg run <scenario> --no-plot` for every shipped scenario but
# the excluded ones below, or for the scenarios named as arguments.
#
# Regenerate ONLY after an intended change of the walks (a new default, a fixed bug), never to
# make a failing regression test pass; commit the new references with a message that says what
# changed and why (datasets/references/README.md).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m -- "${WPG_BUILD_DIR:-$repo/build}")"
references="$repo/datasets/references"
# Shipped scenarios without a reference, to keep datasets/references/ small (6.1 MiB with the
# stored plans; each left out 0.5-1 MiB), and why (datasets/references/README.md): their constraint
# kinds and code paths are covered by the references kept (obstacle_cluttered holds circles,
# boxes and polygons; paper_experiment_a the circle of the paper; goal_with_yaw the planner,
# the path follower and the goal attributes; obstacle_wall's box is obstacle_cluttered's kind,
# its blocked verdict tested by cli.run.obstacle_wall; the obstacle scenes' kinds, one shipped
# scenario each, are judged by cli.obstacle_scenes and the study of docs/obstacle_scenes.md).
excluded=(obstacle_boxes obstacle_polygon paper_experiment_b goal_cluttered goal_u_trap
          goal_unknown_obstacle obstacle_wall obstacle_box_on_path obstacle_box_then_circle
          obstacle_enclosure obstacle_gap obstacle_lateral obstacle_narrow_doorway
          obstacle_slalom obstacle_staggered_boxes obstacle_turning)

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  echo "update-references: error: no build in $build (run scripts/setup.sh first)" >&2
  exit 2
fi
cmake --build "$build" --target wpg -j2 >/dev/null
wpg="$build/cli/wpg"

if [[ $# -gt 0 ]]; then
  scenarios=("$@")
else
  scenarios=()
  for file in "$repo"/datasets/scenarios/*.yaml; do
    name="$(basename "$file" .yaml)"
    skip=0
    for pattern in "${excluded[@]}"; do
      # shellcheck disable=SC2053  # the exclusions are glob patterns
      [[ $name == $pattern ]] && skip=1
    done
    [[ $skip == 1 ]] || scenarios+=("$name")
  done
fi

tmp="$(mktemp -d "$references/.update.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
for name in "${scenarios[@]}"; do
  status=0
  (cd "$repo" && WPG_DATA_DIR="$repo" "$wpg" run "$name" -o "$tmp/$name.h5" --no-plot >/dev/null) \
    || status=$?
  # Exit 1 (a walk that failed) still writes its dataset: the reference records the failure.
  if [[ $status != 0 && $status != 1 ]]; then
    echo "update-references: error: wpg run $name: exit status $status" >&2
    exit 2
  fi
  size="$(du -k "$tmp/$name.h5" | cut -f1) KiB"
  [[ $status == 0 ]] || size+=", the walk fails: exit 1"
  # The wall times differ at every run: a reference whose contents are the same bit for bit
  # (wall times aside) is kept as it is, so that git shows only the walks that changed.
  if [[ -f "$references/$name.h5" ]] && "$wpg" diff "$references/$name.h5" "$tmp/$name.h5" \
       --rtol 0 --atol 0 >/dev/null 2>&1; then
    echo "$name: unchanged ($size)"
  else
    mv -f "$tmp/$name.h5" "$references/$name.h5"
    echo "$name: written ($size)"
  fi
done
echo "total: $(cat "$references"/*.h5 | wc -c | awk '{printf "%.2f MiB", $1 / 1048576}') in $references"
echo "review each written one against its previous version:"
echo "  git show HEAD:datasets/references/<name>.h5 >/tmp/old.h5 && wpg diff /tmp/old.h5 datasets/references/<name>.h5"
echo "and say in the commit why the walks changed"
