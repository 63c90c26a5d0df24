#!/usr/bin/python3
"""plot_compare.py STUDY.h5 -o DIR: the figures of a `wpg compare` study.

DIR/success_rates.png   goal reached / runs per world (groups) and variant (bars)
DIR/time_to_goal.png    time to goal of the runs that reached it, a box per world x variant
DIR/top_<world>.png     a top view per world: its obstacles (margins dashed), the goal, and the
                        CoM path of every variant (one colour and line style each, every seed; a run that
                        missed the goal ends with a cross). A world drawn per seed (a random
                        field) is shown for its first seed only.

Reads /compare/summary, /batch/summary and the runs' com, obstacles/ and goal attributes with
h5py only (layout: datasets/SCHEMA.md, "Comparison studies"). Debian's h5py and matplotlib.
"""
import argparse
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Circle, Polygon  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_run import convex_hull  # noqa: E402  (one hull for every figure)

OBSTACLE_COLOUR = "0.35"


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def texts(values):
    return [text(v) for v in values]


def obstacle_outlines(run):
    """(outline, margin, circle) per obstacle; circle = (cx, cy, r) or None."""
    ob = run["obstacles"]
    shapes = []
    for i in range(int(ob.attrs["count"])):
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


def draw_world(ax, run):
    for outline, margin, circle in obstacle_outlines(run):
        ax.add_patch(Polygon(outline, closed=True, facecolor=OBSTACLE_COLOUR, alpha=0.45,
                             edgecolor=OBSTACLE_COLOUR, linewidth=1.0))
        if margin > 0:
            ax.add_patch(Polygon(grown(outline, margin, circle), closed=True, fill=False,
                                 edgecolor=OBSTACLE_COLOUR, linestyle="--", linewidth=0.7))
    gx, gy = float(run.attrs["goal_x"]), float(run.attrs["goal_y"])
    ax.add_patch(Circle((gx, gy), float(run.attrs["goal_tolerance"]), fill=False,
                        edgecolor="black", linewidth=1.0))
    ax.plot([gx], [gy], marker="*", color="gold", markeredgecolor="black", markersize=13,
            linestyle="none", zorder=5)
    ax.plot([0.0], [0.0], marker="o", color="black", markersize=5, linestyle="none", zorder=5)


def same_world(f, names):
    """Whether the runs `names` have the same obstacles (a fixed world, not drawn per seed)."""
    first = f["runs"][names[0]]["obstacles"]
    for name in names[1:]:
        other = f["runs"][name]["obstacles"]
        for key in ("center", "radius", "vertices"):
            if first[key].shape != other[key].shape or not np.array_equal(first[key][()],
                                                                           other[key][()]):
                return False
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("study_file")
    parser.add_argument("-o", "--output", required=True, help="folder for the figures")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)

    with h5py.File(args.study_file, "r") as f:
        study = text(f.attrs["study_name"])
        worlds = texts(f["compare"].attrs["worlds"])
        variants = texts(f["compare"].attrs["variants"])
        cells = f["compare/summary"]
        cell_world = texts(cells["world"][:])
        cell_variant = texts(cells["variant"][:])
        success = {(w, v): r for w, v, r in zip(cell_world, cell_variant, cells["success_rate"][:])}
        runs_per_cell = {(w, v): int(n) for w, v, n in zip(cell_world, cell_variant,
                                                          cells["runs"][:])}
        table = f["batch/summary"]
        run_names = texts(table["name"][:])
        run_world = texts(table["sweep.world"][:])
        run_variant = texts(table["sweep.variant"][:])
        run_seed = table["sweep.seed"][:]
        time_to_goal = table["time_to_goal"][:]
        reached = table["goal_reached"][:]
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
        fig.savefig(os.path.join(args.output, "success_rates.png"), dpi=110)
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
        fig.savefig(os.path.join(args.output, "time_to_goal.png"), dpi=110)
        plt.close(fig)

        # A top view per world.
        for world in worlds:
            names = [n for n, w in zip(run_names, run_world) if w == world]
            fixed = same_world(f, names)
            first_seed = min(s for s, w in zip(run_seed, run_world) if w == world)
            fig, ax = plt.subplots(figsize=(8.0, 5.0))
            drawn_world = False
            for name, w, v, s, r in zip(run_names, run_world, run_variant, run_seed, reached):
                if w != world or (not fixed and s != first_seed):
                    continue
                run = f["runs"][name]
                if not drawn_world:
                    draw_world(ax, run)
                    drawn_world = True
                com = run["com"][()]
                ax.plot(com[:, 0], com[:, 1], color=colours[v], linestyle=styles[v], linewidth=0.9,
                        alpha=0.75)
                if r != 1:
                    ax.plot([com[-1, 0]], [com[-1, 1]], marker="x", color=colours[v],
                            markersize=8, markeredgewidth=2, linestyle="none")
            for variant in variants:
                ax.plot([], [], color=colours[variant], linestyle=styles[variant], label=variant)
            ax.plot([], [], marker="x", color="black", linestyle="none", label="goal missed")
            ax.set_aspect("equal")
            ax.autoscale_view()
            ax.set_xlabel("x [m]")
            ax.set_ylabel("y [m]")
            ax.grid(alpha=0.3)
            which = "every seed" if fixed else "seed %d (the world is drawn per seed)" % first_seed
            ax.set_title("%s / %s: CoM paths, %s" % (study, world, which), fontsize=10)
            ax.legend(fontsize=8, loc="best")
            fig.tight_layout()
            fig.savefig(os.path.join(args.output, "top_%s.png" % world), dpi=110)
            plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
