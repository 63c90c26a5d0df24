#!/usr/bin/env bash
# run_override.sh WPG: --set changes the scenario (a 3 s walk lasts 3 s) and --no-plot draws
# no figure.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
"$wpg" run walk_forward --set duration=3 --no-plot -o "$WORKDIR/short.h5" || fail "exit status $?"
oracle check_run_file.py "$WORKDIR/short.h5" --duration 3 || fail "bad dataset"
[[ ! -e "$WORKDIR/short.png" ]] || fail "--no-plot drew a figure"
echo "ok"
