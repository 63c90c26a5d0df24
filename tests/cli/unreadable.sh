#!/usr/bin/env bash
# unreadable.sh WPG SCENARIO mode|link: a copy of SCENARIO without read permission (skipped,
# exit 77, when the permission does not stop us, as root), or a dangling symbolic link.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; scenario="$2"; kind="$3"
make_workdir
fixture="$WORKDIR/unreadable_scenario.yaml"
if [[ $kind == mode ]]; then
  cp "$scenario" "$fixture"
  chmod 000 "$fixture"
  if [[ -r "$fixture" ]]; then echo "skipped: running as root, the file stays readable"; exit 77; fi
else
  ln -s "$WORKDIR/no_such_target.yaml" "$fixture"
fi
"$HERE/bad_input.sh" "$wpg" unreadable_scenario.yaml run "$fixture"
