"""check_metrics.py FILE.h5 METRICS.json: every metric that `wpg analyze FILE.h5 --format json`
printed (METRICS.json) agrees with a recomputation from the raw fields of FILE.h5, read with
h5py and computed here with numpy, following the definitions of datasets/METRICS.md (not the
analysis library). Exit 0 when all agree, 1 otherwise (each disagreement on stderr).
"""
import json
import math
import sys

import h5py
import numpy as np
import yaml

RTOL, ATOL = 1e-9, 1e-12
errors = []


def hull(points):
    """Convex hull, counter-clockwise (monotone chain)."""
    pts = sorted(set(map(tuple, np.round(points, 15))))
    if len(pts) < 3:
        return np.array(pts)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return np.array(lower[:-1] + upper[:-1])


def ccw(vertices):
    v = np.asarray(vertices, dtype=float)
    area = np.sum(v[:, 0] * np.roll(v[:, 1], -1) - np.roll(v[:, 0], -1) * v[:, 1])
    return v if area > 0 else v[::-1]


def inside_distance(vertices, p):
    """Signed distance inside a convex polygon to its nearest edge line (> 0 inside)."""
    return float(inside_distances(vertices, np.asarray(p, dtype=float)[None, :])[0])


def inside_distances(vertices, points):
    """inside_distance of each row of `points` (N x 2), for one polygon."""
    v = ccw(vertices)
    best = np.full(len(points), math.inf)
    for a, b in zip(v, np.roll(v, -1, axis=0)):
        edge = b - a
        outward = np.array([edge[1], -edge[0]]) / np.hypot(*edge)
        d = points - a
        best = np.minimum(best, -(outward[0] * d[:, 0] + outward[1] * d[:, 1]))
    return best


def rectangle(center, yaw, length, width):
    c, s = math.cos(yaw), math.sin(yaw)
    local = [(-length / 2, -width / 2), (length / 2, -width / 2), (length / 2, width / 2),
             (-length / 2, width / 2)]
    return np.array([(center[0] + c * x - s * y, center[1] + s * x + c * y) for x, y in local])


def polygon_signed_distance(vertices, p):
    """> 0 outside: distance to the nearest edge; inside: minus the distance to the nearest
    edge line."""
    d_in = inside_distance(vertices, p)
    if d_in >= 0:
        return -d_in
    best = math.inf
    v = ccw(vertices)
    for a, b in zip(v, np.roll(v, -1, axis=0)):
        t = np.clip(np.dot(p - a, b - a) / np.dot(b - a, b - a), 0.0, 1.0)
        best = min(best, np.hypot(*(p - (a + t * (b - a)))))
    return best


def quantile(values, q):
    return float(np.percentile(values, 100 * q)) if len(values) else math.nan


def steady_tracking(w, t, run, reference):
    """steady_vx/vy/omega and steady_tracking of datasets/METRICS.md."""
    keys = ("steady_vx", "steady_vy", "steady_omega", "steady_tracking")
    nan = {key: math.nan for key in keys}
    if not reference:
        return nan
    command = np.array(reference[-1]["v"], dtype=float)
    t_c = reference[-1]["t"]
    landings = [s[0] for s in run["footsteps"][2:] if s[0] >= t_c + 15.0 - 1e-9]
    # a gait cycle: two of the steady steps as walked (adaptive step timing), else two steps
    if len(landings) >= 3:
        cycle = 2 * (landings[-1] - landings[0]) / (len(landings) - 1)
    else:
        cycle = 2 * (w["single_support_samples"] + w["double_support_samples"]) * w["sampling_period"]
    h = int(round(cycle / (2 * w["control_period"])))
    n = len(t)
    if h == 0 or n < 2 * h + 1:
        return nan
    psi = np.unwrap(run["free_flyer_yaw"][:])
    sums = np.concatenate([[0.0], np.cumsum(psi)])

    def heading(i):
        return (sums[i + h] - sums[i - h]) / (2 * h)

    def sample(time):
        return int(np.searchsorted(t, time - 1e-9))
    steps = 0
    for k in range(2, len(landings), 2):
        if sample(landings[k]) + h <= n:
            steps = k
    if steps == 0:
        return nan
    a, b = sample(landings[0]), sample(landings[steps])
    if a < h or b <= a:
        return nan
    vel = run["com_vel"][a:b, :2]
    psi_bar = np.array([heading(i) for i in range(a, b)])
    c, s = np.cos(psi_bar), np.sin(psi_bar)
    vx = float(np.mean(c * vel[:, 0] + s * vel[:, 1]))
    vy = float(np.mean(-s * vel[:, 0] + c * vel[:, 1]))
    omega = float((heading(b) - heading(a)) / (t[b] - t[a]))
    score = max(abs(vx - command[0]) / max(0.1 * abs(command[0]), 0.01),
                abs(vy - command[1]) / max(0.1 * abs(command[1]), 0.01),
                abs(omega - command[2]) / max(0.1 * abs(command[2]), 0.01))
    return dict(zip(keys, (vx, vy, omega, float(score))))


def recompute(run, scenario):
    w = scenario["walking"]
    t = run["time"][:]
    com = run["com"][:]
    cop = run["cop"][:]
    left, right = run["left_foot"][:], run["right_foot"][:]
    yaw = run["free_flyer_yaw"][:]
    support = run["support"][:]
    steps = run["footsteps"][:]
    sides = run["footstep_side"][:]
    m = {}
    m["success"] = float(run.attrs["success"])
    # Stuck is an outcome: the run group's verdict (absent from older files: not blocked).
    m["blocked"] = float(run.attrs.get("blocked", 0))
    m["blocked_since"] = float(run.attrs["blocked_since"]) if m["blocked"] == 1 else math.nan
    # progress_ratio: over the NMPC rows with a linear command (> 1e-3 m/s) whose next
    # sampling instant is a sample of the walk, the CoM's displacement to it along the
    # commanded world velocity, over the commanded distance.
    m["progress_ratio"] = math.nan
    if "commanded_velocity" in run["mpc"]:
        T = w["sampling_period"]
        sub = int(round(T / w["control_period"]))
        velocity = run["mpc"]["commanded_velocity"][:]
        rows = np.round(run["mpc"]["time"][:] / w["control_period"]).astype(int)
        keep = (rows + sub <= len(t) - 1) & (np.linalg.norm(velocity, axis=1) > 1e-3)
        d = velocity[keep] * T
        length = np.linalg.norm(d, axis=1)
        if length.sum() > 0:
            walked = np.sum(np.sum((com[rows[keep] + sub, :2] - com[rows[keep], :2]) * d, axis=1) / length)
            m["progress_ratio"] = float(walked / length.sum())
    m["distance"] = float(np.hypot(*(com[-1, :2] - com[0, :2])))
    m["path_length"] = float(np.sum(np.hypot(*np.diff(com[:, :2], axis=0).T)))
    m["steps"] = float(max(len(steps) - 2, 0))
    m["duration"] = float(t[-1] - t[0])

    # velocity error over a gait cycle (two steps)
    step_duration = (w["single_support_samples"] + w["double_support_samples"]) * w["sampling_period"]
    window = int(round(2 * step_duration / w["control_period"]))
    # A walk to a goal: against the path follower's command of each NMPC iteration
    # (mpc/command; unknown without it), else the scenario's reference schedule.
    reference = scenario.get("reference") or []
    goal = bool(scenario.get("goal"))
    known = not goal or "command" in run["mpc"]
    if goal and known:
        iteration_times = run["mpc"]["time"][:]
        iteration_commands = run["mpc"]["command"][:]
    # The command of each sample: the goal walk's of the last iteration at or before it, then
    # the schedule's entries in order (a later one wins), in the world frame by the yaw.
    commands = np.zeros((len(t), 3))
    if goal and known:
        k = np.maximum(np.searchsorted(iteration_times, t + 1e-9, side="right") - 1, 0)
        commands[:] = iteration_commands[k]
    for entry in reference:
        commands[entry["t"] <= t + 1e-9] = np.array(entry["v"], dtype=float)
    c, s = np.cos(yaw), np.sin(yaw)
    ref = np.column_stack((c * commands[:, 0] - s * commands[:, 1],
                           s * commands[:, 0] + c * commands[:, 1]))
    # The start left out: windows beginning within one cycle of the first non-zero command.
    nonzero = np.flatnonzero(np.any(commands != 0.0, axis=1))
    moving = int(nonzero[0]) if len(nonzero) else 0
    # Window i: the CoM's mean velocity over samples i - window .. i against the mean of the
    # world command over samples i - window + 1 .. i.
    i = np.arange(moving + 2 * window if known and window > 0 else len(t), len(t))
    errs = []
    if len(i):
        mean_v = (com[i, :2] - com[i - window, :2]) / (t[i] - t[i - window])[:, None]
        windows = np.lib.stride_tricks.sliding_window_view(ref, window, axis=0)
        mean_ref = windows[i - window + 1].mean(axis=-1)
        errs = np.hypot(mean_v[:, 0] - mean_ref[:, 0], mean_v[:, 1] - mean_ref[:, 1])
    m["velocity_error_rms"] = float(np.sqrt(np.mean(np.square(errs)))) if len(errs) else math.nan
    m["velocity_error_max"] = float(np.max(errs)) if len(errs) else math.nan

    m.update(steady_tracking(w, t, run, reference))

    # CoP margin: the sole (single support) or the hull of both soles (double support). The
    # support polygon only changes when the support does or a supporting foot moves: it is built
    # once per distinct (support, supporting soles), and measured against their CoPs at once.
    margins = np.empty(len(t))
    stance = np.column_stack((support, left[:, [0, 1, 3]] * (support != 2)[:, None],
                              right[:, [0, 1, 3]] * (support != 1)[:, None]))
    _, stance_of = np.unique(stance, axis=0, return_inverse=True)
    for k in range(stance_of.max() + 1 if len(t) else 0):
        samples = np.flatnonzero(stance_of.ravel() == k)
        i = samples[0]
        corners = []
        if support[i] != 2:
            corners.append(rectangle(left[i, :2], left[i, 3], w["foot_length"], w["foot_width"]))
        if support[i] != 1:
            corners.append(rectangle(right[i, :2], right[i, 3], w["foot_length"], w["foot_width"]))
        polygon = hull(np.vstack(corners)) if support[i] == 0 else corners[0]
        margins[samples] = inside_distances(polygon, cop[samples, :2])
    m["cop_margin_min"] = float(np.min(margins))
    m["cop_margin_p05"] = quantile(margins, 0.05)
    m["cop_margin_median"] = quantile(margins, 0.5)
    m["cop_margin_mean"] = float(np.mean(margins))

    # steps against the previous other-side step: feasibility polygon (eq. 14), yaw bound
    fx, fy = w["feasibility_x"], w["feasibility_y"]
    feas, yawm = [], []
    for k in range(len(steps)):
        if steps[k, 0] <= 0:
            continue
        prev = next((steps[j] for j in range(k - 1, -1, -1) if sides[j] != sides[k]), None)
        if prev is None:
            continue
        c, s = math.cos(prev[3]), math.sin(prev[3])
        d = steps[k, 1:3] - prev[1:3]
        local = np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])
        sign = 1.0 if sides[k] == 1 else -1.0
        polygon = np.array([(fx[i], sign * fy[i]) for i in range(5)])
        feas.append(inside_distance(polygon, local))
        yawm.append(w["max_step_yaw_change"] - abs(steps[k, 3] - prev[3]))
    m["step_feasibility_margin_min"] = float(min(feas)) if feas else math.nan
    m["yaw_bound_margin_min"] = float(min(yawm)) if yawm else math.nan

    ob = run["obstacles"]
    count = int(ob.attrs["count"])
    if count and len(steps):
        clearances = []
        for k in range(len(steps)):
            p = steps[k, 1:3]
            for i in range(count):
                if ob["type"][i] == 0:
                    sd = np.hypot(*(p - ob["center"][i])) - ob["radius"][i]
                else:
                    s0, n = ob["vertex_start"][i], ob["vertex_count"][i]
                    sd = polygon_signed_distance(ob["vertices"][s0:s0 + n], p)
                clearances.append(sd - ob["margin"][i] - w["obstacle_foot_radius"])
        m["obstacle_clearance_min"] = float(min(clearances))
    else:
        m["obstacle_clearance_min"] = math.nan

    # swing foot's peaks: central differences of the ankles (x, y, z), the larger foot's
    if len(t) >= 3:
        dt0, dt1 = t[1:-1] - t[:-2], t[2:] - t[1:-1]
        speed, acc = [], []
        for foot in (left, right):
            p0, p1, p2 = foot[:-2, :3], foot[1:-1, :3], foot[2:, :3]
            speed.append(np.linalg.norm((p2 - p0) / (dt0 + dt1)[:, None], axis=1))
            acc.append(np.linalg.norm((p2 - p1) / dt1[:, None] - (p1 - p0) / dt0[:, None], axis=1)
                       / (0.5 * (dt0 + dt1)))
        m["swing_speed_max"] = float(max(v.max() for v in speed))
        m["swing_acceleration_max"] = float(max(a.max() for a in acc))
    else:
        m["swing_speed_max"] = m["swing_acceleration_max"] = math.nan
    # and the same peaks as the run's checks group stores them
    if "checks" in run and "swing_foot_speed_max" in run["checks"].attrs and len(t) >= 3:
        for key, attribute in (("swing_speed_max", "swing_foot_speed_max"),
                               ("swing_acceleration_max", "swing_foot_acceleration_max")):
            stored = float(run["checks"].attrs[attribute])
            if not math.isclose(stored, m[key], rel_tol=RTOL, abs_tol=ATOL):
                errors.append(f"checks/{attribute} = {stored}, {m[key]} recomputed")

    if "zmp_multibody" in run:
        before = np.hypot(*(cop - run["zmp_multibody"][:]).T)
        m["zmp_error_rms_before"] = float(np.sqrt(np.mean(before ** 2)))
        m["zmp_error_max_before"] = float(np.max(before))
        m["zmp_error_rms_after"] = m["zmp_error_max_after"] = math.nan  # no filter: absent
        if "com_filtered" in run:
            after = np.hypot(*(cop - run["zmp_multibody_filtered"][:]).T)
            m["zmp_error_rms_after"] = float(np.sqrt(np.mean(after ** 2)))
            m["zmp_error_max_after"] = float(np.max(after))
    else:
        for key in ("zmp_error_rms_before", "zmp_error_max_before", "zmp_error_rms_after",
                    "zmp_error_max_after"):
            m[key] = math.nan

    qp = run["mpc/qp_iterations"][:].astype(float)
    status = run["mpc/status"][:]
    solve = run["mpc/solve_time"][:]
    m["nmpc_iterations"] = float(len(qp))
    m["qp_iterations_mean"] = float(qp.mean())
    m["qp_iterations_max"] = float(qp.max())
    m["qp_iterations_total"] = float(qp.sum())
    m["relaxed_iterations"] = float(np.isin(status, [1, 6, 7]).sum())
    m["failed_iterations"] = float(np.isin(status, [2, 3, 4, 5]).sum())
    m["nmpc_time_mean"] = float(solve.mean())
    m["nmpc_time_std"] = float(solve.std(ddof=1)) if len(solve) > 1 else math.nan
    m["nmpc_time_min"] = float(solve.min())
    m["nmpc_time_max"] = float(solve.max())
    m["nmpc_time_p99"] = quantile(solve, 0.99)
    return m


def main():
    with open(sys.argv[2]) as f:
        printed = json.load(f)
    checked = 0
    with h5py.File(sys.argv[1], "r") as f:
        names = sorted(f["runs"])
        if sorted(printed) != names:
            errors.append(f"runs printed {sorted(printed)} != runs in the file {names}")
        for name in names:
            run = f["runs"][name]
            text = run.attrs["scenario"] if "scenario" in run.attrs else f.attrs["scenario"]
            expected = recompute(run, yaml.safe_load(text))
            got = printed.get(name, {})
            if sorted(got) != sorted(expected):
                errors.append(f"{name}: metric names {sorted(set(got) ^ set(expected))}")
            for key, value in expected.items():
                value_got = got.get(key)
                value_got = math.nan if value_got is None else value_got
                if math.isnan(value) and math.isnan(value_got):
                    continue
                if not math.isclose(value, value_got, rel_tol=RTOL, abs_tol=ATOL):
                    errors.append(f"{name}: {key} = {value_got} printed, {value} recomputed")
                checked += 1
    for e in errors:
        print(e, file=sys.stderr)
    print(f"{checked} metric values checked, {len(errors)} disagree")
    return 1 if errors or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
