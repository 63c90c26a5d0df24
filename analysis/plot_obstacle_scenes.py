#!/usr/bin/python3
"""plot_obstacle_scenes.py BATCH.h5 -o FIG.png [--table TABLE.md]: the outcome of each walk of
the obstacle-scenes study (datasets/studies/obstacle_scenes.yaml, docs/obstacle_scenes.md):
slaloms, boxes and polygons, mixed obstacles, doorways, scenes without a passage, obstacles met
while turning and on lateral or diagonal commands.

Per run, from its stored scenario (obstacles, velocity command, walking parameters) and its
fields (com, com_vel, free_flyer_yaw, footsteps, checks/step_centre_clearance, mpc/status):

The command: the reference's last entry, held from t0 on (the first time after which the
schedule no longer changes). The robot starts at the origin facing +x: the command's frame is
the world's at t0 and turns by omega (t - t0) after it (the commanded heading).

Is there a passage? scene_passage.py (its docstring says how): the CoM's free plane, each
obstacle grown by its margin, obstacle_foot_radius and half the minimal step width, within BAND
of the commanded path; the goal the point of that path past the furthest grown obstacle; the
shortest free path to it (L below) when there is one.

Along the command, a point's progress is its distance along the commanded line from the start
(for a turning command, its angle about the circle's centre from the start, times the radius).
- past: the first sample from t0 on at which the CoM's progress reaches the furthest progress
  of any obstacle grown by its margin (the far side of the last margin);
- time to pass: past - t0;
- allowed: ALLOWED_FACTOR x L / v + ALLOWED_EXTRA, L the shortest free path (for a turning
  command the longer of it and the commanded arc, which a straight path round nothing cuts
  short; without a passage, the commanded path's length), v the commanded speed;
- inside: a landed step's centre inside a margin (checks/step_centre_clearance below
  -obstacle_foot_radius);
- relaxed: NMPC iterations with the status relaxed_obstacle (mpc/status, by its codes);
- walks on: over the last WALK_ON_WINDOW s the CoM's velocity along the commanded direction
  averages at least WALK_ON_FRACTION of the commanded speed, and the free-flyer yaw ends within
  WALK_ON_HEADING of the commanded heading (plot_obstacle_passing.py's test, for any command).
Outcome: "failed" when the walk failed (the run's attribute success is 0: a fall, a step landed
inside the NMPC's bound); else "blocked" when never past; "passed" when past within the
allowed time, never inside, never relaxed, walking on; "slow" otherwise (the table says why).
A run's `blocked` attribute (with `blocked_since`), when the file has one and it is set, says
the walk was stopped on purpose: its success 0 then counts as failed only for a fall (an
iteration with the status fallen) or a step landed inside the NMPC's bound, and the table names
it. A walk is "correct" when it passed a scene with a passage, or was blocked by a scene
without one.

The kind of a scene is the first word of its label (the run's swept `name`, as the study's zip
gives it; the run's name without one), its row in the figure the label without that word and
its last, its column the last word (the commanded speed, mostly). The figure: per kind, the top
view of one walk (the scene with the longest detour, at the speed nearest 0.2 m/s) and a grid
of every walk, coloured by its time to pass over the time allowed. Checked reads
(wpg_file_reading.py): a bad file is one line and exit status 2.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_obstacle_passing import WALK_ON_FRACTION, WALK_ON_WINDOW  # noqa: E402
from run_figure.geometry import sole_corners  # noqa: E402
from run_figure.scenario_text import scenario_obstacles  # noqa: E402
from run_figure.styles import (COM_COLOUR, DEFAULT_FOOT_LENGTH,  # noqa: E402
                               DEFAULT_FOOT_WIDTH, LEFT_COLOUR, RIGHT_COLOUR)
from run_figure.top_view import draw_obstacles  # noqa: E402
from scene_passage import (ARC_SEGMENTS, DEFAULT_FOOT_RADIUS,  # noqa: E402,F401
                           HRP2_FEASIBILITY, MIN_STEP_WIDTH,
                           CommandPath, analyse_scene, grown_polygon, least_step_width,
                           shortest_path)
from wpg_file_reading import (BadFile, Reader, import_h5py, open_file,  # noqa: E402
                              parse_scenario, png_metadata, run_script, save_figure,
                              walking_number)

SCRIPT = "plot_obstacle_scenes.py"
import_h5py(SCRIPT)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Polygon, Rectangle  # noqa: E402

# Allowed time to pass: ALLOWED_FACTOR x the shortest free path at the commanded speed, plus
# ALLOWED_EXTRA for the start of the walk (the first step lifts off 0.8 s after the command) and
# the steps round an obstacle, slower along the command than straight ones.
ALLOWED_FACTOR = 1.5
ALLOWED_EXTRA = 5.0  # [s]
# Walking on: the yaw at the end within this of the commanded heading (plot_obstacle_passing.py).
WALK_ON_HEADING = 0.1  # [rad]
# Kinds of scene (the first word of a label), in the figure's order, with their titles.
KINDS = (("slalom", "slalom of circles"), ("shape", "a box or a polygon on the path"),
         ("mixed", "two or three mixed obstacles"), ("gap", "a doorway between two walls"),
         ("closed", "no passage: a wall, an enclosure"), ("turning", "met while turning"),
         ("sideways", "lateral and diagonal commands"))
OUTCOMES = ("passed", "slow", "blocked", "failed")
OUTCOME_MARK = {"passed": "", "slow": "s", "blocked": "B", "failed": "F"}
# The grid's colour scale: time to pass over the time allowed (1 = the limit).
RATIO_TOP = 1.5


# --- the rules ---------------------------------------------------------------------------


def _number(value, low=0.0):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and \
        math.isfinite(value) and value >= low


def allowed_time(scene):
    """ALLOWED_FACTOR x the path to walk at the commanded speed + ALLOWED_EXTRA, s after t0."""
    length = scene["commanded"]
    if scene["passage"]:
        length = max(length, scene["length"])
    return ALLOWED_FACTOR * length / scene["path"].speed + ALLOWED_EXTRA


def scene_walking(scenario):
    """(obstacle_foot_radius, least_step_width) of a stored scenario's walking map, HRP-2's
    where it lacks them."""
    walking = scenario.get("walking") if isinstance(scenario.get("walking"), dict) else {}
    radius = walking.get("obstacle_foot_radius")
    radius = float(radius) if _number(radius) else DEFAULT_FOOT_RADIUS
    xs, ys = walking.get("feasibility_x"), walking.get("feasibility_y")
    feasibility = HRP2_FEASIBILITY
    if isinstance(xs, list) and isinstance(ys, list) and len(xs) == len(ys) and xs and \
            all(_number(v, -math.inf) for v in xs) and all(_number(v, -math.inf) for v in ys):
        feasibility = tuple(zip((float(v) for v in xs), (float(v) for v in ys)))
    return radius, least_step_width(feasibility)


def scene_command(scenario):
    """(t0, (vx, vy, omega)): the last command of the reference and since when it holds."""
    reference = scenario.get("reference")
    if not isinstance(reference, list) or not reference:
        raise ValueError("expected a velocity command")
    last = [float(v) for v in reference[-1]["v"]]
    start = float(reference[-1]["t"])
    for entry in reversed(reference[:-1]):
        if [float(v) for v in entry["v"]] != last:
            break
        start = float(entry["t"])
    return start, last


# --- the walks -----------------------------------------------------------------------------


def status_code(reader, status, name):
    """The code of the status `name` in mpc/status's `codes` ("0=solved, 1=relaxed_obstacle")."""
    codes = reader.attribute(status, "codes", kind="text")
    for item in codes.split(","):
        code, _, label = item.strip().partition("=")
        if label.strip() == name and code.strip().isdigit():
            return int(code)
    reader.fail(status.name + ":codes", "expected the code of %s" % name)


def walk(path, reader, run, scenes):
    where = run.name + ":scenario"
    scenario = parse_scenario(path, where, reader.attribute(run, "scenario", kind="text"))
    label = reader.attribute(run, "sweep.name", kind="text", optional=True) or \
        run.name.rsplit("/", 1)[-1]
    try:
        t0, command = scene_command(scenario)
        shapes = scenario_obstacles(scenario)
        foot_radius, min_width = scene_walking(scenario)
        key = (repr(scenario.get("obstacles")), tuple(command), foot_radius, min_width)
        if shapes and key not in scenes:
            scenes[key] = analyse_scene(shapes, command, foot_radius, min_width)
    except (KeyError, IndexError, TypeError, ValueError, AttributeError):
        raise BadFile("%s: %s: expected a constant velocity command that walks, and obstacles"
                      % (path, where))
    if not shapes:
        raise BadFile("%s: %s: expected obstacles" % (path, where))
    scene = scenes[key]
    time = reader.dataset(run, "time")
    com = reader.dataset(run, "com", columns=3, rows=len(time))
    com_vel = reader.dataset(run, "com_vel", columns=3, rows=len(time))
    yaw = reader.dataset(run, "free_flyer_yaw", rows=len(time))
    steps = reader.dataset(run, "footsteps", columns=4)
    sides = reader.dataset(run, "footstep_side", kind="integer", rows=len(steps))
    clearance = reader.dataset(reader.group(run, "checks"), "step_centre_clearance",
                               rows=len(steps))
    mpc = reader.group(run, "mpc")
    statuses = reader.dataset(mpc, "status", kind="integer")
    relaxed = int(np.count_nonzero(statuses == status_code(reader, mpc["status"],
                                                           "relaxed_obstacle")))
    fell = bool(np.any(statuses == status_code(reader, mpc["status"], "fallen")))
    if not len(time):
        reader.fail(run.name + "/time", "expected samples")
    command_path = scene["path"]
    beyond = np.flatnonzero((command_path.progress(com[:, :2]) >= scene["past"]) & (time >= t0))
    window = time >= time[-1] - WALK_ON_WINDOW
    along = np.einsum("ij,ij->i", com_vel[window, :2],
                      command_path.world_direction(time[window] - t0))
    turned = abs(math.remainder(float(yaw[-1]) - command_path.heading(time[-1] - t0),
                                2.0 * math.pi))
    landed = steps[:, 0] > 0.0   # the two initial feet stand where the scenario puts them
    blocked = reader.attribute(run, "blocked", optional=True)
    return dict(
        label=label, kind=label.split("_")[0], shapes=shapes, scene=scene, command=command,
        allowed=allowed_time(scene),
        past=float(time[beyond[0]] - t0) if len(beyond) else math.nan,
        inside=bool(np.any(clearance[landed] < -foot_radius - 1e-9)),
        # As the walk's own check (libwpg's walk loop): a step centre inside the NMPC's bound.
        stepped_in=bool(np.any(clearance[landed] < -1e-6)), fell=fell,
        clearance=float(np.min(clearance[landed])) if np.any(landed) else math.nan,
        relaxed=relaxed,
        walks_on=float(np.mean(along)) >= WALK_ON_FRACTION * command_path.speed and
        turned < WALK_ON_HEADING,
        success=reader.attribute(run, "success") == 1,
        blocked_attribute=blocked is not None and blocked != 0,
        blocked_since=reader.attribute(run, "blocked_since", optional=True),
        com=com, steps=steps, sides=sides,
        foot_length=walking_number(scenario, "foot_length", DEFAULT_FOOT_LENGTH),
        foot_width=walking_number(scenario, "foot_width", DEFAULT_FOOT_WIDTH))


def classify(w):
    """Sets w["outcome"], w["why"] (what kept it from passing) and w["correct"]."""
    why = []
    if not w["success"] and (not w["blocked_attribute"] or w["fell"] or w["stepped_in"]):
        outcome = "failed"
    elif math.isnan(w["past"]):
        outcome = "blocked"
    else:
        for fault, reason in ((w["past"] > w["allowed"], "late"),
                              (w["inside"], "a step inside a margin"),
                              (w["relaxed"] > 0, "relaxed"),
                              (not w["walks_on"], "not walking on")):
            if fault:
                why.append(reason)
        outcome = "slow" if why else "passed"
    if w["blocked_attribute"]:
        why.append("blocked attribute" + (
            "" if w["blocked_since"] is None else " since %.1f s" % w["blocked_since"]))
    w["outcome"] = outcome
    w["why"] = ", ".join(why)
    w["correct"] = outcome == ("passed" if w["scene"]["passage"] else "blocked")
    return w


def read(path):
    walks, scenes = [], {}
    with open_file(path) as f:
        reader = Reader(path, f)
        table = reader.group(reader.group(f, "batch"), "summary")
        columns = reader.attribute(table, "columns", kind="texts")
        for name in ("name", "done"):
            if name not in columns:
                raise BadFile("%s: /batch/summary:columns: expected the column %s" % (path, name))
        done = reader.dataset(table, "done")
        names = reader.dataset(table, "name", kind="text", rows=len(done))
        runs = reader.group(f, "runs")
        for i in np.flatnonzero(done == 1):
            walks.append(classify(walk(path, reader, reader.group(runs, names[i]), scenes)))
    if not walks:
        raise BadFile("%s: /batch/summary: expected a finished run" % path)
    return walks


# --- the table and the figure --------------------------------------------------------------


def in_order(values):
    """The distinct values in their order of first appearance (the study's)."""
    return list(dict.fromkeys(values))


def kinds_of(walks):
    known = [k for k, _ in KINDS if any(w["kind"] == k for w in walks)]
    return known + in_order(w["kind"] for w in walks if w["kind"] not in known)


def count_line(walks):
    n = {o: sum(w["outcome"] == o for w in walks) for o in OUTCOMES}
    return ", ".join("%d %s" % (n[o], o) for o in OUTCOMES if n[o]) + \
        "; %d of %d correct" % (sum(w["correct"] for w in walks), len(walks))


def fmt(value, digits=1):
    """The number rounded to `digits`, never "-0.000"; "-" for none."""
    if value is None or math.isnan(value):
        return "-"
    return "%.*f" % (digits, round(value, digits) + 0.0)


def write_table(walks, path):
    lines = ["| scene | command [m/s, m/s, rad/s] | obstacles | passage | shortest path [m] "
             "| allowed [s] | outcome | time to pass [s] | least step clearance [m] "
             "| relaxed iterations | correct | why not passed |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for w in walks:
        lines.append("| %s | [%s] | %d | %s | %s | %s | %s | %s | %s | %d | %s | %s |" % (
            w["label"], ", ".join("%g" % v for v in w["command"]), len(w["shapes"]),
            "yes" if w["scene"]["passage"] else "no", fmt(w["scene"]["length"], 2),
            fmt(w["allowed"]), w["outcome"], fmt(w["past"]), fmt(w["clearance"], 3),
            w["relaxed"], "yes" if w["correct"] else "no", w["why"] or "-"))
    lines += ["", "| kind | walks | with a passage | passed | slow | blocked | failed | correct |",
              "|---|---|---|---|---|---|---|---|"]
    for kind in kinds_of(walks) + ["all"]:
        group = [w for w in walks if kind == "all" or w["kind"] == kind]
        lines.append("| %s | %d | %d | %s | %d |" % (
            kind, len(group), sum(w["scene"]["passage"] for w in group),
            " | ".join(str(sum(w["outcome"] == o for w in group)) for o in OUTCOMES),
            sum(w["correct"] for w in group)))
    lines += ["", "%d walks: %s." % (len(walks), count_line(walks))]
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def cell_of(w):
    """(row, column) of a walk in its kind's grid: its label without the kind, and the last
    word."""
    words = w["label"].split("_")
    if len(words) < 3:
        return "_".join(words[1:]) or w["label"], ""
    return "_".join(words[1:-1]), words[-1]


def representative(group):
    """The walk drawn for a kind: a scene with a passage if any, the longest detour (shortest
    free path over the commanded path), the most obstacles, the speed nearest 0.2 m/s; the
    first in the file on ties."""
    def detour(w):
        scene = w["scene"]
        return scene["length"] / scene["commanded"] if scene["passage"] else 0.0
    return min(group, key=lambda w: (not w["scene"]["passage"], -round(detour(w), 6),
                                     -len(w["shapes"]),
                                     round(abs(w["scene"]["path"].speed - 0.2), 6)))


def draw_scene(ax, w):
    scene = w["scene"]
    draw_obstacles(ax, w["shapes"])
    for polygon in scene["free"]:
        ax.add_patch(Polygon(polygon, closed=True, fill=False, edgecolor="0.55",
                             linestyle=":", linewidth=0.9))
    for (_landing, x, y, yaw), side in zip(w["steps"], w["sides"]):
        colour = LEFT_COLOUR if int(side) == 1 else RIGHT_COLOUR
        ax.add_patch(Polygon(sole_corners(x, y, yaw, w["foot_length"], w["foot_width"]),
                             closed=True, facecolor=colour, alpha=0.15, edgecolor=colour,
                             linewidth=0.5))
    commanded = np.array([scene["path"].point(s)
                          for s in np.linspace(0.0, scene["commanded"], 60)])
    ax.plot(commanded[:, 0], commanded[:, 1], color="tab:cyan", linewidth=1.0)
    shown = [np.zeros((1, 2)), commanded]
    if scene["route"] is not None:
        ax.plot(scene["route"][:, 0], scene["route"][:, 1], color="tab:purple", linewidth=1.3,
                linestyle="--")
        shown.append(scene["route"])
    ax.plot(w["com"][:, 0], w["com"][:, 1], color=COM_COLOUR, linewidth=1.2)
    # The scene round the commanded path and the free path, not the whole of long walls.
    shown = np.concatenate(shown)
    low, high = shown.min(axis=0) - 0.9, shown.max(axis=0) + 0.9
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_aspect("equal", adjustable="datalim")
    ax.tick_params(labelsize=7)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    ax.set_title("%s: %s%s" % (w["label"], w["outcome"], "" if math.isnan(w["past"]) else
                               ", past after %.1f s of %.1f allowed" % (w["past"], w["allowed"])),
                 fontsize=8)


def draw_grid(ax, group, cmap):
    rows = in_order(cell_of(w)[0] for w in group)
    columns = in_order(cell_of(w)[1] for w in group)
    ratio = np.full((len(rows), len(columns)), np.nan)
    for w in group:
        row, column = cell_of(w)
        y, x = rows.index(row), columns.index(column)
        if not math.isnan(w["past"]):
            ratio[y, x] = min(w["past"] / w["allowed"], RATIO_TOP)
        mark = OUTCOME_MARK[w["outcome"]] + ("!" if w["inside"] else "")
        if mark:
            ax.text(x, y, mark, ha="center", va="center", fontsize=6)
        if not w["scene"]["passage"]:
            ax.add_patch(Rectangle((x - 0.5, y - 0.5), 1.0, 1.0, fill=False, edgecolor="black",
                                   linewidth=1.2))
    image = ax.imshow(ratio, cmap=cmap, vmin=0.0, vmax=RATIO_TOP, aspect="auto",
                      interpolation="nearest")
    ax.set_facecolor("0.55")
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels(rows, fontsize=6)
    ax.set_xticks(range(len(columns)))
    ax.set_xticklabels(columns, fontsize=6)
    ax.xaxis.tick_top()
    ax.set_title("%d walks: %s" % (len(group), count_line(group)), fontsize=7, pad=14)
    return image


def draw(walks, output, source):
    kinds = kinds_of(walks)
    heights = [max(2.6, 0.14 * len(in_order(cell_of(w)[0] for w in walks if w["kind"] == k))
                   + 1.0) for k in kinds]
    height = sum(heights) + 2.0   # in; the title and the legend above the panels
    fig = plt.figure(figsize=(12.0, height))
    grid = fig.add_gridspec(len(kinds), 2, height_ratios=heights, width_ratios=(2.3, 1.0),
                            hspace=0.42, wspace=0.22, top=1.0 - 1.5 / height,
                            bottom=0.5 / height, left=0.05, right=0.93)
    cmap = plt.get_cmap("RdYlGn_r")
    image = None
    for index, kind in enumerate(kinds):
        group = [w for w in walks if w["kind"] == kind]
        sketch = fig.add_subplot(grid[index, 0])
        draw_scene(sketch, representative(group))
        sketch.text(-0.06, 1.12, dict(KINDS).get(kind, kind), transform=sketch.transAxes,
                    fontsize=10, fontweight="bold", ha="left")
        image = draw_grid(fig.add_subplot(grid[index, 1]), group, cmap)
    bar = fig.colorbar(image, ax=fig.axes, shrink=0.25, pad=0.02, fraction=0.02,
                       anchor=(0.0, 1.0))
    bar.set_label("time to pass / time allowed (grey: never past)", fontsize=8)
    handles = [Line2D([], [], color=COM_COLOUR, linewidth=1.2, label="CoM"),
               Line2D([], [], color="tab:cyan", linewidth=1.0, label="commanded path"),
               Line2D([], [], color="tab:purple", linestyle="--", linewidth=1.3,
                      label="shortest free path"),
               Line2D([], [], color="0.55", linestyle=":",
                      label="room the CoM needs (margin + foot + half the step width)"),
               Line2D([], [], color="0.35", linestyle="--", label="margin")]
    fig.legend(handles=handles, loc="upper left", ncol=5, fontsize=8,
               bbox_to_anchor=(0.04, 1.0 - 0.65 / height))
    fig.text(0.04, 1.0 - 0.12 / height,
             "%s: %d walks, %s.\nTop views: one walk per kind of scene (left foot blue, right "
             "red). Grids: every walk; s past late, relaxed or not walking on, B blocked,\n"
             "F failed, ! a step centre inside a margin; framed: a scene without a passage (the "
             "robot should stop: B)."
             % (source, len(walks), count_line(walks)), fontsize=9, va="top")
    save_figure(fig, output, dpi=80, metadata=png_metadata(source))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("batch_file")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--table", help="also write the table of every walk (Markdown)")
    args = parser.parse_args()
    walks = read(args.batch_file)
    draw(walks, args.output, os.path.basename(args.batch_file))
    if args.table:
        write_table(walks, args.table)
    for kind in kinds_of(walks):
        group = [w for w in walks if w["kind"] == kind]
        print("%-9s %3d walks: %s" % (kind, len(group), count_line(group)))
    print("%d walks: %s" % (len(walks), count_line(walks)))
    return 0


if __name__ == "__main__":
    run_script(SCRIPT, main)
