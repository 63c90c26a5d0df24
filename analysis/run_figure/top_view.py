"""The top view of a run: footsteps as oriented soles, CoM and CoP paths, obstacles with their
margins, the goal and the planner's routes."""
import math

from matplotlib.lines import Line2D
from matplotlib.patches import Circle, Patch, Polygon

from .geometry import grown_outline, sole_corners
from .styles import (COM_COLOUR, COP_COLOUR, LEFT_COLOUR, OBSTACLE_COLOUR, RIGHT_COLOUR,
                     ROUTE_COLOURS)


def draw_goal(ax, goal):
    """The goal (its tolerance circle, its yaw) and every route the planner gave."""
    colours = ROUTE_COLOURS
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
    # Below the axes: inside, "best" still covered obstacles (goal_u_trap's wall).
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.09), ncol=3,
              fontsize=8, framealpha=0.85)
