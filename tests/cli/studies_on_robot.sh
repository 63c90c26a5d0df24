#!/usr/bin/env bash
# studies_on_robot.sh WPG ROBOT: every shipped study runs on ROBOT. Each study file is copied
# with ROBOT selected as docs/robots.md says (`robot: ROBOT` in its base, `robot: [ROBOT]` in
# the grid of a study whose base is a scenario name, `set: {robot: ROBOT}` in a comparison,
# whose worlds from scenario files keep their own robot otherwise) and a slice of it is run
# (`--shard 0/20`, 4 to 27 runs): batches exit 0, or 1 when the only failed walks ended blocked
# (closed scenes), comparisons exit 0; every run's stored scenario names ROBOT.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; robot="$2"
make_workdir
cd "$WORKDIR"
for file in "$WPG_DATA_DIR"/datasets/studies/*.yaml; do
  study=$(basename "$file" .yaml)
  if grep -q '^worlds:' "$file"; then  # a world from a scenario file keeps its robot: set it
    grep -q '^set:' "$file" && fail "test bug: $study has a set: map already"
    sed "s/^worlds:/set: {robot: $robot}\nworlds:/" "$file" >"$study.yaml"
  elif grep -q '^  robot: hrp2' "$file"; then
    sed "s/^  robot: hrp2/  robot: $robot/" "$file" >"$study.yaml"
  else
    grep -q '^base: [a-z_]*' "$file" || fail "$study: no robot to replace"
    sed "s/^  grid:/  grid:\n    robot: [$robot]/" "$file" >"$study.yaml"
  fi
  grep -q "robot: \[*$robot" "$study.yaml" || fail "test bug: $study.yaml names no $robot"
  status=0
  if grep -q '^worlds:' "$study.yaml"; then
    "$wpg" compare "$study.yaml" --shard 0/20 --no-plot -o "$study" >"$study.out" 2>&1 \
      || status=$?
    [[ $status == 0 ]] || fail "$study: exit $status: $(tail -3 "$study.out")"
    out="$study/study.shards/slice-0-of-20.h5"
  else
    "$wpg" batch "$study.yaml" --shard 0/20 --no-plot -o "$study.h5" >"$study.out" 2>&1 \
      || status=$?
    [[ $status == 0 || $status == 1 ]] || fail "$study: exit $status: $(tail -3 "$study.out")"
    out="$study.h5"
  fi
  "$PYTHON" - "$out" "$robot" "$status" <<'PY' || fail "$study: $(tail -3 "$study.out")"
import sys
import h5py
f = h5py.File(sys.argv[1], "r")
runs = f["runs"]
assert len(runs) >= 2, len(runs)
for name in runs:
    run = runs[name]
    text = run.attrs["scenario"] if "scenario" in run.attrs else f.attrs["scenario"]
    assert "robot: " + sys.argv[2] in str(text), name
    if sys.argv[3] == "1" and not run.attrs.get("success", 1):
        assert run.attrs.get("blocked", 0), name + " failed without ending blocked"
print(f"{sys.argv[1]}: {len(runs)} runs on {sys.argv[2]}")
PY
done
echo "ok"
