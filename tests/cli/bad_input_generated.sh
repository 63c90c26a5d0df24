#!/usr/bin/env bash
# bad_input_generated.sh WPG CASE: bad input that a CMake argument cannot carry (a FIFO, a huge
# or deeply nested file, a key 20 000 names deep, newlines and escape characters in --set) is
# made here and handed to bad_input.sh: exit 2, one line on stderr naming EXPECTED, nothing
# written (limits: datasets/SCENARIOS.md, "Limits").
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; case_name="$2"
inputs="$(mktemp -d "${TMPDIR:-/tmp}/wpg-cli-inputs.XXXXXX")"
trap 'rm -rf "$inputs"' EXIT
nested() { printf 'name: x\nrobot: hrp2\nduration: 1.0\nreference: '; head -c 100000 /dev/zero | tr '\0' '['; head -c 100000 /dev/zero | tr '\0' ']'; echo; }
check() { bash "$HERE/bad_input.sh" "$wpg" "$@"; }
case "$case_name" in
  fifo)
    mkfifo "$inputs/scenario.yaml"
    check "expected a regular file" run "$inputs/scenario.yaml" ;;
  big_file)  # one byte past 16 MiB, sparse
    truncate -s $((16 * 1024 * 1024 + 1)) "$inputs/scenario.yaml"
    check "at most 16 MiB" run "$inputs/scenario.yaml" ;;
  nested_file)
    nested >"$inputs/scenario.yaml"
    check "nested less deeply" run "$inputs/scenario.yaml" ;;
  nested_study)
    { printf 'name: x\nbase: walk_forward\nsweep: '; head -c 100000 /dev/zero | tr '\0' '['; } >"$inputs/study.yaml"
    check "nested less deeply" batch "$inputs/study.yaml" ;;
  deep_key)
    key="a$(printf '.a%.0s' $(seq 20000))"
    check "at most 32 names and indices" run walk_forward --set "$key=1" ;;
  second_document)
    check "expected one YAML value, got 2 documents" \
      run walk_forward --set "walking.weight_cop=1"$'\n---\n'"2" ;;
  control_characters)  # escaped: the expected text holds a backslash, not the ESC byte
    check "got key 'a\\x1b[2Jb\\nc'" run walk_forward --set $'a\x1b[2Jb\nc=1' ;;
  *) fail "unknown case $case_name" ;;
esac
