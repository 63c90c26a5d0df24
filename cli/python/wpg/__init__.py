"""wpg from Python: walks, studies and the online generator of the reactive walking pattern
generator (Naveau et al., RA-L 2017), with every result as numpy arrays and pandas tables.

    import wpg
    run = wpg.run("walk_forward", overrides={"duration": 12, "reference[1].v": [0.3, 0, 0]})
    run.success, run.com, run.footsteps, run.metrics
    table = wpg.batch("datasets/studies/speeds_weights_heights.yaml", output="out/s.h5", jobs=2)

The reference is docs/python.md. Everything runs in this process on the C++ engine (the
`wpg` command-line tool is not called); runs and studies release the GIL.
"""
import os
import warnings as _warnings

from . import _wpg
from ._wpg import InputError
from ._overrides import override_items
from ._run import Run
from ._online import OnlineGenerator
from ._studies import batch, compare
from . import io

__all__ = ["run", "batch", "compare", "scenarios", "families", "costs", "data_directory", "Run",
           "OnlineGenerator", "InputError", "io"]

InputError.__module__ = "wpg"
InputError.__doc__ = ("Bad input (scenario, override, study, file): the one-line message of "
                      "the `wpg` command-line tool, naming the file and the key. A ValueError.")


def run(scenario="walk_forward", overrides=None, replay=False, filter=False):  # noqa: A002
    """Runs one scenario as `wpg run` does and returns its wpg.Run (nothing is written: see
    Run.save).

    scenario  -- a shipped scenario's name (wpg.scenarios()) or a scenario YAML file.
    overrides -- {key: value} as `--set key=value`: dotted keys with indices, e.g.
                 {"duration": 12, "reference[1].v": [0.3, 0, 0], "walking.com_height": 0.8};
                 each value is written as YAML text (lists, dicts, numbers, bools, strings).
    replay    -- replay the walk on the multibody model (`--replay`): run.q, run.zmp_multibody.
    filter    -- also run the dynamic filter (`--filter`, implies replay): run.com_filtered,
                 run.zmp_multibody_filtered.

    What the loader warns about (a command beyond the robot's clamp, ...) is issued as a
    UserWarning and kept in run.warnings; it changes nothing of the walk.
    A walk that fails is a result (run.success False, run.exit_code 1, run.message says why).
    Bad input raises wpg.InputError with the CLI's one-line message naming the key. The walk
    runs without the GIL: Python threads can run walks in parallel.
    """
    result = Run(_wpg.run(os.fspath(scenario), override_items(overrides), bool(replay),
                          bool(filter)))
    for warning in result.warnings:  # as `wpg run` prints them (the run records them too)
        _warnings.warn(warning, UserWarning, stacklevel=2)
    return result


def families():
    """The registered constraint families a scenario's `constraints:` section (or an override
    "constraints.<name>.<parameter>") may use: [{"name", "description", "parameters": [{"name",
    "unit", "description", "required", "default"}]}], sorted by name (docs/extending.md)."""
    return list(_wpg.families())


def costs():
    """The registered cost terms of `costs:` ("costs.<name>.<parameter>"), as families()."""
    return list(_wpg.costs())


def scenarios():
    """The names of the shipped scenarios (datasets/scenarios/*.yaml), sorted."""
    return list(_wpg.scenarios())


def data_directory():
    """The folder holding robots/, datasets/scenarios/ and analysis/, found as `wpg` finds
    it: $WPG_DATA_DIR, else the source tree the package was built from, else <prefix>/share/wpg."""
    return _wpg.data_directory()
