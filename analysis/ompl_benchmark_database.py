"""ompl_benchmark_database.py LOG... -o BENCHMARK.db: OMPL benchmark logs (as `wpg compare
--ompl-log DIR` writes them, the grammar of OMPL's "The benchmark logfile format") into the
SQLite database Planner Arena opens, in the schema OMPL's ompl_benchmark_statistics.py gives
it (which Debian does not ship):

- experiments (id, name, totaltime, timelimit, memorylimit, runcount, version, hostname,
  cpuinfo, date, seed, setup), plus a column per experiment property; a first row
  `all_experiments` holds every run too, as the script adds it;
- plannerConfigs (id, name, settings: the common properties, each line followed by ';');
- enums (name, value, description): the `status` enum;
- runs (id, experimentid, plannerid, then a column per run property, its name's spaces as '_',
  its type the log's: REAL, INTEGER, BOOLEAN, ENUM); "", nan and inf are NULL;
- progress (runid, time): empty (wpg logs no planner progress);
- the views bestPlannerConfigsPerExperiment and bestPlannerConfigs (mean solved first, then
  mean time + simplification_time).

Python's standard library only. The database is written beside its target and renamed over it.
Exit 0, or 2 with one line on stderr for a log that does not follow the grammar.
"""
import argparse
import os
import sqlite3
import sys
import tempfile

INVALID = ("", "nan", "-nan", "inf", "-inf")


class LogError(Exception):
    pass


class Lines:
    def __init__(self, path):
        self.path = path
        with open(path, encoding="utf-8") as handle:
            self.lines = handle.read().split("\n")
        self.at = 0

    def next(self):
        if self.at >= len(self.lines):
            raise LogError("%s: ended early (line %d)" % (self.path, self.at + 1))
        self.at += 1
        return self.lines[self.at - 1]

    def count(self, suffix):
        line = self.next()
        words = line.split(" ", 1)
        if len(words) != 2 or words[1] != suffix or not words[0].isdigit():
            raise LogError("%s line %d: expected '<count> %s', got %r" % (self.path, self.at, suffix, line))
        return int(words[0])

    def after(self, prefix):
        line = self.next()
        if not line.startswith(prefix):
            raise LogError("%s line %d: expected '%s...', got %r" % (self.path, self.at, prefix, line))
        return line[len(prefix):]

    def number(self, suffix):
        line = self.next()
        if not line.endswith(" " + suffix):
            raise LogError("%s line %d: expected '<number> %s', got %r" % (self.path, self.at, suffix, line))
        return float(line[:-len(suffix) - 1])

    def multiline(self):
        self.after("<<<|")
        text = ""
        while True:
            line = self.next()
            if line.startswith("|>>>"):
                return text
            text += line + "\n"


def column(name_and_type):
    """'approximate solution REAL' -> ('approximate_solution', 'REAL')."""
    words = name_and_type.split()
    if len(words) < 2:
        raise LogError("a property without a type: %r" % name_and_type)
    return "_".join(words[:-1]), words[-1]


def read_log(path):
    lines = Lines(path)
    library, _, version = lines.next().partition(" version ")
    experiment = {"version": "%s %s" % (library, version), "name": lines.after("Experiment ")}
    experiment["properties"] = []
    for _ in range(lines.count("experiment properties")):
        name_and_type, _, value = lines.next().partition(" = ")
        experiment["properties"].append(column(name_and_type) + (value,))
    experiment["hostname"] = lines.after("Running on ")
    experiment["date"] = lines.after("Starting at ")
    experiment["setup"] = lines.multiline()
    experiment["cpuinfo"] = lines.multiline()
    experiment["seed"] = int(lines.number("is the random seed"))
    experiment["timelimit"] = lines.number("seconds per run")
    experiment["memorylimit"] = lines.number("MB per run")
    experiment["runcount"] = int(lines.number("runs per planner"))
    experiment["totaltime"] = lines.number("seconds spent to collect the data")
    experiment["enums"] = [lines.next().split("|") for _ in range(lines.count("enum type"))]
    planners = []
    for _ in range(lines.count("planners")):
        planner = {"name": lines.next()}
        planner["settings"] = "".join(lines.next() + "\n;" for _ in range(lines.count("common properties")))
        planner["properties"] = [column(lines.next()) for _ in range(lines.count("properties for each run"))]
        planner["runs"] = []
        for _ in range(lines.count("runs")):
            values = lines.next().split("; ")[:-1]
            if len(values) != len(planner["properties"]):
                raise LogError("%s line %d: %d values for %d properties"
                               % (path, lines.at, len(values), len(planner["properties"])))
            planner["runs"].append([None if v in INVALID else v for v in values])
        lines.after(".")
        planners.append(planner)
    experiment["planners"] = planners
    return experiment


SCHEMA = """
CREATE TABLE experiments
  (id INTEGER PRIMARY KEY ON CONFLICT REPLACE AUTOINCREMENT, name VARCHAR(512),
   totaltime REAL, timelimit REAL, memorylimit REAL, runcount INTEGER,
   version VARCHAR(128), hostname VARCHAR(1024), cpuinfo TEXT,
   date DATETIME, seed INTEGER, setup TEXT);
CREATE TABLE plannerConfigs
  (id INTEGER PRIMARY KEY AUTOINCREMENT, name VARCHAR(512) NOT NULL, settings TEXT);
CREATE TABLE enums
  (name VARCHAR(512), value INTEGER, description TEXT, PRIMARY KEY (name, value));
CREATE TABLE runs
  (id INTEGER PRIMARY KEY AUTOINCREMENT, experimentid INTEGER, plannerid INTEGER,
   FOREIGN KEY (experimentid) REFERENCES experiments(id) ON DELETE CASCADE,
   FOREIGN KEY (plannerid) REFERENCES plannerConfigs(id) ON DELETE CASCADE);
CREATE TABLE progress
  (runid INTEGER, time REAL, PRIMARY KEY (runid, time),
   FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE);
"""

FIELDS = ("name", "totaltime", "timelimit", "memorylimit", "runcount", "version", "hostname",
          "cpuinfo", "date", "seed", "setup")


def add_columns(db, table, columns):
    have = {row[1] for row in db.execute('PRAGMA table_info("%s")' % table)}
    for name, kind in columns:
        if name not in have:
            db.execute('ALTER TABLE "%s" ADD "%s" %s' % (table, name, kind))
            have.add(name)


def write_database(experiments, db):
    db.execute("PRAGMA foreign_keys = ON")
    db.executescript(SCHEMA)
    # Every run also under all_experiments (the first row), as ompl_benchmark_statistics.py does.
    first = experiments[0] if experiments else {}
    total = {"name": "all_experiments", "totaltime": sum(e["totaltime"] for e in experiments),
             "timelimit": max((e["timelimit"] for e in experiments), default=0.0),
             "memorylimit": max((e["memorylimit"] for e in experiments), default=0.0),
             "runcount": sum(e["runcount"] for e in experiments)}
    for key in ("version", "hostname", "cpuinfo", "date", "seed", "setup"):
        total[key] = first.get(key, "")
    insert = "INSERT INTO experiments (%s) VALUES (%s)" % (",".join(FIELDS), ",".join("?" * len(FIELDS)))
    all_id = db.execute(insert, [total[k] for k in FIELDS]).lastrowid
    for experiment in experiments:
        add_columns(db, "experiments", [(n, t) for n, t, _ in experiment["properties"]])
        experiment_id = db.execute(insert, [experiment[k] for k in FIELDS]).lastrowid
        for name, kind, value in experiment["properties"]:
            db.execute('UPDATE experiments SET "%s" = ? WHERE id = ?' % name,
                       (None if value in INVALID else value, experiment_id))
        for enum in experiment["enums"]:
            if not db.execute("SELECT 1 FROM enums WHERE name = ?", (enum[0],)).fetchone():
                db.executemany("INSERT INTO enums VALUES (?, ?, ?)",
                               [(enum[0], i, d) for i, d in enumerate(enum[1:])])
        for planner in experiment["planners"]:
            found = db.execute("SELECT id FROM plannerConfigs WHERE name = ? AND settings = ?",
                               (planner["name"], planner["settings"])).fetchone()
            planner_id = found[0] if found else db.execute(
                "INSERT INTO plannerConfigs (name, settings) VALUES (?, ?)",
                (planner["name"], planner["settings"])).lastrowid
            add_columns(db, "runs", planner["properties"])
            names = ["experimentid", "plannerid"] + [n for n, _ in planner["properties"]]
            row = 'INSERT INTO runs (%s) VALUES (%s)' % (",".join('"%s"' % n for n in names), ",".join("?" * len(names)))
            for values in planner["runs"]:
                db.execute(row, [experiment_id, planner_id] + values)
                db.execute(row, [all_id, planner_id] + values)
    solved_time = "time + simplification_time" if "simplification_time" in {
        r[1] for r in db.execute("PRAGMA table_info(runs)")} else "time"
    runs = ("SELECT plannerid, plannerConfigs.name AS plannerName, experimentid, solved, %s AS total_time "
            "FROM plannerConfigs INNER JOIN experiments INNER JOIN runs "
            "ON plannerConfigs.id = runs.plannerid AND experiments.id = runs.experimentid" % solved_time)
    for view, by in (("bestPlannerConfigsPerExperiment", ", experimentid"), ("bestPlannerConfigs", "")):
        means = ("SELECT plannerid, plannerName%s, AVG(solved) AS avg_solved, AVG(total_time) AS avg_total_time "
                 "FROM (%s) GROUP BY plannerid%s" % (by, runs, by))
        db.execute("CREATE VIEW %s AS SELECT plannerid%s, MIN(avg_solved) AS avg_solved, avg_total_time "
                   "FROM (%s) GROUP BY plannerName%s ORDER BY avg_solved DESC, avg_total_time ASC"
                   % (view, by, means, by))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("logs", nargs="+")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    try:
        experiments = [read_log(path) for path in args.logs]
    except (LogError, ValueError, OSError) as error:
        print("ompl_benchmark_database.py: error: %s" % error, file=sys.stderr)
        return 2
    folder = os.path.dirname(os.path.abspath(args.output))
    handle, temporary = tempfile.mkstemp(prefix="." + os.path.basename(args.output) + ".", dir=folder)
    os.close(handle)
    try:
        db = sqlite3.connect(temporary)
        with db:
            write_database(experiments, db)
        db.close()
        os.chmod(temporary, 0o666 & ~_umask())
        os.replace(temporary, args.output)
    finally:
        if os.path.exists(temporary):
            os.unlink(temporary)
    return 0


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


if __name__ == "__main__":
    sys.exit(main())
