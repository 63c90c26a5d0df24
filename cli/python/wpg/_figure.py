"""The figure of a run: the CLI's own drawing code (`wpg plot`), called through run_figure() so
that wherever that code lives, only this file follows it."""
import importlib.util
import os
import sys

from . import _wpg


def analysis_folder():
    """analysis/ of the data directory (as `wpg plot` finds it), on sys.path: plot_run.py
    imports its reading helpers (wpg_file_reading.py) from its folder, and wpg.io reads with
    them too."""
    folder = os.path.join(_wpg.data_directory(), "analysis")
    if folder not in sys.path:
        sys.path.append(folder)
    return folder


def _plot_module():
    """analysis/plot_run.py of the data directory, imported once."""
    name = "wpg_plot_run"
    if name in sys.modules:
        return sys.modules[name]
    folder = analysis_folder()
    spec = importlib.util.spec_from_file_location(name, os.path.join(folder, "plot_run.py"))
    module = importlib.util.module_from_spec(spec)
    # The module selects the Agg backend for its command-line use; a caller that already
    # uses pyplot (a notebook's inline backend) keeps its own.
    previous = sys.modules["matplotlib.pyplot"].get_backend() \
        if "matplotlib.pyplot" in sys.modules else None
    spec.loader.exec_module(module)
    if previous is not None:
        import matplotlib.pyplot as plt
        if plt.get_backend() != previous:
            plt.switch_backend(previous)
    sys.modules[name] = module
    return module


def run_figure(path, name=None, plan=False, at=None):
    """The matplotlib Figure `wpg plot PATH [--run NAME]` draws; with `plan`, the one of
    `--plan [--at T...]` (predicted against executed)."""
    plot = _plot_module()
    runs = plot.read_runs(path, name)
    return plot.draw_plan(runs, path, list(at or ())) if plan else plot.draw(runs, path)
