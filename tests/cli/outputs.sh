#!/usr/bin/env bash
# outputs.sh WPG: outputs never destroy what is not theirs (policy in
# datasets/include/wpg/datasets/output_file.hpp). Each refused case exits 2 with one line on
# stderr and leaves every file as it was; an existing output of the same kind is replaced; no
# temporary file is left behind.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$(readlink -f "$1")"
make_workdir
cd "$WORKDIR"
cp "$HERE/../../datasets/scenarios/walk_forward.yaml" in.yaml

# refused ARGS...: exit 2, one line on stderr naming "expected a regular file".
refused() {
  local status=0
  "$wpg" "$@" >stdout 2>stderr || status=$?
  [[ $status == 2 ]] || fail "wpg $*: exit $status, expected 2 ($(cat stderr))"
  [[ "$(wc -l <stderr)" == 1 ]] || fail "wpg $*: not one line on stderr: $(cat stderr)"
  grep -q "expected a regular file" stderr || fail "wpg $*: $(cat stderr)"
}

# 1. not a regular file: a device, a folder (existing or with '/'), a pipe of this process.
if [[ -c /dev/null ]]; then
  refused run in.yaml -o /dev/null --no-plot
  [[ -c /dev/null ]] || fail "/dev/null is no longer a character device"
fi
refused run in.yaml -o newdir/ --no-plot
[[ ! -e newdir ]] || fail "newdir/ was created"
mkdir existing
refused run in.yaml -o existing --no-plot
refused run in.yaml -o /proc/self/fd/0 --no-plot </dev/null

# 2. an input of the command, compared by identity (a second name for it too).
sum="$(md5sum <in.yaml)"
refused run in.yaml -o in.yaml --no-plot
ln in.yaml hardlink.h5
refused run in.yaml -o hardlink.h5 --no-plot
[[ "$(md5sum <in.yaml)" == "$sum" ]] || fail "the scenario was modified"
refused bench in.yaml --json in.yaml
[[ "$(md5sum <in.yaml)" == "$sum" ]] || fail "the scenario was modified by bench"

# ... and files of another kind: a dataset is not replaced by a figure, a scenario by a dataset.
"$wpg" run in.yaml --set duration=2 -o a.h5 --no-plot >/dev/null
"$wpg" run in.yaml --set duration=2 -o b.h5 --no-plot >/dev/null
sum_b="$(md5sum <b.h5)"
refused plot a.h5 -o b.h5
[[ "$(md5sum <b.h5)" == "$sum_b" ]] || fail "b.h5 was modified by plot"
cp in.yaml other.yaml
refused run in.yaml -o other.yaml --no-plot

# The same kind is replaced (atomically): a dataset by a dataset, a figure by a figure.
"$wpg" run in.yaml --set duration=3 -o b.h5 --no-plot >/dev/null
[[ "$(md5sum <b.h5)" != "$sum_b" ]] || fail "b.h5 was not replaced"
"$wpg" plot a.h5 -o fig.png >/dev/null
"$wpg" plot b.h5 -o fig.png >/dev/null
check_png fig.png

# 3. a symlink in place of the output is not followed into its target: refused when the
#    target is of another kind, and no temporary file is ever left beside the outputs.
ln -s in.yaml link.h5
refused run in.yaml -o link.h5 --no-plot
[[ "$(md5sum <in.yaml)" == "$sum" ]] || fail "the symlink's target was modified"
leftovers="$(ls -A | grep -E '^\.|tmp' || true)"
[[ -z "$leftovers" ]] || fail "temporary files left behind: $leftovers"
echo "ok"
