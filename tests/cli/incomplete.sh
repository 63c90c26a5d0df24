#!/usr/bin/env bash
# incomplete.sh WPG: exit 3 "could not complete": a run whose dataset write
# fails (a file size limit, as a full disk would) and one that runs out of memory (an address
# space limit) both exit 3 with a last stderr line "wpg: error: could not complete: ...", and
# leave nothing in the output folder (neither the dataset nor its temporary file).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
mkdir "$WORKDIR/out"

expect_incomplete() {  # LABEL: checks the last run's status and leftovers
  echo "$1: exit $status; stderr: $(tail -n 1 "$WORKDIR/stderr")"
  [[ $status == 3 ]] || fail "$1: exit status $status, expected 3"
  tail -n 1 "$WORKDIR/stderr" | grep -q '^wpg: error: could not complete: ' ||
    fail "$1: the last stderr line is not 'wpg: error: could not complete: ...'"
  [[ -z "$(ls -A "$WORKDIR/out")" ]] || fail "$1: files left behind: $(ls -A "$WORKDIR/out")"
}

# The walk's dataset is ~230 kB: a 100 kB file size limit fails its write (SIGXFSZ ignored,
# so that write() reports EFBIG as a full disk reports ENOSPC).
status=0
(trap '' XFSZ; ulimit -f 100; exec "$wpg" run walk_forward --no-plot -o "$WORKDIR/out/run.h5") \
  >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
expect_incomplete "write past the file size limit"

# A walk of 3600 s keeps ~200 MB in memory: 150 MB of address space cannot hold it. A build
# that cannot even start in 150 MB skips this part: the sanitizer tree (WPG_SANITIZED,
# tests/cli/CMakeLists.txt) without trying, since AddressSanitizer reserves terabytes and its
# failure to map them is a report that fails scripts/test-sanitizers.sh; others after a probe.
if [[ "${WPG_SANITIZED:-0}" == 1 ]] || ! (ulimit -v 150000; exec "$wpg" --version) >/dev/null 2>&1; then
  echo "skipped the out-of-memory case: wpg does not start in 150 MB of address space"
  echo "ok"
  exit 0
fi
status=0
(ulimit -v 150000; exec "$wpg" run walk_forward --no-plot --set duration=3600 \
  -o "$WORKDIR/out/run.h5") >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
expect_incomplete "out of memory"
[[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "out of memory: more than one line on stderr"
echo "ok"
