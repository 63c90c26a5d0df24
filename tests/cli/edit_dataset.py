"""edit_dataset.py CASE RUN.h5: edits a run file written by `wpg run walk_forward` in place
into what a corrupt or hostile file holds, with h5py only.

Cases:
  nan_time          /runs/<run>/time row 12 = NaN
  time_backwards    /runs/<run>/time row 30 = 0.1 s (rows 29, 30 were 0.145, 0.15 s)
  nan_footstep      /runs/<run>/footsteps row 3 column 1 = NaN
  other_period      the stored scenario says walking.control_period 0.01 (the walk is at 5 ms)
  huge_rows         /runs/<run>/com replaced by a chunked dataset that declares 2e8 x 3 values
                    and stores none (a few kB declaring 4.8 GB)
  no_foot_length    walking.foot_length removed from the stored scenario
"""
import sys

import h5py
import numpy as np


def main():
    case, path = sys.argv[1], sys.argv[2]
    with h5py.File(path, "r+") as f:
        (name,) = list(f["runs"])
        run = f["runs"][name]
        scenario = f.attrs["scenario"]
        if case == "nan_time":
            run["time"][12] = np.nan
        elif case == "time_backwards":
            run["time"][30] = 0.1
        elif case == "nan_footstep":
            run["footsteps"][3, 1] = np.nan
        elif case == "other_period":
            assert "control_period: 0.005" in scenario, scenario
            f.attrs["scenario"] = scenario.replace("control_period: 0.005", "control_period: 0.01")
        elif case == "huge_rows":
            del run["com"]
            run.create_dataset("com", shape=(200000000, 3), maxshape=(None, 3), chunks=(1024, 3),
                               dtype="<f8")
        elif case == "no_foot_length":
            lines = scenario.split("\n")
            kept = [line for line in lines if not line.strip().startswith("foot_length:")]
            assert len(kept) == len(lines) - 1, scenario
            f.attrs["scenario"] = "\n".join(kept)
        else:
            sys.exit("edit_dataset.py: unknown case " + case)


if __name__ == "__main__":
    main()
