#!/usr/bin/env bash
# hardening_input.sh WPG CASE: hostile files and values given to the study commands end in
# bounded time with one clear line (exit 2 bad input, exit 3 could not complete), never a hang
# or unbounded work (datasets/SCENARIOS.md "Limits", datasets/SCHEMA.md "Reading").
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$(readlink -f "$1")"
case_name="$2"
make_workdir
cd "$WORKDIR"
cp "$HERE/studies/tiny_batch.yaml" study.yaml
cp "$HERE/studies/tiny_compare.yaml" compare.yaml

# refused STATUS PATTERN ARGS...: exit STATUS within 20 s, one line on stderr matching PATTERN.
refused() {
  local expected="$1" pattern="$2" status=0
  shift 2
  timeout 20 "$wpg" "$@" >stdout 2>stderr || status=$?
  [[ $status == "$expected" ]] || fail "wpg $*: exit $status, expected $expected ($(cat stderr))"
  [[ "$(wc -l <stderr)" == 1 ]] || fail "wpg $*: not one line on stderr: $(cat stderr)"
  grep -q -- "$pattern" stderr || fail "wpg $*: expected '$pattern': $(cat stderr)"
}

case "$case_name" in
external_link_special)
  # An index whose links lead to a FIFO, a device, a missing file: refused, naming the run and
  # the link, never opened (a FIFO would block analyze and diff forever).
  "$wpg" batch study.yaml -o s0.h5 --shard 0/1 --no-plot >/dev/null 2>&1
  "$wpg" merge idx.h5 s0.h5 --no-plot >/dev/null
  mv s0.h5 real.h5
  mkfifo s0.h5
  refused 2 "/runs/tiny_0: external link to 's0.h5': expected a regular file, got a FIFO" analyze idx.h5
  refused 2 "/runs/tiny_0: external link to 's0.h5': expected a regular file, got a FIFO" diff idx.h5 real.h5
  "$PYTHON" - <<'PY'
import h5py
with h5py.File("device.h5", "w") as f:
    for name, value in h5py.File("idx.h5", "r").attrs.items():
        f.attrs[name] = value
    f.create_group("runs")["tiny_0"] = h5py.ExternalLink("/dev/zero", "/runs/tiny_0")
PY
  refused 2 "/runs/tiny_0: external link to '/dev/zero': expected a regular file, got a character device" \
    diff device.h5 real.h5
  rm s0.h5
  refused 2 "/runs/tiny_0: external link to 's0.h5': no such file" analyze idx.h5
  ;;
*) fail "unknown case $case_name" ;;
esac
echo ok
