#!/usr/bin/python3
"""plot_compare.py STUDY.h5 -o DIR: the figures of a `wpg compare` study.

DIR/success_rates.png   goal reached / runs per world (groups) and variant (bars)
DIR/time_to_goal.png    time to goal of the runs that reached it, a box per world x variant
DIR/top_<world>.png     a top view per world: its obstacles (margins dashed), the goal, and the
                        CoM path of every variant (one colour and line style each, every seed; a run that
                        missed the goal ends with a cross). A world drawn per seed (a random
                        field) is shown for its first seed only.

Reads /compare/summary, /batch/summary and the runs' com, obstacles/ and goal attributes with
h5py only (layout: datasets/SCHEMA.md, "Comparison studies"), every dataset and attribute
checked (wpg_file_reading.py); a bad file gives one line, `plot_compare.py: FILE: /path:
expected ...`, and exit status 2. Debian's h5py and matplotlib.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wpg_file_reading import (  # noqa: E402
    Reader, import_h5py, open_file, png_metadata, run_script, save_figure)

SCRIPT = "plot_compare.py"
import_h5py(SCRIPT)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Circle, Polygon  # noqa: E402

from run_figure.geometry import convex_hull  # noqa: E402  (one hull for every figure)

OBSTACLE_COLOUR = "0.35"
# Figures drawn per world, boxes per world x variant: a study's file may declare any number.
MAX_WORLDS, MAX_VARIANTS = 100, 50


def read_obstacles(reader, run):
    """The run's obstacles/ datasets, checked against each other."""
    group = reader.group(run, "obstacles")
    ob = {"type": reader.dataset(group, "type", kind="integer")}
    n = len(ob["type"])
    ob["margin"] = reader.dataset(group, "margin", rows=n)
    ob["center"] = reader.dataset(group, "center", columns=2, rows=n)
    ob["radius"] = reader.dataset(group, "radius", rows=n)
    ob["vertices"] = reader.dataset(group, "vertices", columns=2)
    ob["vertex_start"] = reader.dataset(group, "vertex_start", kind="integer", rows=n)
    ob["vertex_count"] = reader.dataset(group, "vertex_count", kind="integer", rows=n)
    start, count = ob["vertex_start"], ob["vertex_count"]
    if np.any(start < 0) or np.any(count < 0) or np.any(start + count > len(ob["vertices"])):
        reader.fail(group.name + "/vertex_start", "expected rows of vertices (%d rows) with "
                    "vertex_count" % len(ob["vertices"]))
    return ob


def obstacle_outlines(ob):
    """(outline, margin, circle) per obstacle; circle = (cx, cy, r) or None."""
    shapes = []
    for i in range(len(ob["type"])):
        margin = float(ob["margin"][i])
        if int(ob["type"][i]) == 0:
            cx, cy = ob["center"][i]
            r = float(ob["radius"][i])
            outline = [(cx + r * math.cos(a), cy + r * math.sin(a))
                       for a in np.linspace(0.0, 2.0 * math.pi, 48, endpoint=False)]
            shapes.append((outline, margin, (cx, cy, r)))
        else:
            s, c = int(ob["vertex_start"][i]), int(ob["vertex_count"][i])
            shapes.append(([tuple(p) for p in ob["vertices"][s:s + c]], margin, None))
    return shapes


def grown(outline, margin, circle):
    if circle is not None:
        cx, cy, r = circle
        return [(cx + (r + margin) * math.cos(a), cy + (r + margin) * math.sin(a))
                for a in np.linspace(0.0, 2.0 * math.pi, 64, endpoint=False)]
    points = sorted({(x + margin * math.cos(a), y + margin * math.sin(a))
                     for x, y in outline for a in np.linspace(0.0, 2.0 * math.pi, 24,
                                                               endpoint=False)})

    return convex_hull(points)


def draw_world(ax, reader, run):
    for outline, margin, circle in obstacle_outlines(read_obstacles(reader, run)):
        ax.add_patch(Polygon(outline, closed=True, facecolor=OBSTACLE_COLOUR, alpha=0.45,
                             edgecolor=OBSTACLE_COLOUR, linewidth=1.0))
        if margin > 0:
            ax.add_patch(Polygon(grown(outline, margin, circle), closed=True, fill=False,
                                 edgecolor=OBSTACLE_COLOUR, linestyle="--", linewidth=0.7))
    gx, gy = reader.attribute(run, "goal_x"), reader.attribute(run, "goal_y")
    tolerance = reader.attribute(run, "goal_tolerance")
    if not all(math.isfinite(v) for v in (gx, gy, tolerance)) or tolerance < 0:
        reader.fail(run.name + ":goal_x", "expected a finite goal and tolerance >= 0")
    ax.add_patch(Circle((gx, gy), tolerance, fill=False,
                        edgecolor="black", linewidth=1.0))
    ax.plot([gx], [gy], marker="*", color="gold", markeredgecolor="black", markersize=13,
            linestyle="none", zorder=5)
    ax.plot([0.0], [0.0], marker="o", color="black", markersize=5, linestyle="none", zorder=5)


def same_world(reader, runs, names):
    """Whether the runs `names` have the same obstacles (a fixed world, not drawn per seed)."""
    first = read_obstacles(reader, reader.group(runs, names[0]))
    for name in names[1:]:
        other = read_obstacles(reader, reader.group(runs, name))
        for key in ("center", "radius", "vertices"):
            if first[key].shape != other[key].shape or not np.array_equal(first[key],
                                                                           other[key]):
                return False
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("study_file")
    parser.add_argument("-o", "--output", required=True, help="folder for the figures")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)

    with open_file(args.study_file) as f:
        reader = Reader(args.study_file, f)
        study = reader.attribute(f, "study_name", kind="text")
        compare = reader.group(f, "compare")
        worlds = reader.attribute(compare, "worlds", kind="texts")
        variants = reader.attribute(compare, "variants", kind="texts")
        if not 0 < len(worlds) <= MAX_WORLDS or not 0 < len(variants) <= MAX_VARIANTS:
            reader.fail(compare.name + ":worlds", "expected 1 to %d worlds and 1 to %d variants"
                        % (MAX_WORLDS, MAX_VARIANTS))
        cells = reader.group(compare, "summary")
        cell_world = list(reader.dataset(cells, "world", kind="text"))
        rows = len(cell_world)
        cell_variant = list(reader.dataset(cells, "variant", kind="text", rows=rows))
        rates = reader.dataset(cells, "success_rate", rows=rows, finite=False)
        success = {(w, v): r for w, v, r in zip(cell_world, cell_variant, rates)}
        counts = reader.dataset(cells, "runs", rows=rows)
        runs_per_cell = {(w, v): int(n) for w, v, n in zip(cell_world, cell_variant, counts)}
        for w in worlds:
            for v in variants:
                if (w, v) not in success:
                    reader.fail(cells.name + "/world", "expected a row for world %s, variant %s"
                                % (w, v))
        table = reader.group(reader.group(f, "batch"), "summary")
        run_names = list(reader.dataset(table, "name", kind="text"))
        rows = len(run_names)
        run_world = list(reader.dataset(table, "sweep.world", kind="text", rows=rows))
        run_variant = list(reader.dataset(table, "sweep.variant", kind="text", rows=rows))
        run_seed = reader.dataset(table, "sweep.seed", rows=rows)
        time_to_goal = reader.dataset(table, "time_to_goal", rows=rows, finite=False)
        reached = reader.dataset(table, "goal_reached", kind="integer", rows=rows)
        runs = reader.group(f, "runs")
        colours = {v: plt.get_cmap("tab10")(i % 10) for i, v in enumerate(variants)}
        # Line styles too: variants that walk the same route (a planner with NMPC and with
        # LMPC) draw nearly the same CoM path, and a solid line would hide the other.
        styles = {v: ("-", "--", ":", "-.")[i % 4] for i, v in enumerate(variants)}

        # Success rates: a group of bars per world.
        fig, ax = plt.subplots(figsize=(max(6.0, 0.4 * len(worlds) * len(variants) + 2.0), 4.0))
        width = 0.8 / max(1, len(variants))
        for k, variant in enumerate(variants):
            xs = np.arange(len(worlds)) + (k - (len(variants) - 1) / 2) * width
            values = [100.0 * success[(w, variant)] for w in worlds]
            bars = ax.bar(xs, values, width, label=variant, color=colours[variant])
            for bar, w in zip(bars, worlds):
                ax.annotate("%d" % round(100.0 * success[(w, variant)]),
                            (bar.get_x() + bar.get_width() / 2, bar.get_height()),
                            ha="center", va="bottom", fontsize=7)
        ax.set_xticks(np.arange(len(worlds)))
        ax.set_xticklabels(worlds)
        ax.set_ylim(0, 112)
        ax.set_ylabel("goal reached [% of runs]")
        seeds = max(runs_per_cell.values()) if runs_per_cell else 0
        ax.set_title("%s: success rate per world and variant (%d seeds)" % (study, seeds))
        ax.legend(fontsize=8, ncol=min(len(variants), 4), loc="upper center",
                  bbox_to_anchor=(0.5, -0.1))
        fig.tight_layout()
        save_figure(fig, os.path.join(args.output, "success_rates.png"), dpi=110, metadata=png_metadata(args.study_file))
        plt.close(fig)

        # Time to goal: a box per world x variant (reached runs only; empty boxes say "none").
        fig, axes = plt.subplots(1, len(worlds), figsize=(3.2 * len(worlds) + 1.0, 4.2),
                                 squeeze=False, sharey=True)
        for ax, world in zip(axes[0], worlds):
            data, labels = [], []
            for variant in variants:
                mask = [(w == world and v == variant and r == 1)
                        for w, v, r in zip(run_world, run_variant, reached)]
                data.append(time_to_goal[np.array(mask, dtype=bool)])
                labels.append(variant)
            positions = np.arange(1, len(variants) + 1)
            drawn = [d if len(d) else [np.nan] for d in data]
            boxes = ax.boxplot(drawn, positions=positions, widths=0.6, patch_artist=True,
                               showfliers=True)
            for patch, variant in zip(boxes["boxes"], variants):
                patch.set_facecolor(colours[variant])
                patch.set_alpha(0.6)
            for position, d in zip(positions, data):
                if len(d) == 0:
                    ax.annotate("none\nreached", (position, 0.5), xycoords=("data", "axes fraction"),
                                ha="center", fontsize=7, color="tab:red")
            ax.set_xticks(positions)
            ax.set_xticklabels(labels, rotation=35, ha="right", fontsize=7)
            ax.set_title(world, fontsize=9)
            ax.grid(axis="y", alpha=0.3)
        axes[0][0].set_ylabel("time to goal [s]")
        fig.suptitle("%s: time to goal of the runs that reached it" % study, fontsize=10)
        fig.tight_layout()
        save_figure(fig, os.path.join(args.output, "time_to_goal.png"), dpi=110, metadata=png_metadata(args.study_file))
        plt.close(fig)

        # A top view per world.
        for world in worlds:
            names = [n for n, w in zip(run_names, run_world) if w == world]
            fixed = same_world(reader, runs, names)
            first_seed = min(s for s, w in zip(run_seed, run_world) if w == world)
            fig, ax = plt.subplots(figsize=(8.0, 5.0))
            drawn_world = False
            missed = False
            for name, w, v, s, r in zip(run_names, run_world, run_variant, run_seed, reached):
                if w != world or (not fixed and s != first_seed):
                    continue
                run = reader.group(runs, name)
                if not drawn_world:
                    draw_world(ax, reader, run)
                    drawn_world = True
                com = reader.dataset(run, "com", columns=3)
                if not len(com):
                    continue
                ax.plot(com[:, 0], com[:, 1], color=colours[v], linestyle=styles[v], linewidth=0.9,
                        alpha=0.75)
                if r != 1:
                    missed = True
                    ax.plot([com[-1, 0]], [com[-1, 1]], marker="x", color=colours[v],
                            markersize=8, markeredgewidth=2, linestyle="none")
            for variant in variants:
                ax.plot([], [], color=colours[variant], linestyle=styles[variant], label=variant)
            if missed:  # only when a run drawn here missed the goal
                ax.plot([], [], marker="x", color="black", linestyle="none", label="goal missed")
            ax.set_aspect("equal")
            ax.autoscale_view()
            ax.set_xlabel("x [m]")
            ax.set_ylabel("y [m]")
            ax.grid(alpha=0.3)
            which = "every seed" if fixed else "seed %d (the world is drawn per seed)" % first_seed
            ax.set_title("%s / %s: CoM paths, %s" % (study, world, which), fontsize=10)
            # Beside the axes: inside, "best" can cover obstacles.
            ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0))
            fig.tight_layout()
            save_figure(fig, os.path.join(args.output, "top_%s.png" % world), dpi=110, bbox_inches="tight", metadata=png_metadata(args.study_file))
            plt.close(fig)
    return 0


if __name__ == "__main__":
    run_script(SCRIPT, main)
