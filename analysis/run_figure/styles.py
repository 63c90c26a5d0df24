"""Colours, markers and sizes shared by the panels of the run figure."""

# HRP-2 sole, used when the run's scenario text does not give the foot size.
DEFAULT_FOOT_LENGTH = 0.2172  # [m]
DEFAULT_FOOT_WIDTH = 0.138  # [m]

LEFT_COLOUR = "tab:blue"
RIGHT_COLOUR = "tab:red"
COM_COLOUR = "black"
COP_COLOUR = "tab:green"
PUSH_COLOUR = "tab:purple"
# The planner's routes, one colour per (re)plan: none of them the CoP's green or the CoM's black.
ROUTE_COLOURS = ["tab:purple", "tab:cyan", "tab:brown", "tab:olive", "tab:pink"]

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
# The solve-time panel's scale when an iteration is more than twice the 98th percentile: this
# factor times the 98th percentile, so that one slow iteration (10 ms) does not squash the
# typical ones (~10 µs); the iterations above it are drawn on the top edge and named.
SOLVE_SCALE_PERCENTILE = 98
SOLVE_SCALE_FACTOR = 2.0
OBSTACLE_COLOUR = "0.35"
# Fig. 6 of the paper: reference CoP solid blue, ZMP before the filter dash-dot red, after the
# filter dashed green.
FIG6_REFERENCE = dict(color="tab:blue", linestyle="-", linewidth=1.4)
FIG6_BEFORE = dict(color="tab:red", linestyle="-.", linewidth=1.2)
FIG6_AFTER = dict(color="tab:green", linestyle="--", linewidth=1.4)
FIG6_WINDOW = 3.0  # [s] of steady walking shown per axis
