"""The documentation held to the code where it counts or names things: the metrics of
datasets/METRICS.md (names and order) are the summary's metric columns, every column of a
batch's /batch/summary is one datasets/SCHEMA.md describes, and the shapes docs/python.md's
worked example prints are those of its study (run here with the same swept keys, one value
each and short walks: the columns depend on the keys, not on the values), and the regression
references the docs count are the files."""
import os
import re

import h5py
import yaml

import wpg
from conftest import SOURCE


def doc(path):
    return open(os.path.join(SOURCE, path), encoding="utf-8").read()


def table_names(text, header):
    """The backticked names of the first cell of each row of the first Markdown table from
    `header` on (a table's header line, or text before it)."""
    lines = text[text.index(header):].splitlines()
    first = next(i for i, line in enumerate(lines) if line.startswith("|"))
    lines = lines[first + 2:]
    names = []
    for line in lines:
        if not line.startswith("|"):
            break
        names += re.findall(r"`([^`]+)`", line.split("|")[1])
    return names


def python_example_study(tmp_path):
    """docs/python.md's study with one value per key and 0.5 s walks."""
    study = yaml.safe_load(doc("datasets/studies/speeds_weights_heights.yaml"))
    scenario = yaml.safe_load(doc("datasets/scenarios/walk_forward.yaml"))
    scenario["duration"] = 0.5
    (tmp_path / "short.yaml").write_text(yaml.safe_dump(scenario))
    study["base"] = "short.yaml"
    for key, values in study["sweep"]["grid"].items():
        study["sweep"]["grid"][key] = values[:1]
    study["sweep"]["random"]["samples"] = 1
    path = tmp_path / "study.yaml"
    path.write_text(yaml.safe_dump(study))
    return path


def test_summary_columns_are_the_documented_ones(tmp_path):
    table = wpg.batch(python_example_study(tmp_path), output=tmp_path / "s.h5", jobs=1, plot=False)
    with h5py.File(tmp_path / "s.h5", "r") as f:
        columns = [c.decode() if isinstance(c, bytes) else c for c in f["batch/summary"].attrs["columns"]]
        swept = [k.decode() if isinstance(k, bytes) else k for k in f.attrs["swept_keys"]]
        codes = f["runs"][f["batch/summary/name"].asstr()[0]]["mpc/status"].attrs["codes"]
    metrics = table_names(doc("datasets/METRICS.md"), "| metric | unit | definition |")
    assert len(metrics) == len(set(metrics)) and metrics, metrics
    # SCHEMA.md's order: index, name, sweep.<key>, done, exit_status, status_<code>, the metrics.
    schema = table_names(doc("datasets/SCHEMA.md"), "`/batch/summary/`: one 1-D dataset")
    assert schema[:6] == ["index", "name", "sweep.<key>", "done", "exit_status", "status_<name>"], schema
    statuses = ["status_" + part.split("=", 1)[1] for part in (codes.decode() if isinstance(codes, bytes) else codes).split(", ")]
    expected = ["index", "name"] + ["sweep." + k for k in swept] + ["done", "exit_status"] + statuses + metrics
    assert columns == expected, "summary columns not as documented:\n%s\n%s" % (columns, expected)

    # docs/python.md's worked example: the shape and the swept keys it prints.
    example = doc("docs/python.md")
    rows, count = map(int, re.search(r"table\.shape\s+# \((\d+), (\d+)\)", example).groups())
    full = yaml.safe_load(doc("datasets/studies/speeds_weights_heights.yaml"))["sweep"]
    runs = len(full["grid"]["reference[1].v"]) * len(full["grid"]["walking.weight_cop"]) * full["random"]["samples"]
    assert (rows, count) == (runs, table.shape[1]), "docs/python.md says (%d, %d), the code gives (%d, %d)" % (
        rows, count, runs, table.shape[1])
    printed = re.search(r'table\.attrs\["swept_keys"\]\s+# (\[.*\])', example).group(1)
    assert yaml.safe_load(printed) == table.attrs["swept_keys"]


def test_reference_counts_are_the_files():
    """The regression references the docs count are the files of datasets/references/."""
    files = [n for n in os.listdir(os.path.join(SOURCE, "datasets", "references")) if n.endswith(".h5")]
    for page in ("docs/commands.md", "docs/testing.md"):
        counts = re.findall(r"(\d+) shipped scenarios", doc(page))
        assert counts and all(int(c) == len(files) for c in counts), (page, counts, len(files))
