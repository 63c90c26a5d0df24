#!/usr/bin/env bash
# bad_input.sh WPG EXPECTED ARGS...: `wpg ARGS... -o <tmp>/out.h5` exits 2, prints exactly one
# line on stderr (nothing else) that contains EXPECTED, and leaves the output folder empty.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; expected="$2"; shift 2
make_workdir
mkdir "$WORKDIR/out" "$WORKDIR/cwd"
status=0
(cd "$WORKDIR/cwd" && "$wpg" "$@" -o "$WORKDIR/out/run.h5") \
  >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
echo "stderr: $(cat "$WORKDIR/stderr")"
[[ $status == 2 ]] || fail "exit status $status, expected 2"
lines="$(wc -l <"$WORKDIR/stderr")"
[[ $lines == 1 ]] || fail "$lines lines on stderr, expected 1"
grep -q '^wpg: error: ' "$WORKDIR/stderr" || fail "stderr does not start with 'wpg: error: '"
grep -qF -- "$expected" "$WORKDIR/stderr" || fail "stderr does not name '$expected'"
[[ ! -s "$WORKDIR/stdout" ]] || fail "unexpected stdout: $(cat "$WORKDIR/stdout")"
leftovers="$(ls -A "$WORKDIR/out" "$WORKDIR/cwd")"
[[ -z "$(ls -A "$WORKDIR/out")" && -z "$(ls -A "$WORKDIR/cwd")" ]] || fail "files left behind: $leftovers"
echo "ok"
