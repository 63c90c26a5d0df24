"""check_figures.py CASE WPG WORKDIR: one property of the PNG figures of wpg, checked on the
matplotlib objects that plot_run.py and plot_compare.py build (their savefig is intercepted,
so the figures are inspected before they are written):

  route_colour     the top view of a walk to a goal: no route is drawn in the CoP's colour
                   (nor the CoM's)
  legend_clear     the legends of the top views (plot_run.py on goal_unknown_obstacle and
                   obstacle_cluttered, plot_compare.py's top_<world>) cover no obstacle nor
                   its margin
  solve_outlier    one NMPC iteration of 10 ms among 9 to 11 µs ones: the solve-time panel's scale
                   still shows the typical iteration (top below 5 times the 98th percentile)
                   and says that an iteration is above it, with its value
  goal_missed      "goal missed" is in the legend of a comparison's top view exactly when a
                   run drawn there missed the goal
  cropped          plot_run.py's figures (the largest legend, the Fig. 6 row, two runs, the
                   --plan figure) fit on their canvas, drawn once: the PNG is the drawing with
                   0.1 in of background round it, never savefig's second, tight pass
Exit 0, or 1 naming what is wrong.
"""
import os
import subprocess
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.colors as mcolors  # noqa: E402
import matplotlib.figure  # noqa: E402
import numpy as np  # noqa: E402

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "analysis"))


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def wpg(*args):
    result = subprocess.run([WPG, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if result.returncode not in (0, 1):
        fail("wpg %s: exit status %d: %s" % (" ".join(args), result.returncode, result.stderr))


def run_figure(path):
    """plot_run.py's figure of `path` (drawn, not written)."""
    from run_figure.figure import draw
    from run_figure.reading import read_runs
    fig = draw(read_runs(path), path)
    fig.canvas.draw()
    return fig


def compare_figures(study_file, out):
    """The figures plot_compare.py draws for `study_file`, by file name."""
    import plot_compare
    figures = {}
    original = matplotlib.figure.Figure.savefig

    def capture(self, path, *args, **kwargs):
        self.canvas.draw()
        figures[os.path.basename(path)] = self

    matplotlib.figure.Figure.savefig = capture
    argv = sys.argv
    sys.argv = ["plot_compare.py", study_file, "-o", out]
    try:
        plot_compare.plt.close = lambda *a, **k: None  # keep the figures open for the checks
        # The script saves through save_figure (a temporary file renamed): capture its figures.
        plot_compare.save_figure = lambda fig, output, **kwargs: capture(fig, output)
        plot_compare.main()
    finally:
        matplotlib.figure.Figure.savefig = original
        sys.argv = argv
    return figures


def top_axes(fig):
    return [ax for ax in fig.axes if ax.get_title().startswith("top view")]


def same_colour(a, b):
    return np.allclose(mcolors.to_rgba(a)[:3], mcolors.to_rgba(b)[:3])


def route_colour(work):
    wpg("run", "goal_unknown_obstacle", "--no-plot", "-o", os.path.join(work, "goal.h5"))
    fig = run_figure(os.path.join(work, "goal.h5"))
    ax = top_axes(fig)[0]
    legend = ax.get_legend()
    handles = {t.get_text(): h for t, h in zip(legend.get_texts(), getattr(legend, 'legend_handles', None) or legend.legendHandles)}
    cop = handles["CoP"].get_color()
    com = handles["CoM"].get_color()
    routes = {label: h.get_color() for label, h in handles.items() if label.startswith("route")}
    if len(routes) < 2:
        fail("expected at least two routes (a replan) in goal_unknown_obstacle, got %s" % list(routes))
    for label, colour in routes.items():
        if same_colour(colour, cop) or same_colour(colour, com):
            fail("%s is drawn in %s, the colour of the %s" % (label, colour, "CoP" if same_colour(colour, cop) else "CoM"))
    print("routes %s, CoP %s, CoM %s: all different" % (routes, cop, com))


def obstacle_boxes(ax):
    """Window extents of the obstacle patches (and margins) of a top view."""
    boxes = []
    for patch in ax.patches:
        edge = mcolors.to_rgba(patch.get_edgecolor())[:3]
        if np.allclose(edge, mcolors.to_rgba("0.35")[:3]):  # OBSTACLE_COLOUR of both scripts
            boxes.append(patch.get_window_extent())
    return boxes


def check_legend_clear(name, ax):
    legend = ax.get_legend()
    if legend is None:
        fail("%s: no legend" % name)
    box = legend.get_window_extent()
    obstacles = obstacle_boxes(ax)
    if not obstacles:
        fail("%s: no obstacle drawn" % name)
    for obstacle in obstacles:
        if box.overlaps(obstacle):
            fail("%s: the legend %s covers an obstacle %s" % (name, box.bounds, obstacle.bounds))
    print("%s: the legend covers none of its %d obstacle patches" % (name, len(obstacles)))


SCENARIOS_WITH_OBSTACLES = ("goal_unknown_obstacle", "goal_u_trap", "goal_cluttered", "goal_with_yaw",
                            "obstacle_cluttered", "obstacle_boxes", "obstacle_polygon")


def legend_clear(work):
    for scenario in SCENARIOS_WITH_OBSTACLES:
        path = os.path.join(work, scenario + ".h5")
        wpg("run", scenario, "--no-plot", "-o", path)
        check_legend_clear(scenario, top_axes(run_figure(path))[0])
    study = os.path.join(SOURCE, "tests", "cli", "studies", "compare_small.yaml")
    wpg("compare", study, "-o", os.path.join(work, "study"), "--no-plot", "-j", "2")
    figures = compare_figures(os.path.join(work, "study", "study.h5"), os.path.join(work, "study"))
    for name, fig in figures.items():
        if name.startswith("top_"):
            check_legend_clear(name, fig.axes[0])


def solve_outlier(work):
    path = os.path.join(work, "walk.h5")
    wpg("run", "walk_forward", "--no-plot", "--set", "duration=6", "-o", path)
    with h5py.File(path, "r+") as f:
        # Solve times are wall times: set them (9 to 11 µs, deterministic) so that the check
        # does not depend on the machine's load, then one iteration of 10 ms.
        solve = f["runs/walk_forward/mpc/solve_time"]
        values = 1e-5 * (1.0 + 0.1 * np.sin(np.arange(len(solve))))
        values[len(values) // 2] = 0.010
        solve[...] = values
    typical = 1e6 * np.percentile(np.delete(values, len(values) // 2), 98)
    fig = run_figure(path)
    ax = next(ax for ax in fig.axes if ax.get_ylabel().startswith("solve"))
    top = ax.get_ylim()[1]
    if not top < 5 * typical:
        fail("the solve-time scale goes to %.0f µs for a typical iteration of %.1f µs (98th "
             "percentile): the 10 ms outlier squashes it" % (top, typical))
    texts = " ".join(t.get_text() for t in ax.texts) + " " + ax.get_title()
    if "10.0 ms" not in texts and "10000 µs" not in texts:
        fail("the panel does not say that an iteration of 10.0 ms is above its scale: %r" % texts)
    print("scale up to %.1f µs (typical %.1f µs); the outlier is named: %r" % (top, typical, texts))


def goal_missed(work):
    all_reached = os.path.join(work, "reached.yaml")
    with open(os.path.join(SOURCE, "tests", "cli", "studies", "compare_small.yaml")) as f:
        text = f.read()
    # The same study without the variant that misses the goal.
    text = text.replace("  nmpc_only: {planner.algorithm: none}\n", "")
    with open(all_reached, "w") as f:
        f.write(text.replace("name: compare_small", "name: compare_reached"))
    for study, expect in ((all_reached, False),
                          (os.path.join(SOURCE, "tests", "cli", "studies", "compare_small.yaml"), True)):
        out = os.path.join(work, os.path.splitext(os.path.basename(study))[0])
        wpg("compare", study, "-o", out, "--no-plot", "-j", "2")
        with h5py.File(os.path.join(out, "study.h5"), "r") as f:
            missed = int(np.sum(f["batch/summary/goal_reached"][()] != 1))
        if (missed > 0) != expect:
            fail("%s: %d runs missed the goal, expected %s" % (study, missed, "some" if expect else "none"))
        for name, fig in compare_figures(os.path.join(out, "study.h5"), out).items():
            if not name.startswith("top_"):
                continue
            labels = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
            if ("goal missed" in labels) != expect:
                fail("%s %s: legend %s with %d runs that missed the goal" % (study, name, labels, missed))
            print("%s %s: legend %s (%d runs missed the goal)" % (os.path.basename(study), name, labels, missed))


def cropped(work):
    import matplotlib.image
    from run_figure.figure import draw, save_atomically
    from run_figure.reading import read_runs
    import plot_run
    walks = {"goal": ("goal_unknown_obstacle",), "filtered": ("walk_forward", "--filter", "--set",
                                                              "duration=6")}
    for name, args in walks.items():
        wpg("run", *args, "--no-plot", "-o", os.path.join(work, name + ".h5"))
    wpg("batch", os.path.join(SOURCE, "tests", "cli", "studies", "tiny_batch.yaml"), "--no-plot",
        "-o", os.path.join(work, "two.h5"))
    two_pass = []
    original = matplotlib.figure.Figure.savefig
    matplotlib.figure.Figure.savefig = lambda self, *a, **k: two_pass.append(1) or original(
        self, *a, **k)
    try:
        for name, plan in (("goal", False), ("filtered", False), ("two", False), ("goal", True)):
            path = os.path.join(work, name + ".h5")
            runs = read_runs(path)
            fig = plot_run.draw_plan(runs, path, []) if plan else draw(runs, path)
            png = os.path.join(work, name + (".plan" if plan else "") + ".png")
            save_atomically(fig, png, path)
            if two_pass:
                fail("%s: the drawing does not fit on its canvas: written by the tight pass" % png)
            image = matplotlib.image.imread(png)
            drawn = np.any(image != image[0, 0], axis=2)
            pad = int(round(0.1 * 110))
            if drawn[:pad].any() or drawn[-pad:].any() or drawn[:, :pad].any() \
                    or drawn[:, -pad:].any():
                fail("%s: drawn within %d px of its border" % (png, pad))
            for side, line in (("top", drawn[pad]), ("bottom", drawn[-pad - 1]),
                               ("left", drawn[:, pad]), ("right", drawn[:, -pad - 1])):
                if not line.any():
                    fail("%s: more than %d px of background on the %s" % (png, pad, side))
            print("%s: %d x %d px, drawn once and cropped" % (os.path.basename(png), *image.shape[1::-1]))
    finally:
        matplotlib.figure.Figure.savefig = original


CASES = {"route_colour": route_colour, "legend_clear": legend_clear,
         "solve_outlier": solve_outlier, "goal_missed": goal_missed, "cropped": cropped}

if __name__ == "__main__":
    case, WPG, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.environ["WPG_DATA_DIR"] = SOURCE
    os.makedirs(work, exist_ok=True)
    CASES[case](work)
