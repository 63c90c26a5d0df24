"""check_ompl_log.py DIR STUDY.h5: the OMPL benchmark logs of `wpg compare --ompl-log DIR`
parse with read_ompl_log.py (OMPL's documented grammar), one per world of the study file's
/compare attributes, one planner per variant, every run of the study present once (its seed),
and the values agree with /batch/summary (reached, steps, time to goal, least clearance,
replans) and with each run's first plan (time, solution length, status). The provenance is in
every file: version line, host, date, the wpg commit in the setup text.
"""
import math
import os
import sys

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from read_ompl_log import LogError, read_log  # noqa: E402

EXACT_SOLUTION = 6  # ompl::base::PlannerStatus::EXACT_SOLUTION


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def same(a, b):
    if a is None or b is None or (isinstance(b, float) and not math.isfinite(b)):
        return (a is None) == (b is None or not math.isfinite(b))
    return math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-15)


def text(values):
    return [v.decode() if isinstance(v, bytes) else str(v) for v in values]


def main():
    folder, study = sys.argv[1], sys.argv[2]
    with h5py.File(study, "r") as f:
        worlds = text(f["compare"].attrs["worlds"])
        variants = text(f["compare"].attrs["variants"])
        s = f["batch/summary"]
        table = {name: s[name][()] for name in text(s.attrs["columns"])}
        for key in ("name", "sweep.world", "sweep.variant"):
            table[key] = text(table[key])
        first_plans = {}
        for name in table["name"]:
            plans = f["runs"][name]["plans"]
            first_plans[name] = {k: plans[k][0] for k in ("planning_time", "solution_length", "status")}
            first_plans[name]["algorithm"] = plans.attrs["algorithm"]
        commit = f.attrs["wpg_commit"]
    files = sorted(os.listdir(folder))
    if files != sorted([w + ".log" for w in worlds] + ["benchmark.db"]):
        fail("%s holds %s, expected one log per world %s and benchmark.db" % (folder, files, worlds))
    checked = 0
    for world in worlds:
        try:
            log = read_log(os.path.join(folder, world + ".log"))
        except (LogError, OSError) as error:
            fail(str(error))
        if log["name"] != world or log["library"] != "wpg" or not log["host"] or not log["date"]:
            fail("%s.log: experiment %s, library %s, host %s, date %s"
                 % (world, log["name"], log.get("library"), log["host"], log["date"]))
        if "commit " + commit not in log["setup"]:
            fail("%s.log: the setup text does not name the commit %s" % (world, commit))
        if log["enums"].get("status", [None] * 7)[EXACT_SOLUTION] != "Exact solution":
            fail("%s.log: the status enum is %s" % (world, log["enums"].get("status")))
        if [p["name"] for p in log["planners"]] != variants:
            fail("%s.log: planners %s, expected the variants %s"
                 % (world, [p["name"] for p in log["planners"]], variants))
        for planner in log["planners"]:
            rows = [i for i, (w, v) in enumerate(zip(table["sweep.world"], table["sweep.variant"]))
                    if w == world and v == planner["name"]]
            seeds = sorted(int(table["sweep.seed"][i]) for i in rows)
            if sorted(int(r["seed"]) for r in planner["runs"]) != seeds:
                fail("%s.log %s: runs of seeds %s, expected %s" % (
                    world, planner["name"], [r["seed"] for r in planner["runs"]], seeds))
            for run in planner["runs"]:
                i = next(i for i in rows if int(table["sweep.seed"][i]) == int(run["seed"]))
                name = table["name"][i]
                plan = first_plans[name]
                expected = {
                    "reached": float(table["goal_reached"][i]), "steps": float(table["steps"][i]),
                    "time to goal": float(table["time_to_goal"][i]),
                    "least clearance": float(table["step_centre_clearance_min"][i]),
                    "replans": float(table["replans"][i]),
                    "walked length": float(table["path_length"][i]),
                    "time": float(plan["planning_time"]),
                    "solved": 1.0 if plan["status"] == 0 else 0.0,
                }
                if plan["algorithm"] != "none":
                    expected["solution length"] = float(plan["solution_length"])
                for key, value in expected.items():
                    if not same(run[key], value):
                        fail("%s.log %s seed %d (%s): %s = %s, expected %s"
                             % (world, planner["name"], run["seed"], name, key, run[key], value))
                checked += 1
    if checked != len(table["name"]):
        fail("%d runs in the logs, %d in the study" % (checked, len(table["name"])))
    print("%d logs, %d runs, every run of %s present with its values" % (len(worlds), checked, study))
    return 0


if __name__ == "__main__":
    sys.exit(main())
