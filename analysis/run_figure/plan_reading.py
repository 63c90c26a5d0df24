"""The plan of each NMPC iteration (mpc/plan/, datasets/SCHEMA.md) of one run, checked as the C++
reader checks it: sizes from the attributes, bounded (samples <= 200, steps <= 10, the walking
parameters' limits) before any dataset is read, every dataset exactly its iterations' rows."""
import numpy as np

from wpg_file_reading import BadFile, Reader, open_file

MAX_PLAN_SAMPLES = 200
MAX_PLAN_STEPS = 10


def read_plan(path, run_name):
    """{"time" (k,), "samples" N, "steps" nf, "period" T, "count" (k,), "com" (k, N, 2),
    "cop" (k, N, 2), "steps_pose" (k, nf, 4: landing time, x, y, yaw), "side" (k, nf)}."""
    with open_file(path) as handle:
        reader = Reader(path, handle)
        runs = reader.group(handle, "runs")
        group = reader.group(runs, run_name)
        mpc = reader.group(group, "mpc")
        plan = reader.group(mpc, "plan", optional=True)
        if plan is None:
            raise BadFile("%s: %s/plan: expected the NMPC's plans, missing (the run was made with "
                          "generator.record_plan: false, a study's plan: false, or before "
                          "plans were stored)" % (path, mpc.name))
        time = reader.dataset(mpc, "time")
        k = len(time)

        def bounded(name, high):
            value = reader.attribute(plan, name)
            if not (1 <= value <= high and value == int(value)):
                reader.fail(plan.name + ":" + name, "expected an integer in [1, %d]" % high)
            return int(value)

        n = bounded("samples", MAX_PLAN_SAMPLES)
        nf = bounded("steps", MAX_PLAN_STEPS)
        period = reader.attribute(plan, "sampling_period")
        if not (np.isfinite(period) and period > 0):
            reader.fail(plan.name + ":sampling_period", "expected a positive number of seconds")
        count = reader.dataset(plan, "sample_count", kind="integer", rows=k)
        if np.any((count < 0) | (count > n)):
            reader.fail(plan.name + "/sample_count", "expected counts in [0, %d]" % n)
        result = {"time": time, "samples": n, "steps": nf, "period": period, "count": count}
        for key in ("com", "cop"):
            result[key] = reader.dataset(plan, key, columns=2, rows=k * n,
                                         max_rows=k * n).reshape(k, n, 2)
        result["steps_pose"] = reader.dataset(plan, "steps", columns=4, rows=k * nf,
                                              max_rows=k * nf).reshape(k, nf, 4)
        side = reader.dataset(plan, "step_side", kind="integer", rows=k * nf, max_rows=k * nf)
        if np.any((side < 0) | (side > 2)):
            reader.fail(plan.name + "/step_side", "expected codes 0, 1 or 2")
        result["side"] = side.reshape(k, nf)
        return result


def prediction_errors(plan, time, com):
    """For each look-ahead j = 1..N: the distances |predicted CoM - executed CoM| at
    t_k + j T over the iterations k whose sample j lies within the walk (a list of arrays).
    Look-ahead 1 is the CoM executed at the next iteration: 0 up to rounding without a push."""
    errors = []
    for j in range(1, plan["samples"] + 1):
        target = plan["time"] + j * plan["period"]
        index = np.searchsorted(time, target - 1e-9)
        keep = (index < len(time)) & (plan["count"] >= j)
        keep[keep] &= np.abs(time[index[keep]] - target[keep]) < 1e-6
        predicted = plan["com"][keep, j - 1]
        errors.append(np.hypot(*(predicted - com[index[keep], :2]).T))
    return errors
