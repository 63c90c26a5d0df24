#!/usr/bin/env bash
# soak_batch.sh WPG [RUNS] [KILLS]: a soak test of `wpg batch` (not in ctest's default run: it
# takes minutes). A study of RUNS walks (default 1000, 2 s each) is run once uninterrupted,
# then again with KILLS (default 50) random SIGKILL/SIGTERM interruptions, each followed by
# `--resume`, while `wpg analyze` reads the file concurrently. The resumed file must equal the
# uninterrupted one (every field but the wall times, tests/cli/compare_batch_files.py); every
# reader ends with exit 0 or 2 (a file in use or mid-write), never a crash or a hang; a resume
# that finds the file in use by a reader is refused (exit 2) and retried.
set -euo pipefail
wpg="$(readlink -f "$1")"
runs="${2:-1000}"
kills="${3:-50}"
here="$(cd "$(dirname "$0")" && pwd)"
python="${WPG_PYTHON:-/usr/bin/python3}"
export WPG_DATA_DIR="${WPG_DATA_DIR:-$(cd "$here/.." && pwd)}"
work="$(mktemp -d "${TMPDIR:-/tmp}/wpg-soak.XXXXXX")"
trap 'kill $(jobs -p) 2>/dev/null || true' EXIT
cd "$work"
values="$("$python" -c "print(', '.join(str(300 + i) for i in range($runs)))")"
cat >soak.yaml <<YAML
name: soak
base: {robot: hrp2, duration: 2.0, generator: {algorithm: nmpc, sqp_iterations: 1},
       reference: [{t: 0.0, v: [0.2, 0.0, 0.0]}]}
sweep: {grid: {walking.weight_cop: [$values]}}
YAML
"$wpg" batch soak.yaml -o reference.h5 -j 2 --no-plot >/dev/null 2>&1
killed=0 refused=0 readers=0 reader_errors=0
first=1 rounds=0
while (( rounds++ < 4 * kills + 20 )); do
  args=(batch soak.yaml -o soak.h5 -j 2 --no-plot)
  [[ $first == 1 ]] || args+=(--resume)
  "$wpg" "${args[@]}" >batch.out 2>batch.err &
  pid=$!
  # a concurrent reader, and a kill after a random delay (while kills remain)
  ( s=0; timeout 60 "$wpg" analyze soak.h5 >/dev/null 2>reader.err || s=$?; echo "$s" >reader.status ) &
  reader=$!
  if (( killed < kills )); then
    sleep "$("$python" -c "import random; print(round(random.uniform(0.05, 1.5), 3))")"
    if kill -0 "$pid" 2>/dev/null; then
      signal=$([[ $((RANDOM % 2)) == 0 ]] && echo KILL || echo TERM)
      kill -s "$signal" "$pid" 2>/dev/null && killed=$((killed + 1))
    fi
  fi
  status=0
  wait "$pid" || status=$?
  wait "$reader" || true
  readers=$((readers + 1))
  reader_status="$(cat reader.status)"
  case "$reader_status" in
    0 | 2) ;;
    *) echo "reader: exit $reader_status ($(cat reader.err))" >&2; reader_errors=$((reader_errors + 1)) ;;
  esac
  first=0
  if [[ $status == 0 ]]; then
    (( killed >= kills )) && break
    rm -f soak.h5 soak.summary.*; first=1  # finished before the kill: start another round
    continue
  fi
  if [[ $status == 2 ]]; then
    grep -q "in use" batch.err || { echo "batch: $(cat batch.err)" >&2; exit 1; }
    refused=$((refused + 1))
  fi
done
"$python" "$here/cli/compare_batch_files.py" reference.h5 soak.h5 >/dev/null 2>diff.err && same=yes || same=no
echo "runs $runs, kills $killed, resumes refused while in use $refused, readers $readers" \
     "(crashed or hung: $reader_errors), resumed file equals the uninterrupted one: $same"
[[ $same == yes && $reader_errors == 0 ]] || { echo "kept $work" >&2; exit 1; }
rm -rf "$work"
