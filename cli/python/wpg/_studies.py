"""wpg.batch and wpg.compare: studies on the engine's own worker threads."""
import os
import subprocess
import sys

from . import _wpg
from .io import load_summary, load_compare_summary


def batch(study, output, jobs=1, resume=False, plot=False, fields=None):
    """Runs a study (datasets/SCENARIOS.md, "Studies") as `wpg batch STUDY -o OUTPUT -j JOBS`:
    the engine's thread executor (the GIL released) writes OUTPUT (one group per run and
    /batch/summary, the same runs bit for bit whatever `jobs`) and OUTPUT.summary.csv/.md
    beside it; with plot=True also OUTPUT.summary.png (analysis/plot_batch.py). `resume`
    finishes an interrupted OUTPUT of the same study (`--resume`). `fields` (`--fields`): what
    each run stores, a list such as ["summary", "footsteps"] or "summary,footsteps"
    (datasets/SCHEMA.md, "Lean runs"); None: the study's `fields:`, every field by default.

    Returns /batch/summary as a pandas.DataFrame (wpg.io.load_summary). Failed walks are rows
    with exit_status 1 (df.attrs["failed_runs"] counts them), not an exception; bad input
    raises wpg.InputError before anything is written.
    """
    study, output = os.fspath(study), os.fspath(output)
    if isinstance(fields, str):
        fields = [name.strip() for name in fields.split(",")] if fields.strip() else []
    fields = None if fields is None else [str(name) for name in fields]
    _file, _runs, failed = _wpg.batch(study, output, int(jobs), bool(resume), bool(plot), fields)
    if plot:
        _draw("plot_batch.py", [output, "-o", os.path.splitext(output)[0] + ".summary.png"])
    table = load_summary(output)
    table.attrs["failed_runs"] = int(failed)
    return table


def compare(study, output, jobs=1, plot=False):
    """Runs a comparison study (datasets/SCENARIOS.md, "Comparison studies": worlds x variants
    x seeds of walks to a goal) as `wpg compare STUDY -o OUTPUT -j JOBS`: OUTPUT/study.h5,
    OUTPUT/summary.csv and summary.md; with plot=True also the figures of
    analysis/plot_compare.py. Returns /compare/summary as a pandas.DataFrame, one row per
    world x variant (wpg.io.load_compare_summary); walks that miss the goal are rows, not
    errors."""
    study, output = os.fspath(study), os.fspath(output)
    batch_file, _runs = _wpg.compare(study, output, int(jobs), bool(plot))
    if plot:
        _draw("plot_compare.py", [batch_file, "-o", output])
    return load_compare_summary(batch_file)


def _draw(script, arguments):
    path = os.path.join(_wpg.data_directory(), "analysis", script)
    subprocess.run([sys.executable, path] + arguments, check=True)
