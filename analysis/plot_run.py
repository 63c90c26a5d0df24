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

from run_figure.figure import draw, save_atomically  # noqa: E402
from run_figure.reading import read_runs  # noqa: E402


def main():
    parser = argparse.ArgumentParser(prog=PROG + " plot" if PROG == "wpg" else PROG,
                                     description=__doc__.split("\n")[0])
    parser.add_argument("run_file", help="HDF5 dataset written by `wpg run`")
    parser.add_argument("-o", "--output", help="PNG to write (default: RUN with .png)")
    parser.add_argument("--run", help="draw only this group of /runs/ (default: all)")
    args = parser.parse_args()
    output = args.output or os.path.splitext(args.run_file)[0] + ".png"
    runs = read_runs(args.run_file, args.run)
    if not os.path.isdir(os.path.dirname(os.path.abspath(output))):
        raise BadFile("%s: cannot write it: no such folder" % output)
    try:
        fig = draw(runs, args.run_file)
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
