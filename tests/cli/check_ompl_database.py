"""check_ompl_database.py LOG_DIR: LOG_DIR/benchmark.db (`wpg compare --ompl-log`) holds the logs
of LOG_DIR (read with read_ompl_log.py, the reader of OMPL's documented grammar) in the schema
of OMPL's ompl_benchmark_statistics.py: its five tables and two views, an experiment per log
(and all_experiments first, holding every run again), a plannerConfigs row per planner with its
common properties, a runs row per run with every property of the log under its name (spaces as
'_'), the same numbers (None for "", nan, inf). Exit 0, or 1 with the reason."""
import glob
import math
import os
import sqlite3
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from read_ompl_log import read_log  # noqa: E402


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def main():
    folder = sys.argv[1]
    logs = [read_log(p) for p in sorted(glob.glob(os.path.join(folder, "*.log")))]
    db = sqlite3.connect(os.path.join(folder, "benchmark.db"))
    tables = {r[0] for r in db.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
    views = {r[0] for r in db.execute("SELECT name FROM sqlite_master WHERE type = 'view'")}
    for table in ("experiments", "plannerConfigs", "enums", "runs", "progress"):
        if table not in tables:
            fail("no table %s (tables: %s)" % (table, sorted(tables)))
    if views != {"bestPlannerConfigs", "bestPlannerConfigsPerExperiment"}:
        fail("views %s" % sorted(views))
    names = [r[0] for r in db.execute("SELECT name FROM experiments ORDER BY id")]
    if names != ["all_experiments"] + [e["name"] for e in logs]:
        fail("experiments %s, logs %s" % (names, [e["name"] for e in logs]))
    statuses = [r[0] for r in db.execute("SELECT description FROM enums WHERE name = 'status' ORDER BY value")]
    if statuses != logs[0]["enums"]["status"]:
        fail("status enum %s" % statuses)
    total = 0
    for e in logs:
        (eid, runcount, seed, version) = db.execute(
            "SELECT id, runcount, seed, version FROM experiments WHERE name = ?", (e["name"],)).fetchone()
        if (runcount, seed, version) != (e["runs_per_planner"], e["seed"], "%s %s" % (e["library"], e["version"])):
            fail("experiment %s: %s" % (e["name"], (runcount, seed, version)))
        for planner in e["planners"]:
            settings = "".join("%s = %s\n;" % kv for kv in planner["common"].items())
            pid = db.execute("SELECT id FROM plannerConfigs WHERE name = ? AND settings = ?",
                             (planner["name"], settings)).fetchone()
            if not pid:
                fail("no plannerConfigs row for %s with its settings" % planner["name"])
            columns = [name.replace(" ", "_") for name, _ in planner["properties"]]
            rows = db.execute("SELECT %s FROM runs WHERE experimentid = ? AND plannerid = ? ORDER BY id"
                              % ",".join('"%s"' % c for c in columns), (eid, pid[0])).fetchall()
            if len(rows) != len(planner["runs"]):
                fail("%s/%s: %d runs, the log has %d" % (e["name"], planner["name"], len(rows), len(planner["runs"])))
            for row, run in zip(rows, planner["runs"]):
                for column, (name, _), value in zip(columns, planner["properties"], row):
                    want = run[name]
                    if want is None or (isinstance(want, float) and not math.isfinite(want)):
                        ok = value is None
                    else:
                        ok = value is not None and abs(float(value) - float(want)) <= 1e-12 * max(1.0, abs(float(want)))
                    if not ok:
                        fail("%s/%s: %s = %r, the log's %r" % (e["name"], planner["name"], column, value, want))
            total += len(rows)
    everything = db.execute("SELECT count(*) FROM runs WHERE experimentid = 1").fetchone()[0]
    if everything != total:
        fail("all_experiments holds %d runs, the logs %d" % (everything, total))
    print("benchmark.db: %d experiments, %d runs as in the logs, all_experiments and the views" % (len(logs), total))


if __name__ == "__main__":
    main()
