"""Reading wpg's files (datasets/SCHEMA.md) into numpy and pandas: runs and study summaries.

Every function takes a run file (`wpg run`), a batch file (`wpg batch`), a merged index
(`wpg merge`) or the index an MPI batch writes (its runs are HDF5 external links to the shards,
followed here as everywhere).
"""
import os
import re

from . import _wpg
from ._figure import analysis_folder
from ._wpg import InputError


def load_run(path, name=None):
    """The run `name` of the file at `path` as a wpg.Run (any run, batch, merged or MPI index
    file); `name` may be left out when the file holds one run. The walk is checked against its
    stored scenario and its metrics recomputed as `wpg analyze` does; the multibody datasets
    (q, zmp_multibody, ...) are read from the file when first used. Raises wpg.InputError (one
    line naming the file) for a missing or bad file or run."""
    from ._run import Run
    path = os.fspath(path)
    return Run(_wpg.load_run(path, _run_name(path, name) if name else ""))


def _run_name(path, name):
    """`name`, or the run it numbers: a batch names its runs <study>_<index> with the index
    zero-padded to the width of the largest ("study_007" of 200 runs), and "study_7" is taken
    for it."""
    numbered = re.fullmatch(r"(.*)_([0-9]+)", name)
    if not numbered:
        return name
    names = run_names(path)
    if name in names:
        return name
    pattern = re.compile(re.escape(numbered.group(1)) + "_0*" + str(int(numbered.group(2))))
    matches = [candidate for candidate in names if pattern.fullmatch(candidate)]
    return matches[0] if len(matches) == 1 else name


def run_names(path):
    """The names of the runs under /runs of the file (sorted)."""
    return _wpg.run_names(os.fspath(path))


def _table(path, group_name):
    """The columns of a table group (one 1-D dataset per column, `columns` in order), read as
    `wpg` and its figure scripts read (analysis/wpg_file_reading.py): the file checked to be a
    regular file, every link checked before it is followed, every size before it is loaded."""
    import numpy as np
    analysis_folder()
    import wpg_file_reading as reading
    path = os.fspath(path)
    # HDF5 loops forever or crashes the interpreter on a damaged global heap: the table's
    # strings are checked (in C++, with every size bounded) before h5py reads them.
    _wpg.check_stored_strings(path, "/" + group_name)
    try:
        with reading.open_file(path) as handle:
            reader = reading.Reader(path, handle)
            group = reader.group(handle, group_name, optional=True)
            if group is None:
                raise InputError("%s: /%s: expected a table, missing (not a %s file)"
                                 % (path, group_name,
                                    "batch" if group_name == "batch/summary" else "comparison"))
            names = reader.attribute(group, "columns", kind="texts", optional=True)
            columns, units = {}, {}
            for name in names if names is not None else sorted(group):
                values = reader.dataset(group, name, kind="auto", finite=False,
                                        max_rows=reading.MAX_READ_ELEMENTS)
                columns[name] = values.astype(object) if values.dtype.kind == "U" else values
                units[name] = reader.attribute(group[name], "units", kind="text", default="",
                                               optional=True)
    except reading.BadFile as error:
        raise InputError(str(error)) from None
    return columns, units


def load_summary(path):
    """/batch/summary of a batch file (or index) as a pandas.DataFrame, one row per run of the
    study (row = index), columns in the file's order. Swept values are typed: a number as
    float, a swept vector (stored as YAML text, e.g. "[0.2, 0, 0]") as a column of tuples of
    floats plus one float column per component, `sweep.<key>[i]`; other swept texts as their
    parsed YAML. `done` is bool. df.attrs["units"] gives each column's unit, and
    df.attrs["swept_keys"] the swept keys."""
    import pandas as pd
    import yaml
    columns, units = _table(path, "batch/summary")
    out, out_units, swept = {}, {}, []
    for name, values in columns.items():
        if name.startswith("sweep.") and values.dtype == object:
            # Each distinct text parsed and converted once: a study of 10^6 runs sweeps a few
            # values (10^6 rows: 110 s when every row was parsed, 7 s so).
            distinct = {text: yaml.safe_load(text) for text in set(values)}
            swept.append(name[len("sweep."):])
            items = list(distinct.values())
            if items and all(_is_vector(item) and len(item) == len(items[0]) for item in items):
                tuples = {text: tuple(float(x) for x in item) for text, item in distinct.items()}
                out[name] = [tuples[text] for text in values]
                out_units[name] = units[name]
                for i in range(len(items[0])):
                    component = {text: float(item[i]) for text, item in distinct.items()}
                    out["%s[%d]" % (name, i)] = [component[text] for text in values]
                    out_units["%s[%d]" % (name, i)] = units[name]
                continue
            out[name] = [distinct[text] for text in values]
        else:
            if name.startswith("sweep."):
                swept.append(name[len("sweep."):])
            out[name] = values.astype(bool) if name == "done" else values
        out_units[name] = units[name]
    frame = pd.DataFrame(out)
    frame.attrs["units"] = out_units
    frame.attrs["swept_keys"] = swept
    return frame


def load_compare_summary(path):
    """/compare/summary of a comparison study's study.h5 (or of its folder) as a
    pandas.DataFrame, one row per world x variant; units in df.attrs["units"]."""
    import pandas as pd
    path = os.fspath(path)
    if os.path.isdir(path):
        path = os.path.join(path, "study.h5")
    columns, units = _table(path, "compare/summary")
    frame = pd.DataFrame(columns)
    frame.attrs["units"] = units
    return frame


def _is_vector(item):
    return isinstance(item, list) and all(
        isinstance(x, (int, float)) and not isinstance(x, bool) for x in item)
