#!/usr/bin/env bash
# batch_resume_other.sh WPG STUDY OTHER_STUDY: `wpg batch OTHER --resume -o FILE` where FILE
# holds STUDY exits 2 with one line naming both studies and leaves FILE byte for byte as it was.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; study="$2"; other="$3"
make_workdir
cd "$WORKDIR"
"$wpg" batch "$study" -o batch.h5 -j 2 --no-plot >/dev/null 2>&1 || fail "first batch: exit $?"
before="$(md5sum <batch.h5)"
ls -A >before.list
status=0
"$wpg" batch "$other" -o batch.h5 --resume >stdout 2>stderr || status=$?
echo "stderr: $(cat stderr)"
[[ $status == 2 ]] || fail "exit status $status, expected 2"
[[ "$(wc -l <stderr)" == 1 ]] || fail "expected one line on stderr"
grep -q "other_study" stderr || fail "the message does not name the study"
[[ "$(md5sum <batch.h5)" == "$before" ]] || fail "the file was changed"
ls -A | grep -v -e '^stdout$' -e '^stderr$' | diff - <(grep -v -e '^stdout$' -e '^stderr$' before.list) ||
  fail "files were added or removed"
echo "ok"
