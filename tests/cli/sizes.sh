#!/usr/bin/env bash
# sizes.sh CHECKER SOURCE: the source tree keeps its size limits (scripts/check-sizes.py exits
# 0), and the checker catches what it is for: in a small tree, a source file over 600 lines, a
# README over 200 lines and documentation over 50 000 words, each one line naming it; files at
# their limit and files in a build tree pass.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
checker="$(readlink -f "$1")"
source_tree="$(readlink -f "$2")"
"$PYTHON" "$checker" --root "$source_tree" >out 2>&1 || fail "the source tree: $(cat out)"
make_workdir
cd "$WORKDIR"
mkdir -p tree/libwpg/src tree/analysis tree/docs tree/build-x
lines() { awk -v n="$1" -v text="$2" 'BEGIN { for (i = 0; i < n; i++) print text }'; }
lines 601 'int x;' >tree/libwpg/src/long.cpp
lines 600 'x = 1' >tree/analysis/at_limit.py
lines 700 'int x;' >tree/build-x/generated.cpp
lines 201 'text' >tree/README.md
lines 25000 'two words' >tree/docs/a.md
status=0
"$PYTHON" "$checker" --root tree >out 2>&1 || status=$?
[[ $status == 1 ]] || fail "planted violations: exit $status, expected 1 ($(cat out))"
for expected in "libwpg/src/long.cpp: 601 lines (limit 600)" \
                "README.md: 201 lines (limit 200)" \
                "README.md and docs/*.md: 50201 words (limit 50000)"; do
  grep -qF -- "$expected" out || fail "not reported: $expected ($(cat out))"
done
[[ "$(wc -l <out)" == 3 ]] || fail "expected 3 lines: $(cat out)"
echo ok
