#!/usr/bin/env bash
# replay_bad_robot.sh WPG: a robot folder without a URDF walks, but cannot be replayed:
# `wpg run --filter` and `wpg replay` exit 2 with one line on stderr naming the missing URDF
# (walking.yaml's multibody.urdf), and write nothing; without a `multibody:` map, the line
# names walking.yaml and the key.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
data="$WORKDIR/data"
mkdir -p "$data/robots/nourdf" "$WORKDIR/out"
cp "$WPG_DATA_DIR/robots/hrp2/walking.yaml" "$data/robots/nourdf/walking.yaml"
sed -e 's/^robot: hrp2/robot: nourdf/' -e 's/^duration: .*/duration: 3.0/' \
  "$WPG_DATA_DIR/datasets/scenarios/walk_forward.yaml" >"$WORKDIR/nourdf.yaml"
grep -q '^robot: nourdf' "$WORKDIR/nourdf.yaml" || fail "test bug: robot not replaced"

missing="robots/nourdf/hrp2.urdf"
expect_bad() {  # expect_bad ARGS...: exit 2, one line naming $missing, nothing in out/
  local status=0
  WPG_DATA_DIR="$data" "$wpg" "$@" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
  echo "stderr: $(cat "$WORKDIR/stderr")"
  [[ $status == 2 ]] || fail "$*: exit status $status, expected 2"
  [[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "$*: not one line on stderr"
  grep -q '^wpg: error: ' "$WORKDIR/stderr" || fail "$*: stderr does not start with 'wpg: error: '"
  grep -qF "$missing" "$WORKDIR/stderr" || fail "$*: stderr does not name $missing"
  [[ ! -s "$WORKDIR/stdout" ]] || fail "$*: unexpected stdout"
  [[ -z "$(ls -A "$WORKDIR/out")" ]] || fail "$*: files written: $(ls -A "$WORKDIR/out")"
}
expect_bad run "$WORKDIR/nourdf.yaml" --filter --no-plot -o "$WORKDIR/out/run.h5"
expect_bad run "$WORKDIR/nourdf.yaml" --replay --no-plot -o "$WORKDIR/out/run.h5"
expect_bad run "$WORKDIR/nourdf.yaml" --set replay=true --no-plot -o "$WORKDIR/out/run.h5"
# Without the replay the robot walks; its dataset cannot be replayed.
WPG_DATA_DIR="$data" "$wpg" run "$WORKDIR/nourdf.yaml" --no-plot -o "$WORKDIR/walk.h5" >/dev/null \
  || fail "run without replay: exit status $?"
before="$(md5sum <"$WORKDIR/walk.h5")"
expect_bad replay "$WORKDIR/walk.h5" --no-plot -o "$WORKDIR/out/replayed.h5"
expect_bad replay "$WORKDIR/walk.h5" --no-plot
[[ "$(md5sum <"$WORKDIR/walk.h5")" == "$before" ]] || fail "a failed replay changed the file"
# A walking file without `multibody:` (a robot that only walks).
"$PYTHON" - "$data/robots/nourdf/walking.yaml" <<'PY'
import re, sys
path = sys.argv[1]
text = open(path).read()
stripped = re.sub(r"^multibody:\n(?:  .*\n)+", "", text, flags=re.M)
assert stripped != text, "test bug: no multibody map"
open(path, "w").write(stripped)
PY
missing="robots/nourdf/walking.yaml: robot 'nourdf' has no multibody model for the replay: key 'multibody'"
expect_bad run "$WORKDIR/nourdf.yaml" --replay --no-plot -o "$WORKDIR/out/run.h5"
expect_bad replay "$WORKDIR/walk.h5" --no-plot -o "$WORKDIR/out/replayed.h5"
echo "ok"
