"""The run figure: one row of panels per run (top view, time panels, and the Fig. 6 row when
the run was replayed), written atomically as a PNG."""
import math
import os

import matplotlib.pyplot as plt
from matplotlib.transforms import blended_transform_factory

from wpg_file_reading import png_metadata, save_figure_cropped, walking_number

from .fig6 import draw_fig6
from .scenario_text import describe_command, fmt_number, scenario_obstacles, scenario_pushes
from .styles import DEFAULT_FOOT_LENGTH, DEFAULT_FOOT_WIDTH
from .time_panels import draw_time_panels
from .top_view import draw_top_view


# Below the last row's top view hangs its legend (up to three rows of entries): the figure keeps
# this much more room under matplotlib's default bottom margin, so that the whole drawing is on
# the canvas and save_atomically can crop it after one draw (wpg_file_reading.py).
LEGEND_ROOM = 0.8  # [in]


def figure_with_legend_room(width, height):
    """A figure laid out as plt.figure(figsize=(width, height)) with matplotlib's default
    margins, LEGEND_ROOM taller at the bottom: (figure, the bottom and top of its gridspec)."""
    total = height + LEGEND_ROOM
    fig = plt.figure(figsize=(width, total))
    bottom = (plt.rcParams["figure.subplot.bottom"] * height + LEGEND_ROOM) / total
    top = 1.0 - (1.0 - plt.rcParams["figure.subplot.top"]) * height / total
    return fig, {"bottom": bottom, "top": top}


def draw(runs, source_path):
    rows = len(runs)
    heights = [6.8 + (3.4 if run["multibody"] is not None else 0.0) for run in runs]
    fig, margins = figure_with_legend_room(15, sum(heights))
    outer = fig.add_gridspec(rows, 1, hspace=0.35 if rows > 1 else 0.0, height_ratios=heights,
                             **margins)
    for row, run in enumerate(runs):
        scenario = run["scenario"]
        foot_length = walking_number(scenario, "foot_length", DEFAULT_FOOT_LENGTH)
        foot_width = walking_number(scenario, "foot_width", DEFAULT_FOOT_WIDTH)
        cell = outer[row]
        if run["multibody"] is not None:
            split = cell.subgridspec(2, 1, height_ratios=(6.8, 3.4), hspace=0.5)
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
        if row == 0:
            # The file's name at the right end of the first title's line, clear of the canvas's
            # border (the PNG is cropped to the drawing with 0.1 in round it, save_atomically).
            fig.text(1.0 - 0.15 / fig.get_size_inches()[0], 1.06, os.path.basename(source_path),
                     transform=blended_transform_factory(fig.transFigure, top.transAxes),
                     ha="right", va="bottom", fontsize=7, color="0.4")
    return fig


def save_atomically(fig, output, source=""):
    """The run's figure at `output`, cropped to its drawing, through
    wpg_file_reading.save_figure_cropped (temporary file and rename), with the PNG text naming
    `source`."""
    save_figure_cropped(fig, output, dpi=110, metadata=png_metadata(source))
