#!/usr/bin/env bash
# shard_merge.sh WPG STUDY OTHER_STUDY: a study split into slices without MPI:
#  - `wpg batch --shard K/3` for K = 0, 1, 2 and `wpg merge` give an index whose runs are, bit for
#    bit (wall times aside, compare_batch_files.py), those of `wpg batch -j 1`, through relative
#    external links: still so after the folder is moved; `wpg analyze` and `wpg diff` read it;
#  - `wpg merge --copy` of the shard folder gives one self-contained file, the same contents;
#  - a shard resumes as its own slice only; a complete shard resumed runs nothing;
#  - bad input: a missing slice, a shard of another study, the index over a shard: exit 2, one
#    line naming the problem, nothing written.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"; study="$2"; other="$3"
make_workdir
cd "$WORKDIR"

"$wpg" batch "$study" -o one.h5 -j 1 --no-plot >/dev/null 2>&1 || fail "batch -j 1: exit $?"
total="$("$PYTHON" -c "import h5py,sys; print(h5py.File(sys.argv[1])['batch/summary/done'].size)" one.h5)"
for k in 0 1 2; do
  "$wpg" batch "$study" -o "shards/part-$k.h5" --shard "$k/3" -j 2 >stdout 2>stderr ||
    fail "--shard $k/3: exit $? ($(cat stderr))"
  grep -q "shard $k/3: " stdout || fail "--shard $k/3: $(cat stdout)"
done
# Slice k holds the runs i with i mod 3 = k, and only them: its table has their rows only
# (a slice of a study of 10^7 runs starts as quickly as one of 10), its `index` names them.
"$PYTHON" - "$total" shards/part-*.h5 <<'PY' || fail "the slices do not hold runs i mod 3 = k"
import sys, h5py
total = int(sys.argv[1])
for k, path in enumerate(sys.argv[2:]):
    with h5py.File(path, "r") as f:
        assert f.attrs["shard"] == f"{k}/3", f.attrs["shard"]
        assert f.attrs["run_count"] == total, f.attrs["run_count"]
        index, done = f["batch/summary/index"][:], f["batch/summary/done"][:]
        assert list(index) == list(range(k, total, 3)), index
        assert done.all(), done
        names = [n.decode() for n in f["batch/summary/name"][:]]
        assert sorted(f["runs"]) == sorted(names), (list(f["runs"]), names)
PY

"$wpg" merge index.h5 shards/part-0.h5 shards/part-1.h5 shards/part-2.h5 --no-plot >stdout 2>stderr ||
  fail "merge: exit $? ($(cat stderr))"
[[ -s index.summary.csv && -s index.summary.md ]] || fail "no summary.csv/.md beside the index"
oracle compare_batch_files.py one.h5 index.h5 || fail "merged shards differ from -j 1"
"$PYTHON" - index.h5 <<'PY' || fail "the index does not link its runs with relative paths"
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    assert "shard" not in f.attrs
    for name in f["runs"]:
        link = f["runs"].get(name, getlink=True)
        assert isinstance(link, h5py.ExternalLink), (name, link)
        assert link.filename.startswith("shards/part-"), link.filename
        assert link.path == "/runs/" + name
PY
"$wpg" analyze index.h5 --format csv >metrics.csv || fail "wpg analyze of the index: exit $?"
[[ "$(($(wc -l <metrics.csv) - 1))" == "$total" ]] || fail "analyze of the index: not $total rows"
"$wpg" diff one.h5 index.h5 >/dev/null || fail "wpg diff one.h5 index.h5: exit $?"

# The folder moved elsewhere, read from another working directory: the links still resolve.
mkdir moved && mv index.h5 shards moved/
(cd / && oracle compare_batch_files.py "$WORKDIR/one.h5" "$WORKDIR/moved/index.h5") ||
  fail "the moved index does not read as before"

"$wpg" merge flat.h5 moved/shards --copy --no-plot >/dev/null 2>&1 || fail "merge --copy: exit $?"
oracle compare_batch_files.py one.h5 flat.h5 || fail "merge --copy differs from -j 1"
"$PYTHON" -c "
import sys, h5py
f = h5py.File(sys.argv[1], 'r')
assert all(isinstance(f['runs'].get(n, getlink=True), h5py.HardLink) for n in f['runs'])" flat.h5 ||
  fail "merge --copy left links"

# Resume: a complete shard runs nothing; another slice, or a whole batch, is refused.
"$wpg" batch "$study" -o moved/shards/part-1.h5 --shard 1/3 --resume >/dev/null 2>stderr ||
  fail "--resume of a complete shard: exit $?"
grep -q "resuming, $(( (total + 2) / 3 )) of" stderr || fail "--resume of a shard: $(cat stderr)"
before="$(md5sum <moved/shards/part-1.h5)"
status=0
"$wpg" batch "$study" -o moved/shards/part-1.h5 --shard 2/3 --resume >/dev/null 2>stderr || status=$?
[[ $status == 2 && "$(wc -l <stderr)" == 1 ]] || fail "resume as another slice: exit $status, $(cat stderr)"
grep -q "shard 1/3, not shard 2/3" stderr || fail "resume as another slice: $(cat stderr)"
[[ "$(md5sum <moved/shards/part-1.h5)" == "$before" ]] || fail "resume as another slice changed the shard"

# Bad input to merge: exit 2, one line, nothing written (no index, no temporary file).
"$wpg" batch "$other" -o other.h5 --shard 0/1 --no-plot >/dev/null 2>&1 || fail "other study: exit $?"
expect_refused() {  # expect_refused EXPECTED ARGS...
  local expected="$1"; shift
  ls -A moved >before.list
  status=0
  "$wpg" merge "$@" >stdout 2>stderr || status=$?
  echo "merge $*: $(cat stderr)"
  [[ $status == 2 ]] || fail "merge $*: exit $status, expected 2"
  [[ "$(wc -l <stderr)" == 1 ]] || fail "merge $*: not one line on stderr"
  grep -qF -- "$expected" stderr || fail "merge $*: stderr does not name '$expected'"
  [[ ! -e moved/bad.h5 && ! -e moved/bad.summary.csv ]] || fail "merge $*: wrote an index"
  ls -A moved | diff - before.list >/dev/null || fail "merge $*: files added to moved/"
}
expect_refused "missing or unfinished shards: 1/3" moved/bad.h5 moved/shards/part-0.h5 moved/shards/part-2.h5
expect_refused "other_study" moved/bad.h5 moved/shards/part-0.h5 moved/shards/part-1.h5 \
  moved/shards/part-2.h5 other.h5
expect_refused "no such shard file" moved/bad.h5 moved/shards/part-0.h5 moved/shards/part-9.h5
before="$(md5sum <moved/shards/part-0.h5)"
expect_refused "part-0.h5" moved/shards/part-0.h5 moved/shards/part-0.h5 moved/shards/part-1.h5 \
  moved/shards/part-2.h5
[[ "$(md5sum <moved/shards/part-0.h5)" == "$before" ]] || fail "merge over a shard changed it"
echo "ok"
