"""check_goal_run.py RUN.h5 [--not-reached] [--min-replans N] [--trigger NAME]: a walk to a goal
as datasets/SCHEMA.md describes it ("Walks to a goal").

Reached (default): goal_reached 1, time_to_goal finite, the standing pose within the goal's
tolerance (and yaw tolerance), every landed step centre outside every margin grown by the sole
radius (checks/step_centre_clearance >= 0), every route starting with an exact solution.
--not-reached: goal_reached 0, time_to_goal NaN, success 0 and a message that says why.
"""
import argparse
import math
import sys

import h5py
import numpy as np


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("path")
    parser.add_argument("--not-reached", action="store_true")
    parser.add_argument("--min-replans", type=int, default=0)
    parser.add_argument("--trigger", default=None, help="a replan with this trigger is present")
    args = parser.parse_args()
    errors = []
    with h5py.File(args.path, "r") as f:
        (name,) = list(f["runs"].keys())
        run = f["runs"][name]
        a = run.attrs
        for key in ("goal_x", "goal_y", "goal_yaw", "goal_tolerance", "goal_yaw_tolerance",
                    "goal_reached", "time_to_goal", "goal_final_distance",
                    "goal_final_yaw_error", "goal_outcome"):
            if key not in a:
                errors.append("run attribute %s missing" % key)
        plans = run["plans"]
        count = int(plans.attrs["count"])
        for key in ("time", "status", "trigger", "start", "planning_time", "route_length",
                    "solution_length", "solution_clearance", "simplification_time",
                    "graph_states", "routes", "route_start", "route_count"):
            if key not in plans:
                errors.append("plans/%s missing" % key)
            elif plans[key].shape[0] != count and key != "routes":
                errors.append("plans/%s has %d rows, expected %d" % (key, plans[key].shape[0], count))
        if "known_to_planner" not in run["obstacles"]:
            errors.append("obstacles/known_to_planner missing")
        if count < 1 + args.min_replans:
            errors.append("%d plans, expected at least %d" % (count, 1 + args.min_replans))
        codes = dict(item.split("=") for item in plans["trigger"].attrs["codes"].split(", "))
        if args.trigger and args.trigger not in [codes[str(int(t))] for t in plans["trigger"][()]]:
            errors.append("no plan triggered by '%s'" % args.trigger)
        if int(plans["route_count"][0]) < 2:
            errors.append("the first plan has no route")
        if args.not_reached:
            if int(a["goal_reached"]) != 0 or not math.isnan(float(a["time_to_goal"])):
                errors.append("goal_reached %s, time_to_goal %s: expected 0, NaN"
                              % (a["goal_reached"], a["time_to_goal"]))
            if int(a["success"]) != 0 or "goal not reached" not in str(a["message"]):
                errors.append("success %s, message '%s'" % (a["success"], a["message"]))
        else:
            if int(a["goal_reached"]) != 1 or not math.isfinite(float(a["time_to_goal"])):
                errors.append("goal not reached: %s" % a["goal_outcome"])
            if float(a["goal_final_distance"]) > float(a["goal_tolerance"]):
                errors.append("standing %.3f m from the goal, tolerance %.3f"
                              % (a["goal_final_distance"], a["goal_tolerance"]))
            if not math.isnan(float(a["goal_yaw"])) and \
                    float(a["goal_final_yaw_error"]) > float(a["goal_yaw_tolerance"]):
                errors.append("yaw error %.3f rad, tolerance %.3f"
                              % (a["goal_final_yaw_error"], a["goal_yaw_tolerance"]))
            # the closing sample of the run is the standing pose at time_to_goal
            if abs(float(run["time"][-1]) - float(a["time_to_goal"])) > 1e-9:
                errors.append("the run goes on after the goal was reached")
            centre = np.asarray(run["checks"]["step_centre_clearance"][()])
            if centre.size and centre.min() < -1e-9:
                errors.append("a step centre is %.4f m inside a margin" % -centre.min())
    for error in errors:
        print("check_goal_run: %s: %s" % (args.path, error), file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
