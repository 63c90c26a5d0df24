"""Predicted against executed (`wpg plot RUN.h5 --plan`): what the NMPC previewed at a few
iterations beside what the robot then did. Left, the top view of the walk with each chosen
iteration's previewed CoM (dots, one per sample of the horizon) and previewed steps (dashed
soles); right, CoM x and y against time with the same previews, and the distance between the
predicted and the executed CoM against the look-ahead over every iteration of the walk (the
first look-ahead is the CoM executed next: 0 up to rounding, unless a push acted)."""
import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon

from .geometry import sole_corners
from .plan_reading import prediction_errors
from .styles import COM_COLOUR
from .top_view import draw_top_view

# Distances below this are drawn at it on the log scale (an exact 0 has no logarithm).
ERROR_FLOOR = 1e-16


def chosen_iterations(plan, at_times):
    """The iterations at or before each time of `at_times` (default: four evenly spread over
    the middle half of the walk), without repeats."""
    time = plan["time"]
    if not at_times:
        at_times = list(np.linspace(time[0], time[-1], 6)[1:-1])
    chosen = []
    for t in at_times:
        i = max(0, int(np.searchsorted(time, t + 1e-9)) - 1)
        if i not in chosen:
            chosen.append(i)
    return chosen


def draw_previews(axes, run, plan, chosen, foot_length, foot_width, colours):
    top, x_axis, y_axis = axes
    time, com = run["time"], run["com"]
    handles = []
    for i, colour in zip(chosen, colours):
        t0, count = plan["time"][i], int(plan["count"][i])
        start = com[min(np.searchsorted(time, t0 - 1e-9), len(com) - 1), :2]
        predicted = np.vstack([start, plan["com"][i, :count]])
        instants = t0 + plan["period"] * np.arange(count + 1)
        top.plot(predicted[:, 0], predicted[:, 1], linestyle="--", marker=".", markersize=4,
                 color=colour, linewidth=1.2, zorder=6)
        top.plot(*start, marker="*", markersize=10, color=colour, markeredgecolor="black",
                 zorder=7)
        for landing, x, y, yaw in plan["steps_pose"][i]:
            if count and landing > t0:
                top.add_patch(Polygon(sole_corners(x, y, yaw, foot_length, foot_width),
                                      closed=True, fill=False, edgecolor=colour, linewidth=1.3,
                                      linestyle="--", zorder=6))
        for ax, column in ((x_axis, 0), (y_axis, 1)):
            ax.plot(instants, predicted[:, column], linestyle="--", marker=".", markersize=3,
                    color=colour, linewidth=1.2)
            ax.axvline(t0, color=colour, linewidth=0.6, linestyle=":")
        handles.append(Line2D([], [], color=colour, linestyle="--", marker=".",
                              label="preview at t = %.1f s (%d samples, %d steps)"
                              % (t0, count, int(np.sum(plan["steps_pose"][i, :, 0] > t0)))))
    for ax, column, name in ((x_axis, 0, "x"), (y_axis, 1, "y")):
        ax.plot(time, com[:, column], color=COM_COLOUR, linewidth=1.4, label="executed CoM")
        ax.set_ylabel("CoM %s [m]" % name)
        ax.grid(True, linewidth=0.4, alpha=0.5)
    x_axis.set_title("CoM executed (black) and as previewed (dashed)", fontsize=10)
    y_axis.set_xlabel("time [s]")
    x_axis.legend(handles=handles + [Line2D([], [], color=COM_COLOUR, label="executed CoM")],
                  fontsize=7, loc="best")


def draw_errors(ax, plan, errors, pushed):
    look_ahead = np.arange(1, len(errors) + 1)
    rows = [e for e in errors if len(e)]
    if not rows:
        ax.text(0.5, 0.5, "no previewed sample within the walk", ha="center",
                transform=ax.transAxes)
        return
    steps = look_ahead[:len(rows)]
    for q, style, label in ((50, "-o", "median"), (95, "--s", "95th percentile"),
                            (100, ":^", "largest")):
        values = np.maximum([np.percentile(e, q) for e in rows], ERROR_FLOOR)
        ax.semilogy(steps, values, style, markersize=3, linewidth=1.1, label=label)
    ax.set_xlabel("look-ahead [samples of %.3g s]" % plan["period"])
    ax.set_ylabel("|predicted - executed CoM| [m]")
    ax.set_title("prediction error over %d iterations; look-ahead 1 (executed next): largest "
                 "%.1e m%s" % (len(plan["time"]), float(np.max(rows[0])),
                               ", pushed" if pushed else ""), fontsize=9)
    ax.grid(True, which="both", linewidth=0.4, alpha=0.5)
    ax.legend(fontsize=7, loc="lower right")


def draw_plan_figure(fig, run, plan, at_times, foot_length, foot_width, obstacles, pushed,
                     margins=None):
    """The panels on `fig`, in a grid with the `margins` given (bottom, top: figure.py's
    figure_with_legend_room), matplotlib's defaults without."""
    grid = fig.add_gridspec(3, 2, width_ratios=(1.2, 1.0), hspace=0.45, wspace=0.2,
                            **(margins or {}))
    top = fig.add_subplot(grid[:, 0])
    x_axis = fig.add_subplot(grid[0, 1])
    y_axis = fig.add_subplot(grid[1, 1], sharex=x_axis)
    error_axis = fig.add_subplot(grid[2, 1])
    draw_top_view(top, run, foot_length, foot_width, obstacles)
    chosen = chosen_iterations(plan, at_times)
    colours = ["tab:orange", "tab:purple", "tab:cyan", "tab:olive", "tab:brown", "tab:pink"]
    colours = (colours * (len(chosen) // len(colours) + 1))[:len(chosen)]
    draw_previews((top, x_axis, y_axis), run, plan, chosen, foot_length, foot_width, colours)
    top.set_title("top view; stars: the CoM when each preview was made", fontsize=10)
    draw_errors(error_axis, plan, prediction_errors(plan, run["time"], run["com"]), pushed)
    top.text(0.0, 1.06, "run %s: what the NMPC previewed, and what the robot did" % run["name"],
             transform=top.transAxes, fontsize=12, fontweight="bold", ha="left", va="bottom")
