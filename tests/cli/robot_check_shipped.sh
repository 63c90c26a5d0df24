#!/usr/bin/env bash
# robot_check_shipped.sh WPG ROBOT: `wpg robot check ROBOT` on a shipped robot exits 0 with
# nothing on stderr (every declared polygon vertex reached by the IK, the declared CoM height
# walkable), both legs solved in closed form, and writes nothing.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; robot="$2"
make_workdir
cd "$WORKDIR"
status=0
"$wpg" robot check "$robot" >stdout 2>stderr || status=$?
cat stdout; cat stderr >&2
[[ $status == 0 ]] || fail "exit status $status"
[[ ! -s stderr ]] || fail "warnings on stderr"
grep -Eq '^  legs .* 6 joints, .* 6 joints; .*; IK analytic, analytic$' stdout || fail "legs line"
grep -Eq '^  CoM height .*; declared [0-9.]+ m$' stdout || fail "CoM height line"
[[ "$(ls -A | sort | tr '\n' ' ')" == "stderr stdout " ]] || fail "files written: $(ls -A)"
echo "ok"
