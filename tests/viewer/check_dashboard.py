"""check_dashboard.py PAGE.html STUDY.h5 OUT_DIR: the dashboard of a study (`wpg view`) in
headless Chromium with the network off.

- no console error, warning or exception, no request outside the page's folder;
- a comparison study: the box plots and the success rates draw every world x variant of the
  file's /compare attributes, each with all its seeds, and a top view per world x seed, its
  caption "seed S · R/N reached" (words apart, as read aloud or copied) with the seed and
  the count of the file's goal_reached for that world and seed, then " · B blocked" when B > 0
  of its runs ended blocked (the summary's `blocked`);
  a batch: a top view per run;
- every run of /batch/summary has its page beside the dashboard (PAGE_runs/<run>.html), and
  the first one opens without error at #t=1 (its script, shared in PAGE_runs/, is found).
The screenshot of the dashboard is kept in OUT_DIR/dashboard.png. Exit 0, or 1 with the reasons.
"""
import os
import re
import sys

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from headless_page import HeadlessChromium  # noqa: E402

READY = "document.body && document.body.dataset.wpgReady === '1'"


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def check_batch_views(browser, page, page_path, study, folder):
    """A batch's metric and view are in the URL; its default metric is a tracking one; two
    swept keys give a heatmap whose cells are the medians of the file's runs."""
    import numpy as np
    state = page.evaluate("[window.wpgDashboard.metric, window.wpgDashboard.view, window.location.hash]")
    if state[0] != "velocity_error_rms" or "metric=velocity_error_rms" not in state[2]:
        fail("batch default: metric %s, URL %s (expected velocity_error_rms, in the URL)" % (state[0], state[2]))
    with h5py.File(study, "r") as f:
        s = f["batch/summary"]
        keys = [k.decode() if isinstance(k, bytes) else k for k in f.attrs["swept_keys"]]
        x_key, y_key = "sweep." + keys[1], "sweep." + keys[-1]
        xs, ys, metric = s[x_key][()], s[y_key][()], s["cop_margin_min"][()]
    view = "heatmap:%s:%s" % (x_key, y_key)
    page = browser.open("file://%s#metric=cop_margin_min&view=%s" % (page_path, view))
    page.wait_for(READY)
    problems = page.problems(folder)
    if problems:
        fail("heatmap: " + "; ".join(problems))
    drawn = page.evaluate("window.wpgDashboard")
    if (drawn["metric"], drawn["view"]) != ("cop_margin_min", view):
        fail("the URL's metric and view not shown: %s, %s" % (drawn["metric"], drawn["view"]))
    cells = drawn["heatCells"]
    pairs = {(float(x), float(y)) for x, y in zip(xs, ys)}
    # The page's numbers have 9 significant digits (page_json.hpp).
    near = lambda a, b: np.abs(a - b) <= 1e-8 * np.maximum(1.0, np.abs(b))
    if len(cells) != len(pairs) or sum(c["n"] for c in cells) != len(xs):
        fail("heatmap: %d cells of %d runs, expected %d pairs of %d runs"
             % (len(cells), sum(c["n"] for c in cells), len(pairs), len(xs)))
    for c in cells:
        want = np.median(metric[near(xs, c["x"]) & near(ys, c["y"])])
        if not near(c["median"], want):
            fail("heatmap cell %s: median %r, the file's %r" % (c, c["median"], want))
    print("heatmap %s x %s: %d cells, medians as the file's; metric and view from the URL"
          % (x_key, y_key, len(cells)))


def main():
    page_path, study, out = (os.path.abspath(a) for a in sys.argv[1:4])
    folder = "file://" + os.path.dirname(page_path) + "/"
    with h5py.File(study, "r") as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["batch/summary/name"][()]]
        comparison = "compare" in f
        if comparison:
            worlds = [str(w) for w in f["compare"].attrs["worlds"]]
            variants = [str(v) for v in f["compare"].attrs["variants"]]
            seeds = len(f["compare"].attrs["seeds"])
            summary = f["batch/summary"]
            text = lambda column: [v.decode() if isinstance(v, bytes) else str(v) for v in summary[column][()]]
            # (world, seed) -> [runs that reached the goal, runs, runs that ended blocked], in the
            # study's order.
            captions = {}
            for world, seed, reached, blocked in zip(text("sweep.world"), text("sweep.seed"),
                                                     summary["goal_reached"][()],
                                                     summary["blocked"][()]):
                counts = captions.setdefault((world, float(seed)), [0, 0, 0])
                counts[0] += int(reached == 1)
                counts[1] += 1
                counts[2] += int(blocked == 1)
    runs_folder = os.path.splitext(page_path)[0] + "_runs"
    for name in names:
        if not os.path.isfile(os.path.join(runs_folder, name + ".html")):
            fail("no run page for %s in %s" % (name, runs_folder))
    print("%d run pages in %s" % (len(names), runs_folder))
    # The size budget of a study's pages (docs/viewer.md): at most 25 kB per second walked
    # by its runs (a page of a run not replayed), plus the shared script and the dashboard.
    with h5py.File(study, "r") as f:
        walked = float(sum(f["batch/summary/duration"][()]))
    pages = sum(os.path.getsize(os.path.join(runs_folder, n)) for n in os.listdir(runs_folder)
                if n.endswith(".html"))
    print("run pages: %.2f MB for %.0f s walked (%.1f kB/s), the dashboard %.2f MB, the script %.2f MB"
          % (pages / 1e6, walked, pages / walked / 1e3, os.path.getsize(page_path) / 1e6,
             os.path.getsize(os.path.join(runs_folder, "wpg_viewer.js")) / 1e6))
    if pages > 25e3 * walked:
        fail("the run pages are %.1f kB per second walked, over the budget of 25" % (pages / walked / 1e3))

    with HeadlessChromium(1280, 2000) as browser:
        page = browser.open("file://" + page_path)
        page.wait_for(READY)
        page.screenshot(os.path.join(out, "dashboard.png"))
        drawn = page.evaluate("window.wpgDashboard")
        problems = page.problems(folder)
        if problems:
            fail("dashboard: " + "; ".join(problems))
        if comparison:
            expected = [(w, v) for w in worlds for v in variants]
            for key in ("boxCells", "rateCells"):
                cells = [(c["group"], c["label"]) for c in drawn[key]]
                if cells != expected:
                    fail("%s: drew %s, expected every world x variant %s" % (key, cells, expected))
            totals = [c["total"] for c in drawn["rateCells"]]
            boxes = [c["n"] + c["missing"] for c in drawn["boxCells"]]
            if totals != [seeds] * len(expected) or boxes != [seeds] * len(expected):
                fail("runs per cell: rates %s, boxes %s, expected %d each" % (totals, boxes, seeds))
            if drawn["topViews"] != len(worlds) * seeds:
                fail("%d top views, expected %d (world x seed)" % (drawn["topViews"], len(worlds) * seeds))
            print("every world x variant drawn: %s, %d seeds each; %d top views"
                  % (", ".join("%s/%s" % c for c in expected), seeds, drawn["topViews"]))
            shown = page.evaluate("Array.from(document.querySelectorAll('.top-view .caption'))"
                                  ".map((c) => c.textContent)")
            want = list(captions.items())
            if len(shown) != len(want):
                fail("%d top-view captions, expected %d" % (len(shown), len(want)))
            for caption, ((world, seed), (reached, runs, blocked)) in zip(shown, want):
                match = re.fullmatch(r"seed (\S+) · (\d+)/(\d+) reached( · (\d+) blocked)?", caption)
                if not match or float(match.group(1)) != seed or \
                        (int(match.group(2)), int(match.group(3))) != (reached, runs) or \
                        int(match.group(5) or 0) != blocked or match.group(5) == "0":
                    fail("the top view of %s, seed %g: caption %r, expected 'seed %g · %d/%d "
                         "reached' and %d blocked" % (world, seed, caption, seed, reached, runs, blocked))
            print("top-view captions: %s" % "; ".join(shown))
            # Variant names side by side never run into each other: each fits its slot.
            wide = [c for c in drawn["boxCells"] if c["labelWidth"] > c["slot"]]
            if wide:
                fail("box labels wider than their slot: %s" % wide)
        elif drawn["topViews"] != min(len(names), 240):
            fail("%d top views, expected one per run (%d)" % (drawn["topViews"], len(names)))
        else:
            print("%d runs, a top view each" % len(names))
            check_batch_views(browser, page, page_path, study, folder)

        run_page = os.path.join(runs_folder, names[0] + ".html")
        page = browser.open("file://" + run_page + "#t=1")
        page.wait_for(READY)
        problems = page.problems("file://" + runs_folder + "/")
        if problems:
            fail("%s: %s" % (run_page, "; ".join(problems)))
        back = page.evaluate("document.querySelector('#top a.back').getAttribute('href')")
        if back != "../" + os.path.basename(page_path):
            fail("%s: the link back is %s" % (run_page, back))
        print("%s opens at #t=1 without error, links back to %s" % (os.path.basename(run_page), back))
    return 0


if __name__ == "__main__":
    sys.exit(main())
