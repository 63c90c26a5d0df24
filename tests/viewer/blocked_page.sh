#!/usr/bin/env bash
# blocked_page.sh WPG: the page of a walk that ended blocked (the shipped obstacle_wall) says so
# in its header, where and since when ("blocked since t = 8.9 s at (1.29, -0.01) m", the
# dataset's blocked_since, blocked_x, blocked_y), not "success", and opens without error; the
# page of a walk that made progress says "success".
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"
wpg="$1"
require_chromium
make_workdir
status=0
"$wpg" run obstacle_wall --no-plot -o "$WORKDIR/wall.h5" >/dev/null 2>&1 || status=$?
[[ $status == 1 ]] || fail "run obstacle_wall: exit status $status, expected 1 (blocked)"
"$wpg" run walk_forward --no-plot --set duration=4 -o "$WORKDIR/walk.h5" >/dev/null \
  || fail "run walk_forward: exit status $?"
"$wpg" view "$WORKDIR/wall.h5" -o "$WORKDIR/wall.html" >/dev/null || fail "view: exit status $?"
"$wpg" view "$WORKDIR/walk.h5" -o "$WORKDIR/walk.html" >/dev/null || fail "view: exit status $?"
"$PYTHON" - "$WORKDIR" "$VIEWER_TESTS" <<'PY' || fail "the page headers"
import os
import sys
sys.path.insert(0, sys.argv[2])
from headless_page import HeadlessChromium
folder = sys.argv[1]
READY = "document.body && document.body.dataset.wpgReady === '1'"
with HeadlessChromium() as browser:
    for name, want, not_want in (("wall", "· blocked since t = 8.9 s at (1.29, -0.01) m", "success"),
                                 ("walk", "· success", "blocked")):
        # Paused at the start (#t=0): a page opened without a time plays the walk first and
        # publishes wpgReady when it stops, 30 s of waiting for the wall's walk.
        page = browser.open("file://" + os.path.join(folder, name + ".html") + "#t=0")
        page.wait_for(READY)
        subtitle = page.evaluate("document.querySelector('#top .subtitle').textContent")
        assert want in subtitle and not_want not in subtitle, (name, subtitle)
        problems = page.problems("file://" + folder + "/")
        assert not problems, (name, problems)
        print("%s: %s" % (name, subtitle))
PY
echo "ok"
