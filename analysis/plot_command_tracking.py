#!/usr/bin/python3
"""plot_command_tracking.py BATCH.h5 -o FIG.png [--table TABLE.md]: the figure and the table of
the command-tracking study (datasets/studies/command_tracking.yaml, docs/command_tracking.md).

For each finished run of a `wpg batch` file, its command (the last entry of the stored
scenario's reference: vx, vy, omega), the steady-state tracking metrics of /batch/summary
(steady_vx, steady_vy, steady_omega, steady_tracking: datasets/METRICS.md), and the command's
kinematic reach (gait_reach.py; feasibility polygon and step duration from the run's stored
scenario). A cell is "tracked" when steady_tracking <= 1 (every component within 10 % of the
command, 0.01 of a zero one); otherwise "limp" when only a gait whose two steps reach unequally
far can walk it, "unreachable" when no two-step gait can, else "missed" (the reach is that
of the parameters' own steps, single_support_samples: the paper's timing). The step duration
walked: the mean interval between the steady landings (those 15 s or more after the command;
with walking.step_timing: adaptive a command beyond the reach is walked with shorter steps).
The figure: one panel per omega, vy across, vx up, the cell coloured by steady_tracking and
marked with its step duration when it is not the parameters'. Checked reads
(wpg_file_reading.py): a bad file is one line and exit status 2.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gait_reach import gait_reach  # noqa: E402
from wpg_file_reading import (BadFile, Reader, import_h5py, open_file,  # noqa: E402
                              parse_scenario, run_script)

SCRIPT = "plot_command_tracking.py"
import_h5py(SCRIPT)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

METRICS = ["steady_vx", "steady_vy", "steady_omega", "steady_tracking"]


def command_of(path, where, scenario):
    """The last entry of the scenario's reference: [vx, vy, omega]."""
    reference = scenario.get("reference")
    try:
        v = [float(x) for x in reference[-1]["v"]]
    except (TypeError, KeyError, IndexError, ValueError):
        raise BadFile("%s: %s: expected a velocity command (reference)" % (path, where))
    if len(v) != 3 or not all(math.isfinite(x) for x in v):
        raise BadFile("%s: %s: expected reference[-1].v = [vx, vy, omega]" % (path, where))
    return v


def read(path):
    """The finished runs' commands and steady_* metrics, and the robot's step geometry."""
    with open_file(path) as f:
        reader = Reader(path, f)
        table = reader.group(reader.group(f, "batch"), "summary")
        columns = reader.attribute(table, "columns", kind="texts")
        for name in METRICS + ["name", "done", "exit_status"]:
            if name not in columns:
                raise BadFile("%s: /batch/summary:columns: expected the column %s" % (path, name))
        data = {}
        rows = None
        for name in METRICS + ["done", "exit_status"]:
            data[name] = reader.dataset(table, name, rows=rows, finite=False)
            rows = len(data[name])
        data["name"] = reader.dataset(table, "name", kind="text", rows=rows)
        runs = reader.group(f, "runs")
        data["command"] = [None] * rows
        data["step"] = [math.nan] * rows
        walking = None
        for i in np.flatnonzero(data["done"] == 1):
            run = reader.group(runs, data["name"][i])
            where = run.name + ":scenario"
            scenario = parse_scenario(path, where, reader.attribute(run, "scenario", kind="text"))
            data["command"][i] = command_of(path, where, scenario)
            steps = reader.dataset(run, "footsteps", columns=4)
            t_c = float(scenario["reference"][-1]["t"])
            landings = [row[0] for row in steps[2:] if row[0] >= t_c + 15.0 - 1e-9]
            data["step"][i] = ((landings[-1] - landings[0]) / (len(landings) - 1)
                               if len(landings) >= 2 else math.nan)
            if walking is None:
                walking = (where, scenario.get("walking"))
    if walking is None:
        raise BadFile("%s: /batch/summary: expected a finished run" % path)
    where, w = walking
    try:
        step = (w["single_support_samples"] + w["double_support_samples"]) * w["sampling_period"]
        fx = [float(v) for v in w["feasibility_x"]]
        fy = [float(v) for v in w["feasibility_y"]]
    except (KeyError, TypeError, ValueError):
        raise BadFile("%s: %s: expected the walking timings and feasibility polygon"
                      % (path, where))
    if len(fx) != 5 or len(fy) != 5 or not step > 0:
        raise BadFile("%s: %s: expected a 5-vertex feasibility polygon" % (path, where))
    return data, step, fx, fy


def classify(data, step, fx, fy):
    cells = []
    for i in range(len(data["done"])):
        if data["done"][i] != 1:
            continue
        v = data["command"][i]
        measured = [float(data[m][i]) for m in METRICS]
        reach = gait_reach(v[:2], v[2], step, fx, fy)
        regular = gait_reach(v[:2], v[2], step, fx, fy, regular=True)
        score = measured[3]
        if math.isnan(score):
            kind = "stands" if not any(v) else "no steady state"
        elif score <= 1.0:
            kind = "tracked"
        elif reach < 1.0:
            kind = "unreachable"
        elif regular < 1.0:
            kind = "limp"
        else:
            kind = "missed"
        cells.append(dict(v=v, measured=measured, reach=reach, regular=regular, kind=kind,
                          failed=data["exit_status"][i] != 0, step=data["step"][i]))
    return cells


def percent(measured, commanded):
    if abs(commanded) < 1e-12:
        return "%+.3f" % measured
    return "%.0f %%" % (100.0 * measured / commanded)


def write_table(cells, path):
    lines = ["| vx | vy | omega | steady vx | steady vy | steady omega | score | reach "
             "(any / regular gait) | step [s] | |", "|---|---|---|---|---|---|---|---|---|---|"]
    for c in sorted(cells, key=lambda c: (c["v"][2], c["v"][0], c["v"][1])):
        v, m = c["v"], c["measured"]
        reach = "-" if math.isinf(c["reach"]) else "%.2f / %.2f" % (c["reach"], c["regular"])
        values = ("-", "-", "-", "-") if math.isnan(m[3]) else (
            "%.3f (%s)" % (m[0], percent(m[0], v[0])), "%.3f (%s)" % (m[1], percent(m[1], v[1])),
            "%.3f (%s)" % (m[2], percent(m[2], v[2])), "%.2f" % m[3])
        step = "-" if math.isnan(c["step"]) else "%.2f" % c["step"]
        lines.append("| %g | %g | %g | %s | %s | %s | %s | %s | %s | %s |"
                     % ((v[0], v[1], v[2]) + values + (reach, step, c["kind"] + (
                         ", walk failed" if c["failed"] else ""))))
    counts = {}
    for c in cells:
        counts[c["kind"]] = counts.get(c["kind"], 0) + 1
    lines.append("")
    lines.append("%d cells: %s." % (len(cells), ", ".join(
        "%d %s" % (n, k) for k, n in sorted(counts.items(), key=lambda kv: -kv[1]))))
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def draw(cells, path, study, step):
    omegas = sorted({c["v"][2] for c in cells})
    vxs = sorted({c["v"][0] for c in cells})
    vys = sorted({c["v"][1] for c in cells})
    fig, axes = plt.subplots(1, len(omegas), figsize=(2.6 * len(omegas) + 1.2, 3.4),
                             squeeze=False, sharey=True)
    cmap = plt.get_cmap("RdYlGn_r")
    image = None
    for ax, omega in zip(axes[0], omegas):
        grid = np.full((len(vxs), len(vys)), np.nan)
        for c in cells:
            if c["v"][2] == omega:
                grid[vxs.index(c["v"][0]), vys.index(c["v"][1])] = min(c["measured"][3], 3.0)
        image = ax.imshow(grid, origin="lower", cmap=cmap, vmin=0.0, vmax=3.0, aspect="auto",
                          extent=(-0.5, len(vys) - 0.5, -0.5, len(vxs) - 0.5))
        for c in cells:
            if c["v"][2] != omega:
                continue
            x, y = vys.index(c["v"][1]), vxs.index(c["v"][0])
            mark = {"tracked": "", "unreachable": "x", "limp": "L", "missed": "!",
                    "stands": "s", "no steady state": "?"}[c["kind"]]
            if not math.isnan(c["step"]) and abs(c["step"] - step) > 1e-6:
                mark = (mark + " " if mark else "") + "%.1f" % c["step"]
            if mark:
                ax.text(x, y, mark, ha="center", va="center", fontsize=7)
        ax.set_title("omega = %g rad/s" % omega, fontsize=9)
        ax.set_xticks(range(len(vys)))
        ax.set_xticklabels(["%g" % v for v in vys], fontsize=7, rotation=90)
        ax.set_xlabel("vy [m/s]", fontsize=8)
    axes[0][0].set_yticks(range(len(vxs)))
    axes[0][0].set_yticklabels(["%g" % v for v in vxs], fontsize=7)
    axes[0][0].set_ylabel("vx [m/s]", fontsize=8)
    bar = fig.colorbar(image, ax=axes[0].tolist(), shrink=0.9, pad=0.015, fraction=0.03)
    bar.set_label("steady_tracking (<= 1: within 10 %)", fontsize=8)
    counts = {}
    for c in cells:
        counts[c["kind"]] = counts.get(c["kind"], 0) + 1
    summary = ", ".join("%d %s" % (n, k)
                        for k, n in sorted(counts.items(), key=lambda kv: -kv[1]))
    fig.suptitle("%s: %s   (x beyond any two-step gait of %g s steps, L a limping gait only, "
                 "! missed, s stands; a number: the steps walked [s])" % (study, summary, step),
                 fontsize=8)
    fig.savefig(path, dpi=80)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("batch_file")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--table", help="also write the table of every cell (Markdown)")
    args = parser.parse_args()
    data, step, fx, fy = read(args.batch_file)
    cells = classify(data, step, fx, fy)
    draw(cells, args.output, os.path.basename(args.batch_file), step)
    if args.table:
        write_table(cells, args.table)
    missed = sum(c["kind"] == "missed" for c in cells)
    print("%d cells, %d tracked, %d missed that a regular gait can reach"
          % (len(cells), sum(c["kind"] == "tracked" for c in cells), missed))
    return 0


if __name__ == "__main__":
    run_script(SCRIPT, main)
