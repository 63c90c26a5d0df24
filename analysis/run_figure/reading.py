"""The run groups of a run or batch file, every dataset and attribute checked
(wpg_file_reading: shapes, types, finite numbers, sizes bounded before reading)."""
import math

import numpy as np

from wpg_file_reading import BadFile, Reader, open_file, parse_scenario

from .styles import STATUS_STYLE

SCHEMA_DATASETS = ("time", "com", "cop", "support", "footsteps", "footstep_side")
# The multibody replay (optional): datasets of the run group, and the attributes of multibody/.
MULTIBODY_DATASETS = ("zmp_multibody", "zmp_multibody_filtered", "com_filtered")
MULTIBODY_ATTRIBUTES = ("zmp_error_rms_before", "zmp_error_max_before", "zmp_error_rms_after",
                        "zmp_error_max_after", "ik_failures", "filtered",
                        # filter_settings.mode both: the offline pass beside the online loop
                        "offline_zmp_error_rms_before", "offline_zmp_error_max_before",
                        "offline_zmp_error_rms_after", "offline_zmp_error_max_after",
                        "wpg_reinitialized")
# One figure row per run, 6.8 in high: matplotlib refuses figures over 2^16 pixels (~87 rows).
MAX_RUNS_IN_FIGURE = 50


def read_runs(path, only=None):
    with open_file(path) as handle:
        reader = Reader(path, handle)
        root_scenario = reader.attribute(handle, "scenario", kind="text", optional=True)
        runs_group = reader.group(handle, "runs")
        names = sorted(runs_group.keys())
        if not names:
            raise BadFile("%s: /runs: expected at least one run group, got none" % path)
        if only is not None:
            if only not in names:
                raise BadFile("%s: /runs/%s: expected a run group (runs: %s)"
                              % (path, only, ", ".join(names[:10])))
            names = [only]
        if len(names) > MAX_RUNS_IN_FIGURE:
            raise BadFile("%s: /runs: expected at most %d runs in one figure, got %d (draw one "
                          "with --run NAME, e.g. --run %s)" % (path, MAX_RUNS_IN_FIGURE, len(names),
                                                               names[0]))
        runs = []
        for name in names:
            group = reader.group(runs_group, name, optional=True)
            if group is None:
                continue
            runs.append(read_run(reader, group, name, root_scenario))
        if not runs:
            raise BadFile("%s: /runs: expected at least one run group, got none" % path)
        return runs


def read_run(reader, group, name, root_scenario):
    run = {"name": name}
    time = reader.dataset(group, "time")
    n = len(time)
    if n and not np.all(np.diff(time) > 0):
        row = int(np.argmax(~(np.diff(time) > 0))) + 1
        reader.fail(group.name + "/time", "row %d: expected strictly increasing times" % row)
    run["time"] = time
    run["com"] = reader.dataset(group, "com", columns=3, rows=n)
    run["cop"] = reader.dataset(group, "cop", columns=2, rows=n)
    run["support"] = reader.dataset(group, "support", kind="integer", rows=n)
    if np.any((run["support"] < 0) | (run["support"] > 2)):
        reader.fail(group.name + "/support", "expected codes 0, 1 or 2")
    run["footsteps"] = reader.dataset(group, "footsteps", columns=4)
    run["footstep_side"] = reader.dataset(group, "footstep_side", kind="integer",
                                          rows=len(run["footsteps"]))
    run["mpc"] = None
    mpc = reader.group(group, "mpc", optional=True)
    if mpc is not None and reader.has(mpc, "time") and reader.has(mpc, "solve_time"):
        k = None
        run["mpc"] = {}
        for key in ("time", "solve_time", "status"):
            values = reader.dataset(mpc, key, kind="integer" if key == "status" else "number",
                                    rows=k, optional=key == "status")
            if values is None:
                continue
            k = len(values)
            run["mpc"][key] = values
        status = run["mpc"].get("status")
        if status is not None and not np.all(np.isin(status, list(STATUS_STYLE))):
            reader.fail(mpc.name + "/status", "expected codes %s" % ", ".join(
                str(code) for code in STATUS_STYLE))
    run["multibody"] = None
    if reader.has(group, "zmp_multibody"):
        multibody = {}
        for key in MULTIBODY_DATASETS:
            values = reader.dataset(group, key, columns=3 if key == "com_filtered" else 2,
                                    rows=n, optional=key != "zmp_multibody")
            if values is not None:
                multibody[key] = values
        attributes = reader.group(group, "multibody", optional=True)
        if attributes is not None:
            for key in MULTIBODY_ATTRIBUTES:
                value = reader.attribute(attributes, key, optional=True)
                if value is not None:
                    multibody[key] = value
            # "online" (the loop of Fig. 3) or "offline"; absent in older files (offline)
            multibody["filter_mode"] = reader.attribute(
                attributes, "filter_mode", kind="text", optional=True) or "offline"
        else:
            multibody["filter_mode"] = "offline"
        run["multibody"] = multibody
    run["goal"] = read_goal(reader, group)
    # a batch stores each run's own scenario text on its group
    text = reader.attribute(group, "scenario", kind="text", optional=True) or root_scenario
    where = (group.name + ":scenario") if text is not root_scenario else "/:scenario"
    run["scenario"] = parse_scenario(reader.path, where, text)
    return run


def read_goal(reader, group):
    """The goal and the routes of a walk to a goal (SCHEMA.md: plans), or None."""
    if reader.attribute(group, "goal_x", optional=True) is None:
        return None
    goal = {}
    for key in ("goal_x", "goal_y", "goal_yaw", "goal_tolerance", "time_to_goal"):
        value = reader.attribute(group, key, optional=True)
        if value is not None:
            goal[key] = value
    for key in ("goal_x", "goal_y"):
        if not math.isfinite(goal.get(key, math.nan)):
            reader.fail(group.name + ":" + key, "expected a finite number")
    goal["goal_tolerance"] = goal.get("goal_tolerance", 0.0)
    if not (math.isfinite(goal["goal_tolerance"]) and goal["goal_tolerance"] >= 0):
        reader.fail(group.name + ":goal_tolerance", "expected a finite number >= 0")
    goal["reached"] = reader.attribute(group, "goal_reached", optional=True, default=0) == 1
    goal["routes"] = []
    plans = reader.group(group, "plans", optional=True)
    if plans is not None and reader.has(plans, "routes"):
        routes = reader.dataset(plans, "routes", columns=3)
        starts = reader.dataset(plans, "route_start", kind="integer")
        p = len(starts)
        counts = reader.dataset(plans, "route_count", kind="integer", rows=p)
        times = reader.dataset(plans, "time", rows=p)
        triggers = reader.dataset(plans, "trigger", kind="integer", rows=p)
        if np.any(starts < 0) or np.any(counts < 0) or np.any(starts + counts > len(routes)):
            reader.fail(plans.name + "/route_start",
                        "expected rows of routes (%d rows) with route_count" % len(routes))
        codes_text = reader.attribute(plans["trigger"], "codes", kind="text", optional=True,
                                      default="")
        codes = dict(item.split("=", 1) for item in codes_text.split(", ") if "=" in item)
        for start, count, time, trigger in zip(starts, counts, times, triggers):
            goal["routes"].append((routes[int(start):int(start) + int(count), :2], float(time),
                                   codes.get(str(int(trigger)), str(int(trigger)))))
    return goal
