"""check_run_file.py RUN.h5 [--duration SECONDS]: the file follows datasets/SCHEMA.md.

Every group under /runs/ has the per-sample datasets (n rows), the footsteps (m rows) and
the per-iteration mpc/ datasets, all finite; the root has the schema attributes.
"""
import argparse
import sys

import h5py
import numpy as np

SAMPLES = {"time": (), "com": (3,), "com_vel": (3,), "com_acc": (3,), "cop": (2,),
           "left_foot": (4,), "right_foot": (4,), "free_flyer_yaw": (), "support": ()}
STEPS = {"footsteps": (4,), "footstep_side": ()}
MPC = ("time", "solve_time", "qp_iterations", "sqp_iterations", "status", "cost",
       "relaxed_families")
# the NMPC's constraint families, one slack column each (libwpg/include/wpg/nmpc.hpp), then
# those of the scenario's `constraints:` section (docs/extending.md)
FAMILIES = "cop, step_feasibility, yaw_bound, obstacle, landing_bound, landing_yaw_bound, swing_reach"
ROOT_ATTRS = ("schema_version", "wpg_version", "scenario")

errors = []


def check(condition, message):
    if not condition:
        errors.append(message)
    return condition


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("run_file")
    parser.add_argument("--duration", type=float)
    args = parser.parse_args()
    with h5py.File(args.run_file, "r") as f:
        for attr in ROOT_ATTRS:
            check(attr in f.attrs, "root attribute %s missing" % attr)
        runs = f.get("runs")
        if not check(isinstance(runs, h5py.Group) and len(runs) > 0, "no group under /runs/"):
            return
        for name, run in runs.items():
            where = "/runs/%s" % name
            n = run["time"].shape[0] if "time" in run else None
            check(n is not None and n > 1, where + "/time missing or too short")
            for key, tail in SAMPLES.items():
                if check(key in run, "%s/%s missing" % (where, key)):
                    data = run[key][()]
                    check(data.shape == (n,) + tail, "%s/%s shape %s, expected %s"
                          % (where, key, data.shape, (n,) + tail))
                    check(np.all(np.isfinite(data)), "%s/%s not finite" % (where, key))
            m = run["footsteps"].shape[0] if "footsteps" in run else None
            check(m is not None and m >= 2, where + "/footsteps missing or without the two initial feet")
            for key, tail in STEPS.items():
                if check(key in run, "%s/%s missing" % (where, key)):
                    data = run[key][()]
                    check(data.shape == (m,) + tail, "%s/%s shape %s, expected %s"
                          % (where, key, data.shape, (m,) + tail))
                    check(np.all(np.isfinite(data)), "%s/%s not finite" % (where, key))
            if n:
                time = run["time"][()]
                check(np.all(np.diff(time) > 0), where + "/time not increasing")
                check(set(np.unique(run["support"][()])) <= {0, 1, 2}, where + "/support not in {0,1,2}")
                if args.duration is not None:
                    check(abs(time[-1] - time[0] - args.duration) <= 0.11,
                          "%s/time spans %.3f s, expected %.3f s" % (where, time[-1] - time[0], args.duration))
            if m:
                check(set(np.unique(run["footstep_side"][()])) <= {1, 2}, where + "/footstep_side not in {1,2}")
            mpc = run.get("mpc")
            if check(isinstance(mpc, h5py.Group), where + "/mpc missing"):
                k = mpc["time"].shape[0] if "time" in mpc else None
                check(k is not None and k > 0, where + "/mpc/time missing or empty")
                for key in MPC:
                    if check(key in mpc, "%s/mpc/%s missing" % (where, key)):
                        check(mpc[key].shape == (k,), "%s/mpc/%s shape %s, expected %s"
                              % (where, key, mpc[key].shape, (k,)))
                slack = mpc.get("slack")
                if check(slack is not None, where + "/mpc/slack missing"):
                    columns = slack.attrs.get("columns") or ""
                    added = columns[len(FAMILIES):].split(", ")[1:]
                    check(columns.startswith(FAMILIES) and all(added),
                          "%s/mpc/slack columns %r, expected %r (then the scenario's)"
                          % (where, columns, FAMILIES))
                    width = 7 + len(added)
                    check(slack.shape == (k, width), "%s/mpc/slack shape %s, expected %s"
                          % (where, slack.shape, (k, width)))
                    check(np.all(slack[()] >= 0), where + "/mpc/slack negative")
                    relaxed = mpc["relaxed_families"][()]
                    # a family's bit is set exactly when its slack is positive (above rounding)
                    check(np.array_equal((slack[()] > 1e-9).any(axis=1), relaxed != 0),
                          where + "/mpc/relaxed_families disagrees with slack")
                velocity = mpc.get("commanded_velocity")
                if check(velocity is not None, where + "/mpc/commanded_velocity missing"):
                    check(velocity.shape == (k, 2), "%s/mpc/commanded_velocity shape %s, expected %s"
                          % (where, velocity.shape, (k, 2)))
                    check(np.all(np.isfinite(velocity[()])), where + "/mpc/commanded_velocity not finite")
            # Stuck is an outcome: blocked 0 or 1, where and since when only when 1.
            blocked = run.attrs.get("blocked")
            if check(blocked in (0, 1), "%s:blocked is %r, expected 0 or 1" % (where, blocked)):
                for key in ("blocked_since", "blocked_x", "blocked_y"):
                    present = key in run.attrs
                    check(present == (blocked == 1), "%s:%s %s with blocked %d"
                          % (where, key, "present" if present else "missing", blocked))
                    if present:
                        check(np.isfinite(run.attrs[key]), "%s:%s not finite" % (where, key))
                if blocked == 1:
                    check(int(run.attrs["success"]) == 0, where + ": blocked but success 1")
            if "progress_ratio" in run.attrs:
                check(np.isfinite(run.attrs["progress_ratio"]), where + ":progress_ratio not finite")


if __name__ == "__main__":
    try:
        main()
    except (OSError, KeyError) as error:
        errors.append(str(error))
    for error in errors:
        print("check_run_file: %s" % error, file=sys.stderr)
    sys.exit(1 if errors else 0)
