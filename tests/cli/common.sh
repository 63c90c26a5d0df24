# shellcheck shell=bash
# Helpers sourced by the CLI test drivers (bash, set -euo pipefail).
PYTHON="${WPG_PYTHON:-/usr/bin/python3}"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

fail() { echo "FAIL: $*" >&2; exit 1; }

# A fresh temporary folder, removed on exit when the test passed (kept for a look otherwise).
make_workdir() {
  WORKDIR="$(mktemp -d "${TMPDIR:-/tmp}/wpg-cli-test.XXXXXX")"
  # shellcheck disable=SC2154  # _rc is assigned inside the trap
  trap '_rc=$?; if [[ $_rc == 0 || $_rc == 77 ]]; then rm -rf "$WORKDIR"; else echo "(kept $WORKDIR)" >&2; fi' EXIT
}

# oracle SCRIPT ARGS...: tests/cli/SCRIPT, a Python check of the values a command wrote (against
# the paper's invariants, a recomputation, or another file bit for bit), and its exit status.
# In the sanitizer tree (WPG_SANITIZED) it returns 0 without running: the sanitizers instrument
# the C++ that wrote the file, not the Python that reads it, and the Release tree runs every
# oracle on the same commands' outputs. There the oracles were 45 s of the CLI tests' CPU
# (compare_batch_files.py alone 22 s). A script that runs wpg itself (check_push_sweep.py) or
# makes a test's input is not an oracle: it runs everywhere.
oracle() {
  [[ "${WPG_SANITIZED:-0}" != 1 ]] || return 0
  "$PYTHON" "$HERE/$1" "${@:2}"
}

# check_run_file FILE.h5 [ARGS...]: the schema's datasets are there, with consistent shapes.
check_run_file() { oracle check_run_file.py "$@" || fail "bad dataset $1"; }

# check_png FILE.png: exists and starts with the PNG signature.
check_png() {
  [[ -s "$1" ]] || fail "no figure $1"
  [[ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" == 89504e470d0a1a0a ]] || fail "$1 is not a PNG"
}

# check_multibody FILE.h5 ARGS...: the multibody replay fields (check_multibody.py ARGS).
check_multibody() { oracle check_multibody.py "$@" || fail "bad multibody fields in $1"; }
