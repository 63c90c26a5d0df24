"""The run figure: one row of panels per run (top view, time panels, and the Fig. 6 row when
the run was replayed), written atomically as a PNG."""
import math
import os

import matplotlib.pyplot as plt

from wpg_file_reading import png_metadata, save_figure, walking_number

from .fig6 import draw_fig6
from .scenario_text import describe_command, fmt_number, scenario_obstacles, scenario_pushes
from .styles import DEFAULT_FOOT_LENGTH, DEFAULT_FOOT_WIDTH
from .time_panels import draw_time_panels
from .top_view import draw_top_view


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


def save_atomically(fig, output, source=""):
    """The run's figure at `output`, through wpg_file_reading.save_figure (temporary file and
    rename), with the PNG text naming `source`."""
    save_figure(fig, output, dpi=110, bbox_inches="tight", metadata=png_metadata(source))
