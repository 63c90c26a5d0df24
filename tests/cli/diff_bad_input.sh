#!/usr/bin/env bash
# diff_bad_input.sh WPG REFERENCE.h5: `wpg diff` on bad input exits 2 with one line on stderr
# ("wpg: error: ...") naming the file or option, and nothing on stdout: a missing file, a
# directory, a file that is not HDF5, an HDF5 file that is not a wpg dataset, a negative
# tolerance. And a file compared with itself is the same (exit 0).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; reference="$2"
make_workdir

expect_bad() {  # expect_bad NAME ARGS...
  local name="$1" status=0; shift
  "$wpg" diff "$@" >"$WORKDIR/stdout" 2>"$WORKDIR/stderr" || status=$?
  echo "stderr: $(cat "$WORKDIR/stderr")"
  [[ $status == 2 ]] || fail "diff $*: exit status $status, expected 2"
  [[ "$(wc -l <"$WORKDIR/stderr")" == 1 ]] || fail "diff $*: not one line on stderr"
  grep -q '^wpg: error: ' "$WORKDIR/stderr" || fail "diff $*: stderr does not start with 'wpg: error: '"
  grep -qF -- "$name" "$WORKDIR/stderr" || fail "diff $*: stderr does not name $name"
  [[ ! -s "$WORKDIR/stdout" ]] || fail "diff $*: unexpected stdout: $(cat "$WORKDIR/stdout")"
}
expect_bad missing.h5 "$reference" "$WORKDIR/missing.h5"
expect_bad missing.h5 "$WORKDIR/missing.h5" "$reference"
mkdir "$WORKDIR/folder.h5"
expect_bad folder.h5 "$reference" "$WORKDIR/folder.h5"
echo "not an HDF5 file" >"$WORKDIR/text.h5"
expect_bad text.h5 "$reference" "$WORKDIR/text.h5"
"$PYTHON" -c "import h5py, sys; h5py.File(sys.argv[1], 'w').create_dataset('x', data=[1.0])" \
  "$WORKDIR/other.h5"
expect_bad other.h5 "$WORKDIR/other.h5" "$reference"
expect_bad rtol "$reference" "$reference" --rtol -1
expect_bad 'b is required' "$reference"

"$wpg" diff --help >"$WORKDIR/help" || fail "diff --help: exit status $?"
for text in 'R=1e-09' 'A=1e-09' --compare-wall-time --ignore; do
  grep -qF -- "$text" "$WORKDIR/help" || fail "diff --help lacks '$text'"
done
"$wpg" --help | grep -q '\bdiff\b' || fail "--help lacks the diff subcommand"

"$wpg" diff "$reference" "$reference" >"$WORKDIR/stdout" || fail "diff of a file with itself: exit status $?"
grep -q "^same within tolerance" "$WORKDIR/stdout" || fail "diff of a file with itself: $(cat "$WORKDIR/stdout")"
echo "ok"
