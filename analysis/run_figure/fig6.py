"""The paper's Fig. 6 analogue: reference CoP, multibody ZMP before and after the dynamic
filter over a few seconds of steady walking, and |CoP - ZMP| over the whole walk."""
import numpy as np

from .styles import FIG6_AFTER, FIG6_BEFORE, FIG6_REFERENCE, FIG6_WINDOW
from .time_panels import shade_support, support_spans


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
