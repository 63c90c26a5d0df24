"""A reader of OMPL benchmark log files, written from the grammar of OMPL's documentation ("The
benchmark logfile format", EBNF): it accepts exactly what the grammar allows (and the ENUM
property type that OMPL itself writes for `status`) and raises LogError naming the line
otherwise. Used by the tests of `wpg compare --ompl-log` (check_ompl_log.py).

    experiment = read_log(path)
    experiment["planners"][0]["runs"][0]["time to goal"]   # a float, or None for "", nan, inf
"""
import re

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
TYPES = ("BOOLEAN", "INTEGER", "REAL", "ENUM")


class LogError(Exception):
    pass


class Lines:
    def __init__(self, path):
        with open(path, encoding="utf-8") as stream:
            self.lines = stream.read().split("\n")
        if self.lines and self.lines[-1] == "":
            self.lines.pop()  # the EOL of the last line
        self.at = 0
        self.path = path

    def peek(self):
        return self.lines[self.at] if self.at < len(self.lines) else None

    def take(self):
        line = self.peek()
        if line is None:
            raise LogError("%s: ends early (after line %d)" % (self.path, self.at))
        self.at += 1
        return line

    def fail(self, expected):
        raise LogError("%s line %d: expected %s, got %r" % (self.path, self.at, expected,
                                                              self.lines[self.at - 1]))

    def match(self, pattern, expected):
        line = self.take()
        found = re.fullmatch(pattern, line)
        if not found:
            self.fail(expected)
        return found


def multi_line(lines, what):
    if lines.take() != "<<<|":
        lines.fail("'<<<|' opening the " + what)
    text = []
    while True:
        line = lines.take()
        if line == "|>>>":
            return "\n".join(text)
        text.append(line)


def data_value(text, kind, lines):
    if text in ("", "nan", "inf"):
        return None
    if not re.fullmatch(NUMBER, text):
        lines.fail("a number, 'inf', 'nan' or nothing (got %r)" % text)
    value = float(text)
    if kind in ("INTEGER", "BOOLEAN", "ENUM") and value != int(value):
        lines.fail("an integer for a %s property (got %r)" % (kind, text))
    if kind == "BOOLEAN" and value not in (0, 1):
        lines.fail("0 or 1 for a BOOLEAN property (got %r)" % text)
    return value


def read_log(path):
    lines = Lines(path)
    e = {"properties": {}}
    version = re.fullmatch(r"(\S+) version (\S+)", lines.peek() or "")
    if version:
        lines.take()
        e["library"], e["version"] = version.group(1), version.group(2)
    e["name"] = lines.match(r"Experiment (\S+)", "'Experiment <name>'").group(1)
    count = re.fullmatch(r"(\d+) experiment properties", lines.peek() or "")
    if count:
        lines.take()
        for _ in range(int(count.group(1))):
            found = lines.match(r"(.+) (\S+) ?= ?(.*)", "'<name> <TYPE> = <value>'")
            e["properties"][found.group(1)] = (found.group(2), found.group(3))
    e["host"] = lines.match(r"Running on (\S+)", "'Running on <host>'").group(1)
    e["date"] = lines.match(r"Starting at (.+)", "'Starting at <date>'").group(1)
    e["setup"] = multi_line(lines, "setup")
    e["cpuinfo"] = multi_line(lines, "cpu info") if lines.peek() == "<<<|" else None
    e["seed"] = int(lines.match(r"(\d+) is the random seed", "'<int> is the random seed'").group(1))
    e["time_limit"] = float(lines.match(r"(%s) seconds per run" % NUMBER, "'<float> seconds per run'").group(1))
    e["memory_limit"] = float(lines.match(r"(%s) MB per run" % NUMBER, "'<float> MB per run'").group(1))
    runs = re.fullmatch(r"(\d+) runs per planner", lines.peek() or "")
    if runs:
        lines.take()
        e["runs_per_planner"] = int(runs.group(1))
    e["total_time"] = float(lines.match(r"(%s) seconds spent to collect the data" % NUMBER,
                                        "'<float> seconds spent to collect the data'").group(1))
    e["enums"] = {}
    enums = re.fullmatch(r"(\d+) enum types?", lines.peek() or "")
    if enums:
        lines.take()
        for _ in range(int(enums.group(1))):
            parts = lines.take().split("|")
            if len(parts) < 2:
                lines.fail("'<enum name>|<value>|...'")
            e["enums"][parts[0]] = parts[1:]
    planners = int(lines.match(r"(\d+) planners", "'<int> planners'").group(1))
    e["planners"] = []
    for _ in range(planners):
        planner = {"name": lines.take(), "common": {}, "runs": []}
        if not planner["name"]:
            lines.fail("a planner name")
        common = int(lines.match(r"(\d+) common properties", "'<int> common properties'").group(1))
        for _ in range(common):
            found = lines.match(r"(.+?) = (.*)", "'<name> = <value>'")
            planner["common"][found.group(1)] = found.group(2)
        count = int(lines.match(r"(\d+) properties for each run", "'<int> properties for each run'").group(1))
        properties = []
        for _ in range(count):
            found = lines.match(r"(.+) (%s)" % "|".join(TYPES), "'<name> <TYPE>'")
            properties.append((found.group(1), found.group(2)))
        planner["properties"] = properties
        runs = int(lines.match(r"(\d+) runs", "'<int> runs'").group(1))
        for _ in range(runs):
            line = lines.take()
            if not line.endswith("; ") and not (count == 0 and line == ""):
                lines.fail("run values each followed by '; '")
            values = line[:-2].split("; ") if count else []
            if len(values) != count:
                lines.fail("%d values (one per property), got %d" % (count, len(values)))
            planner["runs"].append({name: data_value(v, kind, lines)
                                    for (name, kind), v in zip(properties, values)})
        progress = re.fullmatch(r"(\d+) progress properties for each run", lines.peek() or "")
        if progress:  # optional; wpg writes none, read for completeness
            lines.take()
            for _ in range(int(progress.group(1))):
                lines.take()
            for _ in range(int(lines.match(r"(\d+) runs", "'<int> runs'").group(1))):
                lines.take()
        if lines.take() != ".":
            lines.fail("'.' closing the planner")
        e["planners"].append(planner)
    if lines.peek() is not None:
        raise LogError("%s line %d: text after the last planner" % (path, lines.at + 1))
    return e
