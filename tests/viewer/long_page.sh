#!/usr/bin/env bash
# long_page.sh WPG: a replayed walk longer than a page holds at full rate (150 s: 30001 samples
# of 54 numbers, above the 1.5 million of kMaxPageFloats) is decimated evenly: the page says
# "one sample in 2 shown", stays under 8 MB, keeps the walk's last instant, and opens without
# error (check_run_page.py at #t=0 and #t=6).
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
require_chromium
make_workdir
"$wpg" run walk_forward --replay --no-plot --set duration=150 -o "$WORKDIR/long.h5" >/dev/null \
  || fail "run: exit status $?"
"$wpg" view "$WORKDIR/long.h5" >/dev/null || fail "view: exit status $?"
grep -qF "one sample in 2 shown" "$WORKDIR/long.html" || fail "the page does not say it is decimated"
size=$(stat -c %s "$WORKDIR/long.html")
((size < 8000000)) || fail "the page is $size bytes"
"$PYTHON" - "$WORKDIR/long.html" <<'PY' || fail "the decimated times"
import base64, json, re, sys
import numpy as np
text = open(sys.argv[1]).read()
data = json.loads(re.search(r'<script id="wpg-data" type="application/json">(.*?)</script>', text, re.S).group(1))
time = np.frombuffer(base64.b64decode(data["time"]), dtype="<f4")
assert data["decimation"] == 2, data["decimation"]
assert len(time) == 15001, len(time)                       # 0, 0.01, ..., 150 s
assert abs(time[-1] - 150.0) < 1e-3 and np.allclose(np.diff(time), 0.01, atol=1e-4)
q = np.frombuffer(base64.b64decode(data["q"]["values"]), dtype="<f4")
assert len(q) == len(time) * len(data["q"]["names"])
print("%d samples kept of 30001, every 0.01 s, the last at %.3f s" % (len(time), time[-1]))
PY
"$PYTHON" "$VIEWER_TESTS/check_run_page.py" "$WORKDIR/long.html" "$WORKDIR" || fail "the page of 150 s"
echo "ok: $size bytes"
