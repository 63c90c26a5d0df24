#!/usr/bin/env bash
# robot_check.sh WPG: `wpg robot check` passes on HRP-2 and prints what it derived; on robot
# folders made bad from a copy of HRP-2's (a missing sole frame, a leg of five joints, a URDF
# with a loop, a zero and a negative mass, an inertia that is not positive definite, a
# feasibility polygon that is not convex) it exits 2 with one line naming the file and what is
# wrong, and writes nothing.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
hrp2="$WPG_DATA_DIR/robots/hrp2"

"$wpg" robot check hrp2 >"$WORKDIR/hrp2.txt" 2>"$WORKDIR/hrp2.err" || fail "hrp2: exit status $?"
cat "$WORKDIR/hrp2.txt"
[[ ! -s "$WORKDIR/hrp2.err" ]] || fail "hrp2: unexpected stderr: $(cat "$WORKDIR/hrp2.err")"
for expected in "LLEG_SOLE 6 joints, RLEG_SOLE 6 joints" "straight 0.7" "IK analytic, analytic" "walkable" \
    "declared        (-0.280, 0.200)" "reached by IK   ("; do
  grep -qF "$expected" "$WORKDIR/hrp2.txt" || fail "hrp2: no '$expected' in the report"
done
# The folder by its path gives the same report.
"$wpg" robot check "$hrp2" | tail -n +2 | cmp -s - <(tail -n +2 "$WORKDIR/hrp2.txt") \
  || fail "the report by path differs from the report by name"

# bad CASE EXPECTED_FILE EXPECTED_TEXT: a copy of hrp2/ as robots/CASE, edited by the caller,
# checked: exit 2, one line on stderr naming the file and the text, nothing written.
fresh() {  # fresh CASE: a copy of HRP-2's folder
  mkdir -p "$WORKDIR/robots"
  cp -r "$hrp2" "$WORKDIR/robots/$1"
}
expect_bad() {
  local case="$1" file="$2" text="$3" status=0
  local before
  before="$(find "$WORKDIR/robots" -type f -exec md5sum {} + | sort)"
  (cd "$WORKDIR" && "$wpg" robot check "robots/$case" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr") \
    || status=$?
  echo "$case: $(cat "$WORKDIR/stderr")"
  [[ $status == 2 ]] || fail "$case: exit status $status, expected 2"
  [[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "$case: not one line on stderr"
  grep -q '^wpg: error: ' "$WORKDIR/stderr" || fail "$case: stderr does not start with 'wpg: error: '"
  grep -qF "robots/$case/$file" "$WORKDIR/stderr" || fail "$case: stderr does not name $file"
  grep -qF "$text" "$WORKDIR/stderr" || fail "$case: stderr does not say '$text'"
  [[ ! -s "$WORKDIR/stdout" ]] || fail "$case: unexpected stdout"
  [[ "$(find "$WORKDIR/robots" -type f -exec md5sum {} + | sort)" == "$before" ]] \
    || fail "$case: files changed"
}
# edit FILE PYTHON: rewrites FILE with the Python expression PYTHON of `text`.
edit() {
  "$PYTHON" - "$1" "$2" <<'PY'
import re, sys
path, expression = sys.argv[1], sys.argv[2]
text = open(path).read()
edited = eval(expression)
assert edited != text, "test bug: the edit changed nothing"
open(path, "w").write(edited)
PY
}

fresh no_sole
edit "$WORKDIR/robots/no_sole/walking.yaml" 'text.replace("left_sole_frame: LLEG_SOLE", "left_sole_frame: LFOOT")'
expect_bad no_sole hrp2.urdf "no link LFOOT"

fresh five_joints  # the left ankle roll welded: five joints from the waist to the sole
edit "$WORKDIR/robots/five_joints/hrp2.urdf" 'text.replace("<joint name=\"LLEG_JOINT5\" type=\"revolute\">", "<joint name=\"LLEG_JOINT5\" type=\"fixed\">")'
edit "$WORKDIR/robots/five_joints/hrp2.srdf" 'text.replace("    <joint name=\"LLEG_JOINT5\" value=\"0\"/>\n", "")'
expect_bad five_joints hrp2.urdf "the leg of LLEG_SOLE has 5 joints"

fresh loop  # the right hip hangs from the left foot too
edit "$WORKDIR/robots/loop/hrp2.urdf" 'text.replace("</robot>", "  <joint name=\"LOOP\" type=\"fixed\"><parent link=\"LLEG_LINK5\"/><child link=\"RLEG_LINK0\"/></joint>\n</robot>")'
expect_bad loop hrp2.urdf "a loop"

fresh zero_mass
edit "$WORKDIR/robots/zero_mass/hrp2.urdf" 're.sub(r"<mass value=\"[^\"]*\"/>", "<mass value=\"0\"/>", text, count=1)'
expect_bad zero_mass hrp2.urdf "expected a positive mass"

fresh negative_mass
edit "$WORKDIR/robots/negative_mass/hrp2.urdf" 're.sub(r"<mass value=\"[^\"]*\"/>", "<mass value=\"-1.5\"/>", text, count=1)'
expect_bad negative_mass hrp2.urdf "expected a positive mass"

fresh inertia  # a negative principal moment
edit "$WORKDIR/robots/inertia/hrp2.urdf" 're.sub(r"ixx=\"[^\"]*\"", "ixx=\"-0.01\"", text, count=1)'
expect_bad inertia hrp2.urdf "not positive definite"

fresh concave  # the outermost vertex pulled in past its neighbours
edit "$WORKDIR/robots/concave/walking.yaml" 'text.replace("feasibility_y: [0.2, 0.3, 0.4, 0.3, 0.2]", "feasibility_y: [0.2, 0.3, 0.22, 0.3, 0.2]")'
expect_bad concave walking.yaml "convex"

fresh no_walking_file
rm "$WORKDIR/robots/no_walking_file/walking.yaml"
expect_bad no_walking_file walking.yaml "not found"
echo "ok"
