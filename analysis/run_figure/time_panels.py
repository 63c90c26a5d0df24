"""The panels against time: CoM and CoP x and y, and the NMPC solve time per iteration with
its status, over the support phases."""
import numpy as np

from .styles import (COM_COLOUR, COP_COLOUR, FAILED_STATUSES, LEFT_COLOUR, PUSH_COLOUR,
                     RIGHT_COLOUR, SOLVE_SCALE_FACTOR, SOLVE_SCALE_PERCENTILE, STATUS_STYLE)


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


def duration_text(microseconds):
    return "%.1f ms" % (1e-3 * microseconds) if microseconds >= 1000 else "%.0f µs" % microseconds


def scale_top(solve_us):
    """The top of the solve-time scale [µs]: 1.5 times the largest iteration (headroom for the
    legend), or, when that iteration is more than twice the 98th percentile,
    SOLVE_SCALE_FACTOR times the 98th percentile: one slow iteration does not squash the
    typical ones."""
    largest = max(float(np.max(solve_us)), 1e-9)
    typical = float(np.percentile(solve_us, SOLVE_SCALE_PERCENTILE))
    if largest <= 2.0 * typical:
        return 1.5 * largest
    return max(SOLVE_SCALE_FACTOR * typical, 1e-9)


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
        title = "NMPC solve time per iteration: median %.0f µs, max %.0f µs" % (
            np.median(solve_us), np.max(solve_us))
        ax.set_ylabel("solve [µs]")
        top = scale_top(solve_us)
        above = solve_us > top
        if np.any(above):
            # The iterations beyond the scale: triangles on the top edge, counted in the title
            # with the largest value.
            ax.plot(mpc_time[above], np.full(int(np.count_nonzero(above)), 0.97 * top), "^",
                    color="tab:red", markersize=6, clip_on=False, zorder=4)
            title += "\n%d above the scale (red ▲), the largest %s" % (
                int(np.count_nonzero(above)), duration_text(float(np.max(solve_us))))
        ax.set_title(title, fontsize=9)
        ax.set_ylim(0, top)
        ax.legend(loc="upper right", fontsize=7, framealpha=0.85, ncol=3)
    else:
        ax.step(time, run["support"], where="post", color="black", linewidth=1.0)
        ax.set_yticks([0, 1, 2])
        ax.set_yticklabels(["double", "left", "right"])
        ax.set_ylabel("support")
    ax.set_xlabel("time [s]   (shaded: left / right single support)")
    ax.grid(True, linewidth=0.4, alpha=0.5)
