#!/usr/bin/env python3
"""large_study.py SOURCE.h5 N OUT.h5: a batch file of N runs in seconds, each run a hard link
to one of the runs of SOURCE (a real batch file), its summary table repeated to N rows with
the runs' names and indices: the readers read every run as they would N distinct ones (a
study of 10^4 real runs takes over an hour to compute on two cores)."""
import shutil, sys
import h5py, numpy as np
source, n, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
shutil.copy(source, out)
with h5py.File(out, "r+") as f:
    runs = f["runs"]
    first = sorted(runs)
    study = f.attrs["study_name"]
    study = study.decode() if isinstance(study, bytes) else study
    width = len(str(n - 1))
    names = ["%s_%0*d" % (study, width, i) for i in range(n)]
    groups = [runs[name] for name in first]
    for name in first:
        del runs[name]
    for i, name in enumerate(names):
        runs[name] = groups[i % len(groups)]
    table = f["batch/summary"]
    for column in list(table):
        data = table[column][()]
        attrs = dict(table[column].attrs)
        del table[column]
        rep = np.resize(data, n)
        if column == "name":
            rep = np.array([s.encode() for s in names], dtype=object)
            d = table.create_dataset(column, data=rep, dtype=h5py.string_dtype())
        elif column == "index":
            d = table.create_dataset(column, data=np.arange(n, dtype=data.dtype))
        else:
            d = table.create_dataset(column, data=rep, dtype=data.dtype)
        for k, v in attrs.items():
            d.attrs[k] = v
    f.attrs["run_count"] = np.int32(n)
