#!/usr/bin/env bash
# view_outputs.sh WPG: every file `wpg view` writes for a study (the dashboard, PAGE_runs/<run>.html,
# PAGE_runs/wpg_viewer.js) goes through the checks of every other output, all of them before any
# run is read (docs/robustness.md): a symbolic link or a file as PAGE_runs, a run page or the
# shared script over a file of another kind or as a symbolic link, PAGE_runs not writable: exit
# 2, one line naming the path, nothing written, nothing of the victim changed. The order is seen
# in a study whose second run is missing: a bad output is what the message names.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
make_workdir
cd "$WORKDIR"
"$wpg" batch "$VIEWER_TESTS/../cli/studies/tiny_batch.yaml" --no-plot -o tiny.h5 >/dev/null || fail "batch: exit status $?"
cp tiny.h5 broken.h5
"$PYTHON" -c 'import h5py; f = h5py.File("broken.h5", "r+"); del f["runs/tiny_1"]' || fail "h5py"
mkdir elsewhere
printf 'precious\0data' >elsewhere/victim.bin
printf 'precious notes\n' >elsewhere/notes.txt
snapshot() { find . -path ./elsewhere -prune -o -type f -newer tiny.h5 -print | sort; sha256sum elsewhere/*; }

expect_refused() {  # expect_refused WHAT EXPECTED_TEXT FILE: exit 2, one line, nothing written
  local what="$1" expected="$2" file="$3" status=0
  local before
  before="$(snapshot)"
  "$wpg" view "$file" >stdout 2>stderr || status=$?
  [[ $status == 2 ]] || fail "$what: exit status $status, expected 2 ($(cat stderr))"
  [[ "$(wc -l <stderr)" == 1 ]] || fail "$what: not one line on stderr: $(cat stderr)"
  grep -qF -- "$expected" stderr || fail "$what: stderr does not say '$expected': $(cat stderr)"
  rm -f stdout
  local after
  after="$(snapshot)"
  rm -f stderr
  [[ "$before" == "$(echo "$after" | grep -v '^./stderr$')" ]] || fail "$what: files changed: $before / $after"
  [[ ! -e "${file%.h5}.html" ]] || fail "$what: the dashboard was written"
  echo "$what: refused"
}

for study in tiny.h5 broken.h5; do
  runs="${study%.h5}_runs"
  ln -s elsewhere "$runs"
  expect_refused "$study: $runs a symbolic link" "'$runs': expected a folder to write into, got a symbolic link" "$study"
  rm "$runs"
  touch "$runs"
  expect_refused "$study: $runs a file" "'$runs': expected a folder to write into, got a file" "$study"
  rm "$runs"
  mkdir "$runs"
  cp elsewhere/victim.bin "$runs/tiny_0.html"
  expect_refused "$study: a run page over binary data" "'$runs/tiny_0.html': expected a regular file to write an HTML page to, got an existing file of another kind" "$study"
  rm "$runs/tiny_0.html"
  ln -s ../elsewhere/notes.txt "$runs/tiny_0.html"
  expect_refused "$study: a run page a symbolic link" "'$runs/tiny_0.html': expected a regular file to write an HTML page to, got a symbolic link" "$study"
  rm "$runs/tiny_0.html"
  cp elsewhere/victim.bin "$runs/wpg_viewer.js"
  expect_refused "$study: the shared script over binary data" "'$runs/wpg_viewer.js': expected a regular file to write a text file to" "$study"
  rm "$runs/wpg_viewer.js"
  mkfifo "$runs/tiny_0.html"
  expect_refused "$study: a run page a FIFO" "'$runs/tiny_0.html': expected a regular file to write an HTML page to, got a FIFO" "$study"
  rm "$runs/tiny_0.html"
  if [[ $(id -u) != 0 ]]; then
    chmod 555 "$runs"
    expect_refused "$study: $runs not writable" "'$runs' is not a writable directory" "$study"
    chmod 755 "$runs"
  else
    echo "$study: $runs not writable: not checked as root (root writes anyway)"
  fi
  rmdir "$runs"
done
# With good outputs, the missing run is what stops the broken study (nothing written either);
# a tree without the viewer bundle (the sanitizer tree) stops before, saying so.
"$wpg" view tiny.h5 -o probe/page.html >/dev/null 2>probe.err || true
if grep -q "the viewer is not built" probe.err; then
  rm -rf probe probe.err
  expect_refused "broken.h5: no bundle" "the viewer is not built" broken.h5
else
  rm -rf probe probe.err
  expect_refused "broken.h5: a missing run" "tiny_1" broken.h5
fi
[[ ! -e broken_runs ]] || [[ -z "$(ls -A broken_runs)" ]] || fail "broken.h5: run pages written"
echo "ok"
