"""check_large_data.py RUN_PAGE DASHBOARD OUT_DIR [N]: the pages of `wpg view` hold arrays of
any length the writer allows, and no page script passes an array's elements as the arguments
of a call (Math.max(...values) throws "RangeError: Maximum call stack size exceeded" beyond
about 10^5 of them).

The pages of a real short walk and a real 2-run batch are given synthetic large data, written
back beside them (large_run.html, large_dashboard.html), and opened in headless Chromium with
the network off:
- the run page: N NMPC iterations (an 800 s walk has 160 000) in its solve-time plot;
- the dashboard: N runs (the rows of its summary columns; every run finished, a swept key of 4
  values), drawn as box plots per value and in the table.
Each must publish data-wpg-ready with no console error, warning or exception. And a comparison
of 2 worlds x 12 variants with 45-character names (long_variants.html): every box's label is
cut to fit its slot (variant names side by side ran into each other). Exit 0 or 1.
"""
import base64
import json
import os
import re
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from headless_page import HeadlessChromium  # noqa: E402

READY = "document.body && document.body.dataset.wpgReady === '1'"
DATA = re.compile(r'(<script id="wpg-data" type="application/json">)(.*?)(</script>)', re.S)


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def floats(values):
    return base64.b64encode(np.asarray(values, dtype="<f4").tobytes()).decode()


def rewrite(source, target, change):
    text = open(source, encoding="utf-8").read()
    match = DATA.search(text)
    data = json.loads(match.group(2))
    change(data)
    # As the page writer escapes: nothing that could close the <script> element.
    body = json.dumps(data, separators=(",", ":")).replace("<", "\\u003c").replace(">", "\\u003e")
    open(target, "w", encoding="utf-8").write(text[:match.start(2)] + body + text[match.end(2):])
    print("%s: %.1f MB" % (target, os.path.getsize(target) / 1e6))


def main():
    run_page, dashboard, out = (os.path.abspath(a) for a in sys.argv[1:4])
    n = int(sys.argv[4]) if len(sys.argv) > 4 else 200000
    rng = np.random.default_rng(1)

    def many_iterations(data):
        end = float(np.frombuffer(base64.b64decode(data["time"]), dtype="<f4")[-1])
        data["mpc"] = {
            "time": floats(np.linspace(0.0, end, n)),
            "solve_time": floats(rng.uniform(1e-4, 3e-4, n)),
            "status": base64.b64encode(np.zeros(n, dtype=np.uint8).tobytes()).decode(),
        }

    def many_runs(data):
        # The columns the dashboard shows by default (the others left out: the page's size is
        # not what is tested here), each run a small top view (its CoM path, two points).
        keep = {"name", "exit_status", "blocked", "blocked_since", "path_length", "distance"}
        columns = []
        for column in data["columns"]:
            name, values = column["name"], column["values"]
            if name == "name":
                column["values"] = ["r%d" % i for i in range(n)]
            elif name.startswith("sweep."):
                column["values"] = [float(i % 4) for i in range(n)]
            elif name in ("path_length", "distance"):
                column["values"] = [round(float(v), 4) for v in rng.uniform(0.0, 1.0, n)]
            elif name in keep:
                column["values"] = [values[i % len(values)] for i in range(n)]
            else:
                continue
            columns.append(column)
        data["columns"] = columns
        runs = [r for r in data["runs"] if r]
        small = [dict(r["top"], obstacles=[],
                      path=floats(np.frombuffer(base64.b64decode(r["top"]["path"]), dtype="<f4")[:4]))
                 for r in runs]
        data["runs"] = [{"page": runs[i % len(runs)]["page"], "top": small[i % len(runs)]} for i in range(n)]

    def long_variant_names(data):
        # A comparison of 2 worlds x 12 variants with long names: each name must fit its box.
        variants = ["rrtconnect_nmpc_variant_with_a_long_name_%02d" % i for i in range(12)]
        worlds = ["field", "trap"]
        rows = [(w, v) for w in worlds for v in variants]
        runs = [r for r in data["runs"] if r]
        data.update(comparison=True, worlds=worlds, variants=variants, seeds=["1"])
        data["columns"] = [
            {"name": "name", "unit": "1", "values": ["%s.%s.1" % r for r in rows]},
            {"name": "sweep.world", "unit": "1", "values": [w for w, _ in rows]},
            {"name": "sweep.variant", "unit": "1", "values": [v for _, v in rows]},
            {"name": "sweep.seed", "unit": "1", "values": [1.0] * len(rows)},
            {"name": "goal_reached", "unit": "1", "values": [1.0] * len(rows)},
            {"name": "path_length", "unit": "m", "values": [float(i) for i in range(len(rows))]},
        ]
        data["runs"] = [runs[i % len(runs)] for i in range(len(rows))]

    large_run = os.path.join(os.path.dirname(run_page), "large_run.html")
    large_dashboard = os.path.join(os.path.dirname(dashboard), "large_dashboard.html")
    rewrite(run_page, large_run, many_iterations)
    rewrite(dashboard, large_dashboard, many_runs)
    variants_page = os.path.join(os.path.dirname(dashboard), "long_variants.html")
    rewrite(dashboard, variants_page, long_variant_names)
    with HeadlessChromium(1280, 1000) as browser:
        for path, what in ((large_run, "%d NMPC iterations" % n), (large_dashboard, "%d runs" % n)):
            page = browser.open("file://" + path + "#t=1&follow=0")
            # Drawn, or stopped by an exception (then it would never be drawn): no time limit
            # of this script's own decides (the test's timeout is the only one).
            folder = "file://" + os.path.dirname(path) + "/"
            while not page.evaluate("Boolean(%s)" % READY) and not page.problems(folder):
                time.sleep(0.2)
            problems = page.problems(folder)
            if problems:
                fail("%s: %s" % (what, "; ".join(problems)))
            page.screenshot(os.path.join(out, os.path.basename(path) + ".png"))
            print("%s: drawn, no error" % what)
        page = browser.open("file://" + variants_page)
        page.wait_for(READY)
        cells = page.evaluate("window.wpgDashboard.boxCells")
        wide = [c for c in cells if not c.get("labelWidth", 1e9) <= c["slot"]]
        if len(cells) != 24 or wide:
            fail("long variant names: %d boxes, labels wider than their slot: %s" % (len(cells), wide[:3]))
        page.screenshot(os.path.join(out, "long_variants.png"))
        print("24 variants with long names: every label within its box's slot")
    return 0


if __name__ == "__main__":
    sys.exit(main())
