"""compare_batch_files.py A.h5 B.h5: the two files hold the same contents, bit for bit, except
the wall-time fields (datasets/SCHEMA.md, "Batch files": mpc/solve_time, the timing/ group and
the summary's nmpc_time_* columns; a goal walk's plans/planning_time and
plans/simplification_time; the planning and NMPC time columns of `wpg compare`'s tables) and
the root attributes that say where and when a file was written (created_on, created_at). Exit 0
same, 1 different (each difference on stderr).

Reads both files with h5py only: every group, dataset (values and dtype) and attribute.
"""
import sys

import h5py
import numpy as np

WALL_TIME = ("solve_time", "timing", "nmpc_time_mean", "nmpc_time_std", "nmpc_time_min",
             "nmpc_time_max", "nmpc_time_p99",
             # walks to a goal (plans/) and `wpg compare` (/batch/summary, /compare/summary)
             "planning_time", "simplification_time", "planning_time_median", "planning_time_max",
             "nmpc_time_median")

# Where and when the file was written (wpg/datasets/storage/provenance.hpp): not its contents.
PROVENANCE = ("created_on", "created_at")

differences = []


def same_values(a, b):
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        a, b = np.asarray(a), np.asarray(b)
        if a.shape != b.shape or a.dtype != b.dtype:
            return False
        if a.dtype.kind == "f":
            # bit for bit, NaN equal to NaN
            return a.tobytes() == b.tobytes()
        return bool(np.all(a == b))
    if isinstance(a, float) and isinstance(b, float) and np.isnan(a) and np.isnan(b):
        return True
    return a == b


def compare_attributes(path, a, b):
    if set(a.attrs) != set(b.attrs):
        differences.append(f"{path}: attributes {sorted(set(a.attrs) ^ set(b.attrs))}")
        return
    for name in a.attrs:
        if path == "" and name in PROVENANCE:
            continue
        if not same_values(a.attrs[name], b.attrs[name]):
            differences.append(f"{path}: attribute {name} differs")


def compare(path, a, b):
    compare_attributes(path, a, b)
    if isinstance(a, h5py.Group):
        if not isinstance(b, h5py.Group):
            differences.append(f"{path}: group vs dataset")
            return
        if set(a) != set(b):
            differences.append(f"{path}: members {sorted(set(a) ^ set(b))}")
        for name in sorted(set(a) & set(b)):
            if name in WALL_TIME:
                continue
            compare(f"{path}/{name}", a[name], b[name])
    else:
        if not (same_stored_chunks(a, b) or same_values(a[()], b[()])):
            differences.append(f"{path}: values differ")


def same_stored_chunks(a, b):
    """Whether two chunked datasets of one type and shape store the same bytes in every chunk,
    compressed as they are: then their values are the same, bit for bit, without inflating
    them (which took a third of this script's time). False when anything differs, the values
    are then compared."""
    if a.chunks is None or a.chunks != b.chunks or a.shape != b.shape or a.dtype != b.dtype \
            or a.compression != b.compression or a.dtype.kind in "OV":
        return False
    count = a.id.get_num_chunks()
    if count != b.id.get_num_chunks():
        return False
    for i in range(count):
        offset = a.id.get_chunk_info(i).chunk_offset
        if b.id.get_chunk_info(i).chunk_offset != offset \
                or a.id.read_direct_chunk(offset) != b.id.read_direct_chunk(offset):
            return False
    return True


def main():
    with h5py.File(sys.argv[1], "r") as a, h5py.File(sys.argv[2], "r") as b:
        compare("", a, b)
    for line in differences[:20]:
        print(line, file=sys.stderr)
    if differences:
        print(f"{len(differences)} differences", file=sys.stderr)
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main())
