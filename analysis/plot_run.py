#!/usr/bin/python3
"""Draw the figure of a wpg run dataset (HDF5, datasets/SCHEMA.md) as one PNG.

For every group under /runs/: on the left the top view (every footstep as an oriented sole
rectangle centred on the ankle, the CoM and CoP paths, equal axes); on the right CoM and CoP
x and y against time, and the NMPC solve time per iteration over the support phases. When the
run was replayed on the multibody model (`zmp_multibody`, `wpg run --filter`, `wpg replay`),
a bottom row draws the analogue of the paper's Fig. 6: reference CoP (solid blue), multibody
ZMP before the dynamic filter (dash-dot red) and after it (dashed green) for x and y over a
few seconds of steady walking, and the distance |CoP - ZMP| over the whole walk, with the
filter that ran (online: the loop of Fig. 3, or offline) and, for filter_settings.mode both,
the offline pass's errors beside the online ones.

    /usr/bin/python3 plot_run.py RUN.h5 [-o FIG.png] [--run NAME]
    /usr/bin/python3 plot_run.py RUN.h5 --plan [--at T ...] [-o FIG.png] [--run NAME]

With --plan, the figure is predicted against executed instead (run_figure/plan_figure.py): what
the NMPC previewed (mpc/plan/) at the iterations at or before the times of --at (default four
spread over the walk) beside the walk, and the prediction error against the look-ahead.

Needs Debian's python3-h5py and python3-matplotlib (run it with /usr/bin/python3: a pyenv
python3 does not see them). The PNG is written atomically (temporary file, then rename).
Every dataset and attribute it uses is checked (wpg_file_reading.py: shapes, types, finite
numbers, sizes bounded before reading); the stored scenario is parsed with PyYAML. A bad file
gives one line on stderr, `plot_run.py: FILE: /path: expected ...` (after `wpg: error: ` under
`wpg plot`), and exit status 2; never a traceback.

The panels are drawn by the package run_figure/ beside this script, one module per part of
the figure (its __init__.py lists them).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wpg_file_reading import BadFile, import_h5py, run_script  # noqa: E402

SCRIPT = "plot_run.py"
PROG = os.environ.get("WPG_PLOT_PROG") or os.path.basename(sys.argv[0])

import_h5py(SCRIPT)
try:
    import numpy  # noqa: F401
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import yaml  # noqa: F401  (python3-yaml: the stored scenario is read with it)
except ImportError as error:
    from wpg_file_reading import report
    report(SCRIPT, "plotting needs h5py, matplotlib and PyYAML for %s (%s): install the Debian "
           "packages python3-h5py python3-matplotlib python3-yaml" % (sys.executable, error))
    sys.exit(2)

from run_figure.figure import draw, figure_with_legend_room, save_atomically  # noqa: E402
from run_figure.plan_figure import draw_plan_figure  # noqa: E402
from run_figure.plan_reading import read_plan  # noqa: E402
from run_figure.reading import read_runs  # noqa: E402
from run_figure.scenario_text import scenario_obstacles, scenario_pushes  # noqa: E402
from run_figure.styles import DEFAULT_FOOT_LENGTH, DEFAULT_FOOT_WIDTH  # noqa: E402
from wpg_file_reading import walking_number  # noqa: E402


def draw_plan(runs, path, at_times):
    """The predicted-against-executed figure of the file's one run (or the --run one)."""
    if len(runs) != 1:
        raise BadFile("%s: /runs: --plan draws one run, the file holds %d (name one with --run, "
                      "e.g. --run %s)" % (path, len(runs), runs[0]["name"]))
    run = runs[0]
    plan = read_plan(path, run["name"])
    walk = (float(run["time"][0]), float(run["time"][-1]))
    for t in at_times or ():
        if not walk[0] <= t <= walk[1]:
            raise BadFile("--at %g: expected a time of the walk, in [%g, %g] s" % (t, *walk))
    scenario = run["scenario"]
    fig, margins = figure_with_legend_room(15, 8)
    draw_plan_figure(fig, run, plan, at_times,
                     walking_number(scenario, "foot_length", DEFAULT_FOOT_LENGTH),
                     walking_number(scenario, "foot_width", DEFAULT_FOOT_WIDTH),
                     scenario_obstacles(scenario), bool(scenario_pushes(scenario)), margins)
    return fig


def main():
    parser = argparse.ArgumentParser(prog=PROG + " plot" if PROG == "wpg" else PROG,
                                     description=__doc__.split("\n")[0])
    parser.add_argument("run_file", help="HDF5 dataset written by `wpg run`")
    parser.add_argument("-o", "--output", help="PNG to write (default: RUN with .png)")
    parser.add_argument("--run", help="draw only this group of /runs/ (default: all)")
    parser.add_argument("--plan", action="store_true",
                        help="draw what the NMPC previewed against what the robot did")
    parser.add_argument("--at", type=float, nargs="+", metavar="T",
                        help="with --plan: the previews of the iterations at these times [s]")
    args = parser.parse_args()
    if args.at and not args.plan:
        raise BadFile("--at: expected with --plan only")
    output = args.output or os.path.splitext(args.run_file)[0] + (".plan" if args.plan else "") + ".png"
    runs = read_runs(args.run_file, args.run)
    if not os.path.isdir(os.path.dirname(os.path.abspath(output))):
        raise BadFile("%s: cannot write it: no such folder" % output)
    try:
        fig = draw_plan(runs, args.run_file, args.at) if args.plan else draw(runs, args.run_file)
    except (ValueError, TypeError, KeyError, IndexError, OverflowError, AttributeError) as error:
        # numbers the checks let through that matplotlib cannot place (e.g. 1e300 m)
        raise BadFile("%s: cannot draw it: %s: %s" % (args.run_file, type(error).__name__,
                                                       str(error)[:160]))
    try:
        save_atomically(fig, output, args.run_file)
    except OSError as error:
        raise BadFile("%s: cannot write it: %s" % (output, error))
    except (ValueError, OverflowError, RuntimeError) as error:
        raise BadFile("%s: cannot draw it: %s: %s" % (args.run_file, type(error).__name__,
                                                       str(error)[:160]))
    finally:
        plt.close("all")
    return 0


if __name__ == "__main__":
    run_script(SCRIPT, main)
