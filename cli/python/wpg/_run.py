"""Run: one walk (its samples, footsteps, NMPC log, metrics and replay) as numpy and pandas."""
import os
import tempfile

from . import _wpg
from ._figure import run_figure

_REPLAY_ARRAYS = ("q", "zmp_multibody", "com_filtered", "zmp_multibody_filtered")


class Run:
    """One walk, from wpg.run() or read back by wpg.io.load_run().

    The per-sample arrays (time, com, cop, ...) are read-only numpy views of the C++ result
    (nothing copied; the run keeps them alive), in the units and frames of the dataset
    (datasets/SCHEMA.md). A failed walk is a run too: success False, exit_code 1.
    """

    def __init__(self, core):
        self._core = core
        self._cache = {}

    def __repr__(self):
        return "<wpg.Run %s: %s, %d samples>" % (self.name, self.outcome, len(self.time))

    # --- outcome ------------------------------------------------------------------------
    @property
    def name(self):
        """The scenario's name (the dataset's group /runs/<name>)."""
        return self._core.name

    @property
    def success(self):
        """True when the walk (and its replay) succeeded: `wpg run` exits 0."""
        return self._core.success

    @property
    def exit_code(self):
        """`wpg run`'s exit status for this run: 0 succeeded, 1 the walk (or replay) failed."""
        return self._core.exit_code

    @property
    def outcome(self):
        """"succeeded", "walk_failed", "replay_failed" or "blocked" (the robot stopped making
        progress along its command and had not resumed at the end: datasets/SCENARIOS.md,
        generator.blocked_window_cycles)."""
        return self._core.outcome

    @property
    def blocked(self):
        """True when the walk ended blocked (the dataset's `blocked` attribute)."""
        return self._core.blocked

    @property
    def blocked_since(self):
        """Start of the blocked stretch [s] (the start of the first window without progress);
        None when not blocked."""
        return self._core.blocked_since

    @property
    def blocked_position(self):
        """(x, y) of the CoM [m, world] when the blocked stretch started; None when not
        blocked."""
        return self._core.blocked_position

    @property
    def message(self):
        """What went wrong first (one line); empty on success."""
        return self._core.message

    @property
    def warnings(self):
        """The scenario loader's warnings (a command beyond the robot's clamp, a value outside
        its plausible range; datasets/SCENARIOS.md, "Warnings"), one line each as `wpg` prints
        them after "wpg: warning: "; wpg.run() also issues each as a Python warning."""
        return list(self._core.warnings)

    @property
    def scenario(self):
        """The resolved scenario (YAML text: every key explicit, the overrides merged)."""
        return self._core.scenario_yaml

    # --- samples at the control period ---------------------------------------------------
    def _walk(self, name):
        if name not in self._cache:
            self._cache[name] = self._core.walk_array(name)
        return self._cache[name]

    time = property(lambda self: self._walk("time"), doc="(N,) time of each sample [s].")
    com = property(lambda self: self._walk("com"), doc="(N, 3) CoM position x, y, z [m], world.")
    com_vel = property(lambda self: self._walk("com_vel"), doc="(N, 3) CoM velocity [m/s].")
    com_acc = property(lambda self: self._walk("com_acc"), doc="(N, 3) CoM acceleration [m/s^2].")
    cop = property(lambda self: self._walk("cop"), doc="(N, 2) CoP of the LIPM, x, y [m] (eq. 3).")
    left_foot = property(lambda self: self._walk("left_foot"),
                         doc="(N, 4) left ankle x, y, z [m], yaw [rad].")
    right_foot = property(lambda self: self._walk("right_foot"),
                          doc="(N, 4) right ankle x, y, z [m], yaw [rad].")
    free_flyer_yaw = property(lambda self: self._walk("free_flyer_yaw"),
                              doc="(N,) waist yaw, mean of the foot yaws [rad].")
    support = property(lambda self: self._walk("support"),
                       doc="(N,) support phase codes: 0 double, 1 left, 2 right.")

    # --- tables --------------------------------------------------------------------------
    @property
    def footsteps(self):
        """pandas.DataFrame of the landed footsteps (the two initial feet first, landing_time
        0): landing_time [s], x, y [m], yaw [rad], side ("left"/"right")."""
        if "footsteps" not in self._cache:
            import pandas as pd
            frame = pd.DataFrame(self._core.footstep_columns())
            frame.attrs["units"] = {"landing_time": "s", "x": "m", "y": "m", "yaw": "rad",
                                    "side": "1"}
            self._cache["footsteps"] = frame
        return self._cache["footsteps"].copy()

    @property
    def mpc(self):
        """pandas.DataFrame, one row per NMPC iteration: time, status (text, e.g. "solved"),
        status_code, solve_time [s, wall time], qp_iterations, sqp_iterations, cost,
        relaxed_families (bit mask), commanded_vx, commanded_vy [m/s, world: the linear command
        the iteration tracked, as progress is measured along it; NaN when read back from a file
        without it], then slack_<family> per constraint family (its unit in
        df.attrs["units"])."""
        if "mpc" not in self._cache:
            import pandas as pd
            frame = pd.DataFrame(self._core.mpc_columns())
            units = {"time": "s", "status": "1", "status_code": "1", "solve_time": "s",
                     "qp_iterations": "1", "sqp_iterations": "1", "cost": "1",
                     "relaxed_families": "1", "commanded_vx": "m/s", "commanded_vy": "m/s"}
            groups = {}
            for family, unit, group in self._core.constraint_families():
                units["slack_" + family] = unit
                groups["slack_" + family] = group
            frame.attrs["units"] = units
            frame.attrs["groups"] = groups
            self._cache["mpc"] = frame
        return self._cache["mpc"].copy()

    @property
    def plans(self):
        """wpg.Plans: what each NMPC iteration predicted (the dataset's mpc/plan/; arrays per
        iteration, .frame() a tidy DataFrame); None when the run did not record it
        (generator.record_plan false, a study's `plan: false`)."""
        if "plans" not in self._cache:
            from ._plans import Plans, stored_plan_columns
            columns = self._core.plan_columns()
            if len(columns["sample_count"]) == 0:
                columns = None
                if self._core.stored_file:
                    columns = stored_plan_columns(self._core.stored_file, self.name)
            families = [family for family, _unit, _group in self._core.constraint_families()]
            self._cache["plans"] = (None if columns is None else
                                    Plans(columns, self.mpc["time"].to_numpy(), families))
        return self._cache["plans"]

    @property
    def route_plans(self):
        """pandas.DataFrame, one row per route plan of a walk to a goal (none otherwise), as
        the dataset's plans/ group holds them (datasets/SCHEMA.md): time [s], trigger and
        status (text, e.g. "start", "exact_solution"), planning_time and simplification_time
        [s, wall time], route_length, solution_length, simplified_solution_length,
        solution_clearance [m], graph_states, graph_motions, and route: the (k, 3) waypoints x,
        y [m], yaw [rad] (k = 0: no route)."""
        if "route_plans" not in self._cache:
            import pandas as pd
            frame = pd.DataFrame(self._core.route_plan_columns())
            frame.attrs["units"] = {"time": "s", "trigger": "1", "status": "1", "planning_time": "s",
                                    "route_length": "m", "solution_length": "m",
                                    "simplified_solution_length": "m", "solution_clearance": "m",
                                    "simplification_time": "s", "graph_states": "1",
                                    "graph_motions": "1", "route": "m, m, rad"}
            self._cache["route_plans"] = frame
        return self._cache["route_plans"].copy()

    @property
    def metrics(self):
        """dict of the metrics of datasets/METRICS.md: the names and values `wpg analyze`
        gives (counts as int; NaN where a metric does not apply)."""
        out = {}
        for name, value, _unit, integer, _wall in self._core.metric_rows():
            out[name] = int(value) if integer and value == value else value
        return out

    # --- multibody replay ----------------------------------------------------------------
    def _replay(self, name):
        if name not in self._cache:
            array = self._core.replay_array(name)
            if array is None and self._core.stored_file:
                array = _stored_dataset(self._core.stored_file, self.name, name)
            self._cache[name] = array
        return self._cache[name]

    q = property(lambda self: self._replay("q"),
                 doc="(N, nq) configuration sent to the robot (replayed runs; else None).")
    zmp_multibody = property(lambda self: self._replay("zmp_multibody"),
                             doc="(N, 2) multibody ZMP before the filter [m] (replayed runs).")
    com_filtered = property(lambda self: self._replay("com_filtered"),
                            doc="(N, 3) CoM corrected by the dynamic filter [m] (filtered runs).")
    zmp_multibody_filtered = property(lambda self: self._replay("zmp_multibody_filtered"),
                                      doc="(N, 2) multibody ZMP after the filter [m].")

    @property
    def replay(self):
        """dict of the replay's summary (configuration_names, zmp_error_*, ik_failures,
        filter_mode, wall_time) for a run replayed by wpg.run(); empty otherwise."""
        return dict(self._core.replay_summary())

    # --- files ---------------------------------------------------------------------------
    def save(self, path):
        """Writes the run's dataset at `path`: the file `wpg run -o PATH` writes (`wpg diff`
        finds them identical but for wall times). Raises wpg.InputError (nothing written) for
        a path that is a folder, a device, an input or a file that is not HDF5."""
        self._core.save(os.fspath(path))

    def figure(self, plan=False, at=None):
        """The run's figure as `wpg plot` draws it (a matplotlib Figure). With plan=True, the
        one of `wpg plot --plan`: what the NMPC previewed at the iterations at the times `at`
        [s] (default four spread over the walk) against what the robot did."""
        if self._core.stored_file:
            return run_figure(self._core.stored_file, self.name, plan, at)
        with tempfile.TemporaryDirectory(prefix="wpg-figure-") as folder:
            path = os.path.join(folder, "run.h5")
            self.save(path)
            return run_figure(path, self.name, plan, at)


def _stored_dataset(path, run_name, name):
    """/runs/<run_name>/<name> of a file read back (None when absent), one copy."""
    import h5py
    with h5py.File(path, "r") as handle:
        group = handle["runs"][run_name]
        if name not in group:
            return None
        array = group[name][()]
    array.flags.writeable = False
    return array
