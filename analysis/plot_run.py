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

Why one file of ~600 lines: `wpg plot` runs it as one script with Debian's python3 (no
package to install); its panels share the reading of the file and the styles above them.
"""
import argparse
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wpg_file_reading import (BadFile, Reader, import_h5py, open_file,  # noqa: E402
                              parse_scenario, run_script, walking_number)

SCRIPT = "plot_run.py"
PROG = os.environ.get("WPG_PLOT_PROG") or os.path.basename(sys.argv[0])

# HRP-2 sole (DESIGN.md), used when the run's scenario text does not give the foot size.
DEFAULT_FOOT_LENGTH = 0.2172  # [m]
DEFAULT_FOOT_WIDTH = 0.138  # [m]

LEFT_COLOUR = "tab:blue"
RIGHT_COLOUR = "tab:red"
COM_COLOUR = "black"
COP_COLOUR = "tab:green"
PUSH_COLOUR = "tab:purple"

# mpc/status values (libwpg IterationStatus) and how they are drawn.
STATUS_STYLE = {
    0: ("solved", "tab:gray", "o"),
    1: ("relaxed obstacle", "tab:orange", "s"),
    2: ("fallback", "tab:red", "X"),
    3: ("iteration limit", "tab:purple", "D"),
    4: ("fallen", "black", "v"),
    5: ("not converged", "tab:olive", "^"),
    6: ("relaxed kinematics", "tab:brown", "P"),
    7: ("relaxed balance", "tab:pink", "*"),
}
# fallback, iteration limit, fallen, relaxed kinematics / balance: the walk failed
FAILED_STATUSES = (2, 3, 4, 6, 7)
OBSTACLE_COLOUR = "0.35"
SCHEMA_DATASETS = ("time", "com", "cop", "support", "footsteps", "footstep_side")
# The multibody replay (optional): datasets of the run group, and the attributes of multibody/.
MULTIBODY_DATASETS = ("zmp_multibody", "zmp_multibody_filtered", "com_filtered")
MULTIBODY_ATTRIBUTES = ("zmp_error_rms_before", "zmp_error_max_before", "zmp_error_rms_after",
                        "zmp_error_max_after", "ik_failures", "filtered",
                        # filter_settings.mode both: the offline pass beside the online loop
                        "offline_zmp_error_rms_before", "offline_zmp_error_max_before",
                        "offline_zmp_error_rms_after", "offline_zmp_error_max_after",
                        "wpg_reinitialized")
# Fig. 6 of the paper: reference CoP solid blue, ZMP before the filter dash-dot red, after the
# filter dashed green.
FIG6_REFERENCE = dict(color="tab:blue", linestyle="-", linewidth=1.4)
FIG6_BEFORE = dict(color="tab:red", linestyle="-.", linewidth=1.2)
FIG6_AFTER = dict(color="tab:green", linestyle="--", linewidth=1.4)
FIG6_WINDOW = 3.0  # [s] of steady walking shown per axis
# One figure row per run, 6.8 in high: matplotlib refuses figures over 2^16 pixels (~87 rows).
MAX_RUNS_IN_FIGURE = 50


import_h5py(SCRIPT)
try:
    import numpy as np
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Patch, Polygon
    from matplotlib.lines import Line2D
    import yaml  # noqa: F401  (python3-yaml: the stored scenario is read with it)
except ImportError as error:
    from wpg_file_reading import report
    report(SCRIPT, "plotting needs h5py, matplotlib and PyYAML for %s (%s): install the Debian "
           "packages python3-h5py python3-matplotlib python3-yaml" % (sys.executable, error))
    sys.exit(2)


# --- scenario text (root attribute `scenario`, parsed by wpg_file_reading with PyYAML) --------
def fmt_number(value):
    try:
        return ("%.3g" % float(value))
    except (TypeError, ValueError):
        return str(value)


def describe_command(scenario):
    """A short text of the velocity command(s) of the scenario, or ''."""
    request = scenario.get("request") if isinstance(scenario.get("request"), dict) else scenario
    for key in ("reference", "command", "commands", "velocity"):
        entries = request.get(key)
        if entries is None:
            continue
        if isinstance(entries, dict):
            entries = [entries]
        if not isinstance(entries, list):
            return "%s: %s" % (key, entries)
        parts = []
        for entry in entries:
            if isinstance(entry, dict):
                velocity = entry.get("velocity", entry.get("command", entry.get("v")))
                if isinstance(velocity, (list, tuple)):
                    velocity = "(" + ", ".join(fmt_number(v) for v in velocity) + ")"
                elif isinstance(velocity, dict):
                    velocity = "(" + ", ".join(
                        "%s %s" % (k, fmt_number(v)) for k, v in velocity.items()) + ")"
                t = entry.get("t", entry.get("time"))
                parts.append(("t=%ss: " % fmt_number(t) if t is not None else "") + str(velocity))
            elif isinstance(entry, (list, tuple)):
                parts.append("(" + ", ".join(fmt_number(v) for v in entry) + ")")
            else:
                parts.append(str(entry))
        if len(parts) > 4:
            parts = parts[:3] + ["... (%d commands)" % len(parts)]
        text = "command [vx m/s, vy m/s, ω rad/s] " + "; ".join(parts)
        pushes = request.get("pushes")
        if isinstance(pushes, list) and pushes:
            text += "; %d push%s" % (len(pushes), "es" if len(pushes) > 1 else "")
            first = pushes[0]
            if isinstance(first, dict) and isinstance(first.get("force"), (list, tuple)):
                text += " (%s N at t=%ss)" % (
                    ", ".join(fmt_number(v) for v in first["force"]), fmt_number(first.get("t")))
        return text
    return ""


# --- reading (every dataset checked: wpg_file_reading) -----------------------------------------
def read_runs(path, only=None):
    with open_file(path) as handle:
        reader = Reader(path, handle)
        root_scenario = reader.attribute(handle, "scenario", kind="text", optional=True)
        runs_group = reader.group(handle, "runs")
        names = sorted(runs_group.keys())
        if not names:
            raise BadFile("%s: /runs: expected at least one run group, got none" % path)
        if only is not None:
            if only not in names:
                raise BadFile("%s: /runs/%s: expected a run group (runs: %s)"
                              % (path, only, ", ".join(names[:10])))
            names = [only]
        if len(names) > MAX_RUNS_IN_FIGURE:
            raise BadFile("%s: /runs: expected at most %d runs in one figure, got %d (draw one "
                          "with --run NAME)" % (path, MAX_RUNS_IN_FIGURE, len(names)))
        runs = []
        for name in names:
            group = reader.group(runs_group, name, optional=True)
            if group is None:
                continue
            runs.append(read_run(reader, group, name, root_scenario))
        if not runs:
            raise BadFile("%s: /runs: expected at least one run group, got none" % path)
        return runs


def read_run(reader, group, name, root_scenario):
    run = {"name": name}
    time = reader.dataset(group, "time")
    n = len(time)
    if n and not np.all(np.diff(time) > 0):
        row = int(np.argmax(~(np.diff(time) > 0))) + 1
        reader.fail(group.name + "/time", "row %d: expected strictly increasing times" % row)
    run["time"] = time
    run["com"] = reader.dataset(group, "com", columns=3, rows=n)
    run["cop"] = reader.dataset(group, "cop", columns=2, rows=n)
    run["support"] = reader.dataset(group, "support", kind="integer", rows=n)
    if np.any((run["support"] < 0) | (run["support"] > 2)):
        reader.fail(group.name + "/support", "expected codes 0, 1 or 2")
    run["footsteps"] = reader.dataset(group, "footsteps", columns=4)
    run["footstep_side"] = reader.dataset(group, "footstep_side", kind="integer",
                                          rows=len(run["footsteps"]))
    run["mpc"] = None
    mpc = reader.group(group, "mpc", optional=True)
    if mpc is not None and reader.has(mpc, "time") and reader.has(mpc, "solve_time"):
        k = None
        run["mpc"] = {}
        for key in ("time", "solve_time", "status"):
            values = reader.dataset(mpc, key, kind="integer" if key == "status" else "number",
                                    rows=k, optional=key == "status")
            if values is None:
                continue
            k = len(values)
            run["mpc"][key] = values
        status = run["mpc"].get("status")
        if status is not None and not np.all(np.isin(status, list(STATUS_STYLE))):
            reader.fail(mpc.name + "/status", "expected codes %s" % ", ".join(
                str(code) for code in STATUS_STYLE))
    run["multibody"] = None
    if reader.has(group, "zmp_multibody"):
        multibody = {}
        for key in MULTIBODY_DATASETS:
            values = reader.dataset(group, key, columns=3 if key == "com_filtered" else 2,
                                    rows=n, optional=key != "zmp_multibody")
            if values is not None:
                multibody[key] = values
        attributes = reader.group(group, "multibody", optional=True)
        if attributes is not None:
            for key in MULTIBODY_ATTRIBUTES:
                value = reader.attribute(attributes, key, optional=True)
                if value is not None:
                    multibody[key] = value
            # "online" (the loop of Fig. 3) or "offline"; absent in older files (offline)
            multibody["filter_mode"] = reader.attribute(
                attributes, "filter_mode", kind="text", optional=True) or "offline"
        else:
            multibody["filter_mode"] = "offline"
        run["multibody"] = multibody
    run["goal"] = read_goal(reader, group)
    # a batch stores each run's own scenario text on its group
    text = reader.attribute(group, "scenario", kind="text", optional=True) or root_scenario
    where = (group.name + ":scenario") if text is not root_scenario else "/:scenario"
    run["scenario"] = parse_scenario(reader.path, where, text)
    return run


def read_goal(reader, group):
    """The goal and the routes of a walk to a goal (SCHEMA.md: plans), or None."""
    if reader.attribute(group, "goal_x", optional=True) is None:
        return None
    goal = {}
    for key in ("goal_x", "goal_y", "goal_yaw", "goal_tolerance", "time_to_goal"):
        value = reader.attribute(group, key, optional=True)
        if value is not None:
            goal[key] = value
    for key in ("goal_x", "goal_y"):
        if not math.isfinite(goal.get(key, math.nan)):
            reader.fail(group.name + ":" + key, "expected a finite number")
    goal["goal_tolerance"] = goal.get("goal_tolerance", 0.0)
    if not (math.isfinite(goal["goal_tolerance"]) and goal["goal_tolerance"] >= 0):
        reader.fail(group.name + ":goal_tolerance", "expected a finite number >= 0")
    goal["reached"] = reader.attribute(group, "goal_reached", optional=True, default=0) == 1
    goal["routes"] = []
    plans = reader.group(group, "plans", optional=True)
    if plans is not None and reader.has(plans, "routes"):
        routes = reader.dataset(plans, "routes", columns=3)
        starts = reader.dataset(plans, "route_start", kind="integer")
        p = len(starts)
        counts = reader.dataset(plans, "route_count", kind="integer", rows=p)
        times = reader.dataset(plans, "time", rows=p)
        triggers = reader.dataset(plans, "trigger", kind="integer", rows=p)
        if np.any(starts < 0) or np.any(counts < 0) or np.any(starts + counts > len(routes)):
            reader.fail(plans.name + "/route_start",
                        "expected rows of routes (%d rows) with route_count" % len(routes))
        codes_text = reader.attribute(plans["trigger"], "codes", kind="text", optional=True,
                                      default="")
        codes = dict(item.split("=", 1) for item in codes_text.split(", ") if "=" in item)
        for start, count, time, trigger in zip(starts, counts, times, triggers):
            goal["routes"].append((routes[int(start):int(start) + int(count), :2], float(time),
                                   codes.get(str(int(trigger)), str(int(trigger)))))
    return goal


def draw_goal(ax, goal):
    """The goal (its tolerance circle, its yaw) and every route the planner gave."""
    colours = ["tab:green", "tab:purple", "tab:olive", "tab:cyan", "tab:brown"]
    handles = []
    for index, (route, time, trigger) in enumerate(goal["routes"]):
        if len(route) < 2:
            continue
        colour = colours[index % len(colours)]
        ax.plot(route[:, 0], route[:, 1], color=colour, linewidth=1.3,
                linestyle="-" if index == 0 else "--", marker=".", markersize=4, zorder=3)
        handles.append(Line2D([], [], color=colour, linewidth=1.3,
                              linestyle="-" if index == 0 else "--",
                              label="route %d (%s, t=%.1f s)" % (index + 1, trigger, time)))
    x, y, tolerance = goal["goal_x"], goal["goal_y"], goal.get("goal_tolerance", 0.0)
    ax.add_patch(Circle((x, y), tolerance, fill=False, edgecolor="black", linewidth=1.0,
                        linestyle=":", zorder=4))
    ax.plot([x], [y], marker="*", color="gold", markeredgecolor="black", markersize=13,
            zorder=5)
    yaw = goal.get("goal_yaw", float("nan"))
    if not math.isnan(yaw):
        ax.annotate("", xy=(x + 0.35 * math.cos(yaw), y + 0.35 * math.sin(yaw)), xytext=(x, y),
                    arrowprops=dict(arrowstyle="->", color="black", linewidth=1.2), zorder=5)
    label = "goal (dotted: tolerance), " + (
        "reached at t=%.1f s" % goal["time_to_goal"] if goal["reached"] else "not reached")
    handles.append(Line2D([], [], marker="*", color="gold", markeredgecolor="black",
                          markersize=11, linestyle="none", label=label))
    return handles


# --- drawing -----------------------------------------------------------------------------------
def sole_corners(x, y, yaw, length, width):
    c, s = math.cos(yaw), math.sin(yaw)
    corners = []
    for dx, dy in ((0.5, 0.5), (-0.5, 0.5), (-0.5, -0.5), (0.5, -0.5)):
        px, py = dx * length, dy * width
        corners.append((x + c * px - s * py, y + s * px + c * py))
    return corners


def scenario_obstacles(scenario):
    """[(outline [(x, y)], margin, circle, known to the planner)] of the scenario's obstacles
    (circles as polygons)."""
    request = scenario.get("request") if isinstance(scenario.get("request"), dict) else scenario
    obstacles = request.get("obstacles")
    shapes = []
    for obstacle in obstacles if isinstance(obstacles, list) else []:
        try:
            kind = obstacle.get("type", "circle")
            margin = float(obstacle.get("margin", 0.0) or 0.0)
            known = obstacle.get("known_to_planner", True) is not False
            if kind == "circle":
                cx, cy = (float(v) for v in obstacle["center"])
                radius = float(obstacle["radius"])
                outline = [(cx + radius * math.cos(a), cy + radius * math.sin(a))
                           for a in np.linspace(0.0, 2.0 * math.pi, 64, endpoint=False)]
                shapes.append((outline, margin, ("circle", cx, cy, radius), known))
            elif kind == "box":
                cx, cy = (float(v) for v in obstacle["center"])
                length, width = (float(v) for v in obstacle["size"])
                outline = sole_corners(cx, cy, float(obstacle.get("yaw", 0.0) or 0.0),
                                       length, width)
                shapes.append((outline, margin, None, known))
            elif kind == "polygon":
                outline = [(float(v[0]), float(v[1])) for v in obstacle["vertices"]]
                shapes.append((outline, margin, None, known))
        except (TypeError, KeyError, ValueError, AttributeError):
            continue
    return shapes


def grown_outline(outline, margin, circle):
    """The outline grown by `margin` (Minkowski sum with a disc), as a polygon."""
    if circle is not None:
        _, cx, cy, radius = circle
        return [(cx + (radius + margin) * math.cos(a), cy + (radius + margin) * math.sin(a))
                for a in np.linspace(0.0, 2.0 * math.pi, 64, endpoint=False)]
    points = []
    for x, y in outline:
        for a in np.linspace(0.0, 2.0 * math.pi, 24, endpoint=False):
            points.append((x + margin * math.cos(a), y + margin * math.sin(a)))
    return convex_hull(points)


def convex_hull(points):
    points = sorted(set(points))
    if len(points) < 3:
        return points

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in points:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(points):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def draw_obstacles(ax, obstacles):
    for outline, margin, circle, known in obstacles:
        ax.add_patch(Polygon(outline, closed=True, facecolor=OBSTACLE_COLOUR, alpha=0.45,
                             edgecolor=OBSTACLE_COLOUR, linewidth=1.0,
                             hatch=None if known else "///"))
        if margin > 0:
            ax.add_patch(Polygon(grown_outline(outline, margin, circle), closed=True, fill=False,
                                 edgecolor=OBSTACLE_COLOUR, linestyle="--", linewidth=0.8))


def draw_top_view(ax, run, foot_length, foot_width, obstacles=()):
    footsteps, sides = run["footsteps"], run["footstep_side"]
    draw_obstacles(ax, obstacles)
    goal_handles = draw_goal(ax, run["goal"]) if run.get("goal") else []
    for index, ((landing, x, y, yaw), side) in enumerate(zip(footsteps, sides)):
        colour = LEFT_COLOUR if int(side) == 1 else RIGHT_COLOUR
        ax.add_patch(Polygon(sole_corners(x, y, yaw, foot_length, foot_width), closed=True,
                             facecolor=colour, alpha=0.18, edgecolor=colour, linewidth=1.0))
        # a tick from the ankle towards the toe shows the yaw
        ax.plot([x, x + 0.35 * foot_length * math.cos(yaw)],
                [y, y + 0.35 * foot_length * math.sin(yaw)], color=colour, linewidth=1.0)
    ax.plot(run["cop"][:, 0], run["cop"][:, 1], color=COP_COLOUR, linewidth=0.9, label="CoP")
    ax.plot(run["com"][:, 0], run["com"][:, 1], color=COM_COLOUR, linewidth=1.6, label="CoM")
    if len(run["com"]):
        ax.plot(run["com"][0, 0], run["com"][0, 1], "o", color=COM_COLOUR, markersize=4)
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title("top view: %d footsteps (%d initial)" % (len(footsteps), min(2, len(footsteps))),
                 fontsize=10)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    handles = [Line2D([], [], color=COM_COLOUR, linewidth=1.6, label="CoM"),
               Line2D([], [], color=COP_COLOUR, linewidth=0.9, label="CoP"),
               Patch(facecolor=LEFT_COLOUR, alpha=0.35, edgecolor=LEFT_COLOUR, label="left foot"),
               Patch(facecolor=RIGHT_COLOUR, alpha=0.35, edgecolor=RIGHT_COLOUR,
                     label="right foot")]
    if obstacles:
        handles.append(Patch(facecolor=OBSTACLE_COLOUR, alpha=0.45, edgecolor=OBSTACLE_COLOUR,
                             label="obstacle (dashed: margin)"))
    if any(not known for _, _, _, known in obstacles):
        handles.append(Patch(facecolor="white", hatch="///", edgecolor=OBSTACLE_COLOUR,
                             label="unknown to the planner until sensed"))
    handles += goal_handles
    ax.legend(handles=handles, loc="best", fontsize=8, framealpha=0.85)


def support_spans(time, support):
    """[(t0, t1, state)] for the runs of equal support state."""
    spans = []
    if len(time) == 0:
        return spans
    start = 0
    for i in range(1, len(time) + 1):
        if i == len(time) or support[i] != support[start]:
            end = time[i] if i < len(time) else time[-1]
            spans.append((time[start], end, int(support[start])))
            start = i
    return spans


def shade_support(ax, spans):
    for t0, t1, state in spans:
        if state in (1, 2):
            ax.axvspan(t0, t1, color=LEFT_COLOUR if state == 1 else RIGHT_COLOUR, alpha=0.07,
                       linewidth=0)


def first_failure(run):
    """(time, status name) of the first NMPC iteration that fell back, hit its iteration
    limit or found the robot fallen, or None."""
    mpc = run["mpc"]
    if mpc is None or "status" not in mpc:
        return None
    status = np.asarray(mpc["status"], dtype=int)
    bad = np.flatnonzero(np.isin(status, FAILED_STATUSES))
    if len(bad) == 0:
        return None
    return float(mpc["time"][bad[0]]), STATUS_STYLE[int(status[bad[0]])][0]


def scenario_pushes(scenario):
    """[(t0, t1)] of the pushes of the scenario."""
    request = scenario.get("request") if isinstance(scenario.get("request"), dict) else scenario
    pushes = request.get("pushes")
    spans = []
    for push in pushes if isinstance(pushes, list) else []:
        try:
            t0 = float(push["t"])
            spans.append((t0, t0 + float(push.get("duration", 0.1))))
        except (TypeError, KeyError, ValueError):
            continue
    return spans


def draw_time_panels(axes, run, pushes):
    time, com, cop = run["time"], run["com"], run["cop"]
    spans = support_spans(time, run["support"])
    failure = first_failure(run)
    for ax in axes:
        for index, (t0, t1) in enumerate(pushes):
            ax.axvspan(t0, t1, color=PUSH_COLOUR, alpha=0.45, linewidth=0,
                       label="push" if index == 0 and ax is not axes[2] else None)
        if failure is not None:
            ax.axvline(failure[0], color=STATUS_STYLE[2][1], linestyle="--", linewidth=1.0)
    if failure is not None:
        axes[0].set_title("first %s at t = %.2f s" % (failure[1], failure[0]), fontsize=9,
                          color=STATUS_STYLE[2][1])
    for ax, column, axis_name in ((axes[0], 0, "x"), (axes[1], 1, "y")):
        shade_support(ax, spans)
        ax.plot(time, cop[:, column], color=COP_COLOUR, linewidth=0.9, label="CoP " + axis_name)
        ax.plot(time, com[:, column], color=COM_COLOUR, linewidth=1.4, label="CoM " + axis_name)
        ax.set_ylabel(axis_name + " [m]")
        ax.legend(loc="best", fontsize=8, framealpha=0.85)
        ax.grid(True, linewidth=0.4, alpha=0.5)
    ax = axes[2]
    shade_support(ax, spans)
    mpc = run["mpc"]
    if mpc is not None and len(mpc["time"]):
        mpc_time = mpc["time"]
        solve_us = 1e6 * np.asarray(mpc["solve_time"], dtype=float)
        status = np.asarray(mpc.get("status", np.zeros(len(mpc_time))), dtype=int)
        ax.plot(mpc_time, solve_us, color="0.6", linewidth=0.6)
        for value, (label, colour, marker) in STATUS_STYLE.items():
            chosen = status == value
            if np.any(chosen):
                ax.plot(mpc_time[chosen], solve_us[chosen], linestyle="none", marker=marker,
                        markersize=3 if value == 0 else 6, color=colour,
                        label="%s (%d)" % (label, int(np.count_nonzero(chosen))))
        unknown = ~np.isin(status, list(STATUS_STYLE))
        if np.any(unknown):
            ax.plot(mpc_time[unknown], solve_us[unknown], "k*", markersize=6,
                    label="other status (%d)" % int(np.count_nonzero(unknown)))
        ax.set_title("NMPC solve time per iteration: median %.0f µs, max %.0f µs"
                     % (np.median(solve_us), np.max(solve_us)), fontsize=9)
        ax.set_ylabel("solve [µs]")
        # headroom above the data for the legend
        ax.set_ylim(0, 1.5 * max(float(np.max(solve_us)), 1e-9))
        ax.legend(loc="upper right", fontsize=7, framealpha=0.85, ncol=3)
    else:
        ax.step(time, run["support"], where="post", color="black", linewidth=1.0)
        ax.set_yticks([0, 1, 2])
        ax.set_yticklabels(["double", "left", "right"])
        ax.set_ylabel("support")
    ax.set_xlabel("time [s]   (shaded: left / right single support)")
    ax.grid(True, linewidth=0.4, alpha=0.5)


def steady_window(time, support, length=FIG6_WINDOW):
    """(t0, t1): `length` s of steady walking, from 1 s after the first single support (the
    start transient), or the whole run when it is shorter."""
    if len(time) == 0:
        return 0.0, 1.0
    single = np.flatnonzero(np.asarray(support) != 0)
    start = float(time[single[0]]) + 1.0 if len(single) else float(time[0])
    start = min(start, float(time[-1]) - length)
    start = max(start, float(time[0]))
    return start, min(float(time[-1]), start + length)


def mm(value):
    return "%.1f mm" % (1e3 * value)


def draw_fig6(axes, run):
    """The paper's Fig. 6: reference CoP, multibody ZMP before and after the dynamic filter."""
    time, cop, mb = run["time"], run["cop"], run["multibody"]
    before = mb["zmp_multibody"]
    after = mb.get("zmp_multibody_filtered")
    filtered = after is not None and len(after) == len(time)
    t0, t1 = steady_window(time, run["support"])
    chosen = (time >= t0) & (time <= t1)
    spans = support_spans(time, run["support"])
    for ax, column, axis_name in ((axes[0], 0, "x"), (axes[1], 1, "y")):
        shade_support(ax, [s for s in spans if s[1] >= t0 and s[0] <= t1])
        ax.plot(time[chosen], cop[chosen, column], label="reference CoP", **FIG6_REFERENCE)
        ax.plot(time[chosen], before[chosen, column], label="multibody ZMP", **FIG6_BEFORE)
        if filtered:
            ax.plot(time[chosen], after[chosen, column], label="multibody ZMP, filtered",
                    **FIG6_AFTER)
        ax.set_xlim(t0, t1)
        ax.set_ylabel("ZMP %s [m]" % axis_name)
        ax.set_xlabel("time [s]")
        ax.set_title("Fig. 6 analogue, %s: %.1f s of steady walking" % (axis_name, t1 - t0),
                     fontsize=9)
        ax.grid(True, linewidth=0.4, alpha=0.5)
        ax.legend(loc="best", fontsize=7, framealpha=0.85)
    ax = axes[2]
    shade_support(ax, spans)
    ax.plot(time, 1e3 * np.linalg.norm(cop - before, axis=1), label="before the filter",
            **dict(FIG6_BEFORE, linewidth=0.8))
    title = "|CoP - multibody ZMP|: RMS %s, max %s" % (
        mm(mb.get("zmp_error_rms_before", float("nan"))),
        mm(mb.get("zmp_error_max_before", float("nan"))))
    if filtered:
        mode = mb.get("filter_mode") or "offline"
        if mode == "online":
            mode += ", WPG re-initialised" if mb.get("wpg_reinitialized") else ", open loop"
        ax.plot(time, 1e3 * np.linalg.norm(cop - after, axis=1),
                label="after the filter (%s)" % mode, **dict(FIG6_AFTER, linewidth=0.9))
        title = "|CoP - multibody ZMP|, %s filter: RMS %s -> %s, max %s -> %s" % (
            mode,
            mm(mb.get("zmp_error_rms_before", float("nan"))),
            mm(mb.get("zmp_error_rms_after", float("nan"))),
            mm(mb.get("zmp_error_max_before", float("nan"))),
            mm(mb.get("zmp_error_max_after", float("nan"))))
        if "offline_zmp_error_rms_after" in mb:
            # mode both: the offline pass over the open-loop walk, for comparison
            title += "\noffline pass (open-loop walk): RMS %s -> %s, max %s -> %s" % (
                mm(mb["offline_zmp_error_rms_before"]), mm(mb["offline_zmp_error_rms_after"]),
                mm(mb["offline_zmp_error_max_before"]), mm(mb["offline_zmp_error_max_after"]))
    ax.axvspan(t0, t1, facecolor="none", edgecolor="0.3", linestyle=":", linewidth=1.0)
    ax.set_title(title, fontsize=9)
    ax.set_ylabel("distance [mm]")
    ax.set_xlabel("time [s]   (dotted box: the window on the left)")
    ax.set_ylim(bottom=0)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    ax.legend(loc="upper right", fontsize=7, framealpha=0.85)


def draw(runs, source_path):
    rows = len(runs)
    heights = [6.8 + (3.4 if run["multibody"] is not None else 0.0) for run in runs]
    fig = plt.figure(figsize=(15, sum(heights)))
    outer = fig.add_gridspec(rows, 1, hspace=0.35 if rows > 1 else 0.0, height_ratios=heights)
    for row, run in enumerate(runs):
        scenario = run["scenario"]
        foot_length = walking_number(scenario, "foot_length", DEFAULT_FOOT_LENGTH)
        foot_width = walking_number(scenario, "foot_width", DEFAULT_FOOT_WIDTH)
        cell = outer[row]
        if run["multibody"] is not None:
            split = cell.subgridspec(2, 1, height_ratios=(6.8, 3.4), hspace=0.28)
            bottom = split[1].subgridspec(1, 3, wspace=0.3)
            draw_fig6([fig.add_subplot(bottom[0, i]) for i in range(3)], run)
            cell = split[0]
        cell = cell.subgridspec(3, 2, width_ratios=(1.25, 1.0), hspace=0.45, wspace=0.18)
        top = fig.add_subplot(cell[:, 0])
        right = [fig.add_subplot(cell[0, 1])]
        right.append(fig.add_subplot(cell[1, 1], sharex=right[0]))
        right.append(fig.add_subplot(cell[2, 1], sharex=right[0]))
        for ax in right[:2]:
            ax.tick_params(labelbottom=False)
        draw_top_view(top, run, foot_length, foot_width, scenario_obstacles(scenario))
        draw_time_panels(right, run, scenario_pushes(scenario))
        command = describe_command(scenario)
        if run.get("goal"):
            goal = run["goal"]
            command = "goal (%s, %s)" % (fmt_number(goal["goal_x"]), fmt_number(goal["goal_y"]))
            if not math.isnan(goal.get("goal_yaw", float("nan"))):
                command += ", yaw %s rad" % fmt_number(goal["goal_yaw"])
            command += ", %d route%s" % (len(goal["routes"]), "" if len(goal["routes"]) == 1 else "s")
        title = "run %s" % run["name"] + ("   —   " + command if command else "")
        top.text(0.0, 1.06, title, transform=top.transAxes, fontsize=12, fontweight="bold",
                 ha="left", va="bottom")
    fig.text(0.995, 0.003, os.path.basename(source_path), ha="right", va="bottom", fontsize=7,
             color="0.4")
    return fig


def save_atomically(fig, output):
    folder = os.path.dirname(os.path.abspath(output))
    fd, temporary = tempfile.mkstemp(prefix="." + os.path.basename(output) + ".",
                                     suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "wb") as stream:
            fig.savefig(stream, format="png", dpi=110, bbox_inches="tight")
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        os.replace(temporary, output)
    except BaseException:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        raise


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
        save_atomically(fig, output)
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
