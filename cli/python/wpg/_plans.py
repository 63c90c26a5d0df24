"""Plans: what each NMPC iteration of a run predicted (the dataset's mpc/plan/)."""


class Plans:
    """One row per NMPC iteration (row i of Run.mpc), numpy arrays in the units and frame of
    datasets/SCHEMA.md, "mpc/plan": sample_count (k,), com, com_vel, com_acc, jerk, cop
    (k, N, 2: previewed sample j + 1 of iteration i at time[i] + (j + 1) * sampling_period;
    rows past sample_count[i] hold 0), steps (k, nf, 4: landing_time, x, y, yaw), step_side
    (k, nf: 1 left, 2 right), active_rows (k, F: per constraint family, `families`)."""

    def __init__(self, columns, time, families):
        self.time = time
        self.families = list(families)
        self.sampling_period = float(columns.pop("sampling_period"))
        for name, array in columns.items():
            array.flags.writeable = False
            setattr(self, name, array)

    def __len__(self):
        return len(self.sample_count)

    def __repr__(self):
        return "<wpg.Plans: %d iterations x %d samples x %d steps>" % (
            len(self), self.com.shape[1] if self.com.ndim == 3 else 0,
            self.steps.shape[1] if self.steps.ndim == 3 else 0)

    def frame(self):
        """A tidy pandas.DataFrame, one row per (iteration, previewed sample): iteration,
        time (of the iteration), sample (1 ..), sample_time, com_x, com_y, com_vel_x, ...,
        jerk_x, jerk_y, cop_x, cop_y."""
        import numpy as np
        import pandas as pd
        k = len(self)
        n = self.com.shape[1] if self.com.ndim == 3 else 0
        mask = np.arange(n)[None, :] < self.sample_count[:, None]
        iteration = np.repeat(np.arange(k), n).reshape(k, n)
        sample = np.tile(np.arange(1, n + 1), k).reshape(k, n)
        columns = {"iteration": iteration[mask], "time": self.time[iteration[mask]],
                   "sample": sample[mask]}
        columns["sample_time"] = columns["time"] + columns["sample"] * self.sampling_period
        for name in ("com", "com_vel", "com_acc", "jerk", "cop"):
            values = getattr(self, name)
            columns[name + "_x"] = values[..., 0][mask]
            columns[name + "_y"] = values[..., 1][mask]
        return pd.DataFrame(columns)


def stored_plan_columns(path, run_name):
    """mpc/plan/ of a stored run as plan_columns() gives it (None when absent)."""
    import h5py
    with h5py.File(path, "r") as handle:
        mpc = handle["runs"][run_name]["mpc"]
        if "plan" not in mpc:
            return None
        plan = mpc["plan"]
        k, n, s = len(plan["sample_count"]), int(plan.attrs["samples"]), int(plan.attrs["steps"])
        out = {"sampling_period": float(plan.attrs["sampling_period"]),
               "sample_count": plan["sample_count"][()],
               "steps": plan["steps"][()].reshape(k, s, 4),
               "step_side": plan["step_side"][()].reshape(k, s)}
        for name in ("com", "com_vel", "com_acc", "jerk", "cop"):
            out[name] = plan[name][()].reshape(k, n, 2)
        out["active_rows"] = plan["active_rows"][()] if "active_rows" in plan else None
        return out
