#!/usr/bin/python3
"""plot_batch.py BATCH.h5 -o FIG.png [--metrics a,b,c]: the summary figure of a `wpg batch`
file: each metric (rows) against each swept key (columns), one point per finished run, failed
runs (exit_status 1) as red crosses. Non-numeric swept values (lists, maps) are placed at their
rank among the distinct values, labelled with their YAML text.

Reads /batch/summary with h5py only (layout: datasets/SCHEMA.md, "Batch files"; metrics:
datasets/METRICS.md), every column checked (wpg_file_reading.py); a bad file gives one line,
`plot_batch.py: FILE: /path: expected ...`, and exit status 2. Debian's h5py and matplotlib
(/usr/bin/python3).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wpg_file_reading import (  # noqa: E402
    BadFile, Reader, import_h5py, open_file, png_metadata, run_script, save_figure)

SCRIPT = "plot_batch.py"
import_h5py(SCRIPT)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DEFAULT_METRICS = "velocity_error_rms,cop_margin_min,distance,qp_iterations_mean"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("batch_file")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--metrics", default=DEFAULT_METRICS)
    args = parser.parse_args()

    with open_file(args.batch_file) as f:
        reader = Reader(args.batch_file, f)
        table = reader.group(reader.group(f, "batch"), "summary")
        columns = reader.attribute(table, "columns", kind="texts")
        data, units, rows = {}, {}, None
        for name in columns:
            # numbers (NaN: not run) or text (names; swept lists or maps as YAML)
            data[name] = reader.dataset(table, name, kind="auto", rows=rows, finite=False)
            rows = len(data[name])
            units[name] = reader.attribute(table[name], "units", kind="text")
        study = reader.attribute(f, "study_name", kind="text")
    for required in ("done", "exit_status"):
        if required not in data:
            raise BadFile("%s: /batch/summary:columns: expected the column %s"
                          % (args.batch_file, required))
    keys = [c for c in columns if c.startswith("sweep.")]
    metrics = [m for m in args.metrics.split(",") if m in data and data[m].dtype.kind in "fiu"]
    if not keys or not metrics:
        raise BadFile("%s: /batch/summary: expected a swept key and a metric to plot"
                      % args.batch_file)
    done = data["done"] == 1
    failed = done & (data["exit_status"] != 0)
    fig, axes = plt.subplots(len(metrics), len(keys), squeeze=False,
                             figsize=(3.6 * len(keys) + 1, 2.4 * len(metrics) + 0.8))
    for col, key in enumerate(keys):
        values = data[key]
        if values.dtype.kind in "fi":
            x, labels = values.astype(float), None
        else:
            strings = [str(v) for v in values]
            labels = sorted(set(strings), key=strings.index)
            x = np.array([labels.index(s) for s in strings], dtype=float)
        for row, metric in enumerate(metrics):
            ax = axes[row][col]
            y = data[metric].astype(float)
            ok = done & ~failed
            ax.plot(x[ok], y[ok], ".", color="tab:blue", alpha=0.7, label="succeeded")
            if failed.any():
                ax.plot(x[failed], y[failed], "x", color="tab:red", label="failed")
            if labels is not None:
                ax.set_xticks(range(len(labels)))
                ax.set_xticklabels(labels, rotation=20, fontsize=7)
            if row == len(metrics) - 1:
                ax.set_xlabel(key[len("sweep."):])
            if col == 0:
                unit = units[metric]
                ax.set_ylabel(metric + ("" if unit == "1" else f" [{unit}]"), fontsize=8)
            ax.grid(alpha=0.3)
    fig.suptitle(f"study {study}: {int(done.sum())} runs, {int(failed.sum())} failed")
    fig.tight_layout()
    save_figure(fig, args.output, dpi=100, metadata=png_metadata(args.batch_file))
    return 0


if __name__ == "__main__":
    run_script(SCRIPT, main)
