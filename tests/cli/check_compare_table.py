"""check_compare_table.py STUDY.h5 SUMMARY.csv: the table of a `wpg compare` study agrees with
its runs, recomputed with h5py + numpy from the run groups (not from the table's code):
- /compare/summary has one row per world x variant, in study order, and summary.csv the same
  rows and numbers (10 significant digits);
- success rate = goal_reached attributes / runs; time to goal median, q1, q3 (numpy's linear
  percentile) over the reached runs; clearance_min = least checks/step_centre_clearance;
  runs with a step centre inside a margin (< -1e-9 m); runs that ended blocked (their
  `blocked` attribute);
- every run's planner seed is its study seed; the obstacles of the world named `field` (a
  random field in tests/cli/studies/compare_small.yaml) differ between seeds, those of every
  other world do not.
Exit 0 agree, 1 not (each difference on stderr).
"""
import csv
import math
import sys

import h5py
import numpy as np

errors = []


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def close(a, b, tolerance=1e-12):
    if math.isnan(a) and math.isnan(b):
        return True
    return abs(a - b) <= tolerance * max(1.0, abs(a), abs(b))


def main():
    study_path, csv_path = sys.argv[1], sys.argv[2]
    with h5py.File(study_path, "r") as f:
        worlds = [text(w) for w in f["compare"].attrs["worlds"]]
        variants = [text(v) for v in f["compare"].attrs["variants"]]
        table = f["compare/summary"]
        rows = list(zip([text(w) for w in table["world"][:]], [text(v) for v in table["variant"][:]]))
        if rows != [(w, v) for w in worlds for v in variants]:
            errors.append("rows %s are not worlds x variants in order" % rows)
        summary = f["batch/summary"]
        names = [text(n) for n in summary["name"][:]]
        run_world = [text(w) for w in summary["sweep.world"][:]]
        run_variant = [text(v) for v in summary["sweep.variant"][:]]
        run_seed = summary["sweep.seed"][:]
        obstacles_by_world = {}
        for r, (world, variant) in enumerate(rows):
            members = [n for n, w, v in zip(names, run_world, run_variant) if w == world and v == variant]
            reached, blocked, times, clearances = 0, 0, [], []
            for name in members:
                run = f["runs"][name]
                blocked += int(run.attrs["blocked"])
                seed = int(run_seed[names.index(name)])
                if int(run["plans"].attrs["seed"]) != seed:
                    errors.append("%s: planner seed %d, study seed %d" % (name, run["plans"].attrs["seed"], seed))
                if int(run.attrs["goal_reached"]) == 1:
                    reached += 1
                    times.append(float(run.attrs["time_to_goal"]))
                clearances.extend(run["checks"]["step_centre_clearance"][()].tolist())
                obstacles_by_world.setdefault(world, {})[seed] = run["obstacles"]["center"][()].tobytes()
            expected = {
                "runs": len(members),
                "reached": reached,
                "success_rate": reached / len(members),
                "blocked": blocked,
                "time_to_goal_median": float(np.percentile(times, 50)) if times else math.nan,
                "time_to_goal_q1": float(np.percentile(times, 25)) if times else math.nan,
                "time_to_goal_q3": float(np.percentile(times, 75)) if times else math.nan,
                "clearance_min": min(clearances) if clearances else math.nan,
            }
            entered = 0
            for name in members:
                c = f["runs"][name]["checks"]["step_centre_clearance"][()]
                entered += int(c.size > 0 and c.min() < -1e-9)
            expected["margin_entered"] = entered
            for column, value in expected.items():
                got = float(table[column][r])
                if not close(got, float(value)):
                    errors.append("%s/%s %s: table %r, runs %r" % (world, variant, column, got, value))
        for world, by_seed in obstacles_by_world.items():
            distinct = len(set(by_seed.values()))
            generator = "random" if world == "field" else "fixed"
            if generator == "random" and len(by_seed) > 1 and distinct != len(by_seed):
                errors.append("%s: the random field is the same for different seeds" % world)
            if generator == "fixed" and distinct != 1:
                errors.append("%s: a fixed world differs between seeds" % world)
        columns = [text(c) for c in table.attrs["columns"]]
        with open(csv_path, newline="") as handle:
            lines = list(csv.reader(handle))
        if lines[0] != columns:
            errors.append("summary.csv header %s, table columns %s" % (lines[0], columns))
        for r, line in enumerate(lines[1:]):
            for column, cell in zip(columns, line):
                value = table[column][r]
                if isinstance(value, (bytes, str)):
                    if text(value) != cell:
                        errors.append("summary.csv %s row %d: %s vs %s" % (column, r, cell, text(value)))
                elif not close(float(cell), float(value), 1e-9):
                    errors.append("summary.csv %s row %d: %s vs %r" % (column, r, cell, value))
    for error in errors[:20]:
        print("check_compare_table: %s" % error, file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
