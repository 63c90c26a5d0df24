#!/usr/bin/python3
"""plot_push_sweep.py SWEEP.h5 -o FIG.png: the figure of a `wpg push-sweep` file: the largest
recovered force of a 100 ms push against the gait phase (fraction of the step since the swing
foot's lift-off), one line per direction, one panel per walking situation; the paper's value
(Sec. V-B) of each direction as a dashed line of the same colour; the end of single support
(phase 0.875 for HRP-2's 0.7 s + 0.1 s step) as a grey band. When the file has the swing
foot's peaks (columns swing_speed_max, swing_acceleration_max), a second row of panels plots
the peak speed of the walk at the found force against the phase, with the sweep's limit
(attribute max_swing_speed, when > 0) dotted.

Reads /push_sweep with h5py only (layout: datasets/SCHEMA.md, "Push sweep files"), every
column checked (wpg_file_reading.py); a bad file gives one line, `plot_push_sweep.py: FILE:
/path: expected ...`, and exit status 2.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wpg_file_reading import (  # noqa: E402
    BadFile, Reader, import_h5py, open_file, png_metadata, run_script, save_figure)

SCRIPT = "plot_push_sweep.py"
import_h5py(SCRIPT)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# The paper's Sec. V-B forces [N] (magnitudes), as cli/commands/push_sweep_command.cpp reads them.
PAPER = {
    "forward": {"sagittal+": 70, "sagittal-": 160, "coronal+": 90, "coronal-": 45},
    "on_spot": {"sagittal+": 115, "sagittal-": 115, "coronal+": 90, "coronal-": 45},
}
COLOURS = {"sagittal+": "tab:blue", "sagittal-": "tab:cyan", "coronal+": "tab:red",
           "coronal-": "tab:orange"}
SITUATION_TITLES = {"forward": "walking forward at 0.2 m/s", "on_spot": "stepping in place"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sweep_file")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()

    with open_file(args.sweep_file) as f:
        reader = Reader(args.sweep_file, f)
        table = reader.group(f, "push_sweep")
        situation = reader.dataset(table, "situation", kind="text")
        rows = len(situation)
        direction = reader.dataset(table, "direction", kind="text", rows=rows)
        phase = reader.dataset(table, "phase", rows=rows)
        force = np.abs(reader.dataset(table, "force", rows=rows))
        bound = reader.dataset(table, "at_upper_bound", kind="integer", rows=rows) == 1
        overrides = reader.attribute(f, "overrides", kind="texts", optional=True, default=[])
        swing_speed = reader.dataset(table, "swing_speed_max", rows=rows, optional=True)
        swing_limit = reader.attribute(f, "max_swing_speed", optional=True, default=0.0)
    if rows == 0:
        raise BadFile("%s: /push_sweep/situation: expected at least one row" % args.sweep_file)
    situations = list(dict.fromkeys(situation))
    panels = 1 if swing_speed is None else 2
    fig, axes = plt.subplots(panels, len(situations), squeeze=False, sharey="row",
                             figsize=(5.2 * len(situations) + 0.6, 4.0 + 2.6 * (panels - 1)))
    for ax, name in zip(axes[0], situations):
        ax.axvspan(0.875, 1.0, color="0.9", label="double support")
        for d in COLOURS:
            rows = (situation == name) & (direction == d)
            if not rows.any():
                continue
            order = np.argsort(phase[rows])
            x, y = phase[rows][order], force[rows][order]
            # "-" directions as open squares: on the spot they coincide with "+" (symmetry).
            marker = dict(marker="o") if d.endswith("+") else dict(marker="s", fillstyle="none")
            ax.plot(x, y, "-", color=COLOURS[d], label=d, **marker)
            capped = bound[rows][order]
            if capped.any():
                ax.plot(x[capped], y[capped], "^", color=COLOURS[d], markersize=10)
            if d in PAPER.get(name, {}):
                ax.axhline(PAPER[name][d], color=COLOURS[d], linestyle="--", linewidth=0.9)
        ax.set_title(SITUATION_TITLES.get(name, name))
        ax.set_xlabel("phase (fraction of the step since lift-off)")
        ax.set_xlim(-0.02, 1.0)
        ax.set_ylim(0, max(force.max(), 160.0) * 1.12)
        ax.grid(alpha=0.3)
    if swing_speed is not None:
        for ax, name in zip(axes[1], situations):
            for d in COLOURS:
                rows = (situation == name) & (direction == d)
                if not rows.any():
                    continue
                order = np.argsort(phase[rows])
                marker = dict(marker="o") if d.endswith("+") else dict(marker="s", fillstyle="none")
                ax.plot(phase[rows][order], swing_speed[rows][order], "-", color=COLOURS[d],
                        label=d, **marker)
            if swing_limit > 0:
                ax.axhline(swing_limit, color="k", linestyle=":", linewidth=0.9)
            ax.set_xlabel("phase (fraction of the step since lift-off)")
            ax.set_xlim(-0.02, 1.0)
            ax.set_ylim(0, max(float(swing_speed.max()), swing_limit, 1.0) * 1.12)
            ax.grid(alpha=0.3)
        axes[1][0].set_ylabel("swing foot's peak speed\nat that force [m/s]")
    axes[0][0].set_ylabel("largest recovered |force| of a 100 ms push [N]")
    axes[0][-1].legend(fontsize=8, loc="upper right")
    title = "Push recovery (dashed: the paper's Sec. V-B; triangles: the upper bound held)"
    if overrides:
        title += "\n--set " + " ".join(overrides)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    save_figure(fig, args.output, dpi=110, metadata=png_metadata(args.sweep_file))
    return 0


if __name__ == "__main__":
    run_script(SCRIPT, main)
