#!/usr/bin/python3
"""plot_obstacle_passing.py BATCH.h5 -o FIG.png [--table TABLE.md]: the outcome of each walk of
the obstacle-passing study (datasets/studies/obstacle_passing.yaml, docs/obstacle_passing.md):
one circle obstacle, a straight forward command.

Per run, from its fields (com, time, footsteps, checks/step_centre_clearance, obstacles/) and
its stored scenario: the obstacle's margin circle has radius R + m about its centre c;
- reached: the first time the CoM comes within R + m + 0.5 m of c (about a step and a half
  from the margin circle);
- past: the first time the CoM's x passes c_x + R + m, the far side of the margin circle;
- time to pass: past - reached; speed while passing: the CoM's x progress over that time;
- inside: a step centre closer to c than R + m (the step centre inside the margin);
- walks on: over the last 4.8 s (three gait cycles) the CoM advances at >= 80 % of the
  commanded speed along +x with |free-flyer yaw| < 0.1 rad.
Outcome: "passed" when past within max(10 s, 2 m / v) of reached, at >= min(0.1 m/s, v / 2)
along +x while passing (10 s and 0.1 m/s at 0.2 and 0.3 m/s; a command of 0.1 m/s walks the
same way for twice as long, at half the speed), never inside, walking on; "slow" when past
but not so; "blocked" when never past; "failed" when the walk failed (exit status 1) but for
ending blocked alone (its message "the robot is blocked: ...": such a walk is classed by where
it got, as before the walks were judged blocked).
Checked reads (wpg_file_reading.py): a bad file is one line and exit status 2.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wpg_file_reading import (BadFile, Reader, import_h5py, open_file,  # noqa: E402
                              parse_scenario, run_script)

SCRIPT = "plot_obstacle_passing.py"
import_h5py(SCRIPT)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PASS_WITHIN = 10.0      # s after reaching (at least)
PASS_DISTANCE = 2.0     # m: or the time this takes at the commanded speed, if longer
REACHED_BEYOND = 0.5    # m beyond the margin circle
MIN_SPEED = 0.1         # m/s while passing (or half the commanded speed, if less)
WALK_ON_WINDOW = 4.8    # s at the end
WALK_ON_FRACTION = 0.8  # of the commanded speed


def outcome(path, reader, run):
    where = run.name + ":scenario"
    scenario = parse_scenario(path, where, reader.attribute(run, "scenario", kind="text"))
    try:
        command = float(scenario["reference"][-1]["v"][0])
        reach = float(scenario["generator"]["obstacle_reach"])
        obstacle = scenario["obstacles"][0]
        centre = np.array([float(v) for v in obstacle["center"]])
        radius, margin = float(obstacle["radius"]), float(obstacle["margin"])
    except (KeyError, IndexError, TypeError, ValueError):
        raise BadFile("%s: %s: expected a forward command and one circle obstacle" % (path, where))
    t = reader.dataset(run, "time")
    com = reader.dataset(run, "com", columns=3, rows=len(t))
    yaw = reader.dataset(run, "free_flyer_yaw", rows=len(t))
    steps = reader.dataset(run, "footsteps", columns=4)
    rm = radius + margin
    distance = np.hypot(com[:, 0] - centre[0], com[:, 1] - centre[1])
    near = np.flatnonzero(distance <= rm + REACHED_BEYOND)
    beyond = np.flatnonzero(com[:, 0] >= centre[0] + rm)
    reached = t[near[0]] if len(near) else math.nan
    past = t[beyond[0]] if len(beyond) else math.nan
    inside = bool(np.any(np.hypot(steps[:, 1] - centre[0], steps[:, 2] - centre[1]) < rm - 1e-9))
    window = np.flatnonzero(t >= t[-1] - WALK_ON_WINDOW)
    speed_end = (com[-1, 0] - com[window[0], 0]) / max(t[-1] - t[window[0]], 1e-9)
    walks_on = speed_end >= WALK_ON_FRACTION * command and abs(yaw[-1]) < 0.1
    time_to_pass = past - reached if len(beyond) and len(near) else math.nan
    speed = math.nan
    if not math.isnan(time_to_pass) and time_to_pass > 0:
        speed = (com[beyond[0], 0] - com[near[0], 0]) / time_to_pass
    return dict(command=command, reach=reach, offset=centre[1], radius=radius, margin=margin,
                reached=reached, past=past, time_to_pass=time_to_pass, speed=speed,
                inside=inside, walks_on=walks_on, y_max=float(np.max(np.abs(com[:, 1]))))


def read(path):
    cells = []
    with open_file(path) as f:
        reader = Reader(path, f)
        table = reader.group(reader.group(f, "batch"), "summary")
        columns = reader.attribute(table, "columns", kind="texts")
        for name in ("name", "done", "exit_status"):
            if name not in columns:
                raise BadFile("%s: /batch/summary:columns: expected the column %s" % (path, name))
        done = reader.dataset(table, "done")
        status = reader.dataset(table, "exit_status", rows=len(done))
        names = reader.dataset(table, "name", kind="text", rows=len(done))
        runs = reader.group(f, "runs")
        for i in np.flatnonzero(done == 1):
            run = reader.group(runs, names[i])
            cell = outcome(path, reader, run)
            message = reader.attribute(run, "message", kind="text")
            cell["failed"] = status[i] != 0 and not message.startswith("the robot is blocked: ")
            cells.append(cell)
    if not cells:
        raise BadFile("%s: /batch/summary: expected a finished run" % path)
    for c in cells:
        if c["failed"]:
            c["kind"] = "failed"
        elif math.isnan(c["past"]):
            c["kind"] = "blocked"
        elif (math.isnan(c["time_to_pass"]) or
              c["time_to_pass"] <= max(PASS_WITHIN, PASS_DISTANCE / c["command"])) and \
                not c["inside"] and c["walks_on"] and \
                (math.isnan(c["speed"]) or
                 c["speed"] >= min(MIN_SPEED, 0.5 * c["command"]) - 1e-9):
            c["kind"] = "passed"
        else:
            c["kind"] = "slow"
    return cells


def counts(cells):
    n = {}
    for c in cells:
        n[c["kind"]] = n.get(c["kind"], 0) + 1
    return ", ".join("%d %s" % (v, k) for k, v in sorted(n.items(), key=lambda kv: -kv[1]))


def draw(cells, path, title):
    speeds = sorted({c["command"] for c in cells})
    shapes = sorted({(c["radius"], c["margin"]) for c in cells})
    offsets = sorted({c["offset"] for c in cells})
    reaches = sorted({c["reach"] for c in cells})
    fig, axes = plt.subplots(len(speeds), len(shapes), squeeze=False, sharex=True, sharey=True,
                             figsize=(2.3 * len(shapes) + 1.4, 1.9 * len(speeds) + 0.9))
    cmap = plt.get_cmap("RdYlGn_r")
    image = None
    for row, speed in enumerate(speeds):
        for col, shape in enumerate(shapes):
            ax = axes[row][col]
            grid = np.full((len(reaches), len(offsets)), np.nan)
            for c in cells:
                if c["command"] == speed and (c["radius"], c["margin"]) == shape:
                    x, y = offsets.index(c["offset"]), reaches.index(c["reach"])
                    if c["kind"] in ("passed", "slow"):
                        grid[y, x] = min(c["time_to_pass"], 20.0) if not math.isnan(
                            c["time_to_pass"]) else 0.0
                    mark = {"passed": "", "slow": "s", "blocked": "B", "failed": "F"}[c["kind"]]
                    if c["inside"]:
                        mark += "!"
                    if mark:
                        ax.text(x, y, mark, ha="center", va="center", fontsize=6)
            image = ax.imshow(grid, origin="lower", cmap=cmap, vmin=0.0, vmax=20.0,
                              aspect="auto", extent=(-0.5, len(offsets) - 0.5, -0.5,
                                                     len(reaches) - 0.5))
            ax.set_facecolor("0.35")
            if row == 0:
                ax.set_title("R %g m, margin %g m" % shape, fontsize=8)
            if col == 0:
                ax.set_ylabel("v %g m/s\nmet at [m]" % speed, fontsize=7)
            if row == len(speeds) - 1:
                ax.set_xlabel("offset [m]", fontsize=7)
    for ax in axes[-1]:
        ax.set_xticks(range(len(offsets)))
        ax.set_xticklabels(["%g" % o for o in offsets], fontsize=6, rotation=90)
    axes[0][0].set_yticks(range(len(reaches)))
    axes[0][0].set_yticklabels(["%g" % r for r in reaches], fontsize=6)
    bar = fig.colorbar(image, ax=[a for r in axes for a in r], shrink=0.8, pad=0.015,
                       fraction=0.03)
    bar.set_label("time to pass [s] (grey: blocked; allowed: 10 s, 20 s at 0.1 m/s)", fontsize=7)
    fig.suptitle("%s: %s   (B blocked, s passed slowly or not walking on, F failed, ! a step "
                 "centre inside the margin)" % (title, counts(cells)), fontsize=7)
    fig.savefig(path, dpi=80)


def write_table(cells, path):
    lines = ["| v [m/s] | R [m] | margin [m] | met at [m] | offset [m] | outcome "
             "| time to pass [s] | speed passing [m/s] | largest \\|y\\| [m] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for c in sorted(cells, key=lambda c: (c["command"], c["radius"], c["margin"], c["reach"],
                                          c["offset"])):
        lines.append("| %g | %g | %g | %g | %g | %s | %s | %s | %.2f |" % (
            c["command"], c["radius"], c["margin"], c["reach"], c["offset"],
            c["kind"] + (", step inside" if c["inside"] else ""),
            "-" if math.isnan(c["time_to_pass"]) else "%.1f" % c["time_to_pass"],
            "-" if math.isnan(c["speed"]) else "%.2f" % c["speed"], c["y_max"]))
    lines += ["", "%d walks: %s." % (len(cells), counts(cells))]
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("batch_file")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--table", help="also write the table of every walk (Markdown)")
    args = parser.parse_args()
    cells = read(args.batch_file)
    draw(cells, args.output, os.path.basename(args.batch_file))
    if args.table:
        write_table(cells, args.table)
    print("%d walks: %s" % (len(cells), counts(cells)))
    return 0


if __name__ == "__main__":
    run_script(SCRIPT, main)
