#!/usr/bin/python3
"""plot_batch.py BATCH.h5 -o FIG.png [--metrics a,b,c]: the summary figure of a `wpg batch`
file: each metric (rows) against each swept key (columns), one point per finished run, failed
runs (exit_status 1) as red crosses. Non-numeric swept values (lists, maps) are placed at their
rank among the distinct values, labelled with their YAML text.

Reads /batch/summary with h5py only (layout: datasets/SCHEMA.md, "Batch files"; metrics:
datasets/METRICS.md). Debian's h5py and matplotlib (/usr/bin/python3).
"""
import argparse
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DEFAULT_METRICS = "velocity_error_rms,cop_margin_min,distance,qp_iterations_mean"


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("batch_file")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--metrics", default=DEFAULT_METRICS)
    args = parser.parse_args()

    with h5py.File(args.batch_file, "r") as f:
        table = f["batch/summary"]
        columns = [text(c) for c in table.attrs["columns"]]
        data = {name: table[name][:] for name in columns}
        units = {name: text(table[name].attrs["units"]) for name in columns}
        study = text(f.attrs["study_name"])
    keys = [c for c in columns if c.startswith("sweep.")]
    metrics = [m for m in args.metrics.split(",") if m in data]
    if not keys or not metrics:
        print(f"{args.batch_file}: no swept key or no metric to plot", file=sys.stderr)
        return 2
    done = data["done"] == 1
    failed = done & (data["exit_status"] != 0)
    fig, axes = plt.subplots(len(metrics), len(keys), squeeze=False,
                             figsize=(3.6 * len(keys) + 1, 2.4 * len(metrics) + 0.8))
    for col, key in enumerate(keys):
        values = data[key]
        if values.dtype.kind in "fi":
            x, labels = values.astype(float), None
        else:
            strings = [text(v) for v in values]
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
    fig.savefig(args.output, dpi=100)
    return 0


if __name__ == "__main__":
    sys.exit(main())
