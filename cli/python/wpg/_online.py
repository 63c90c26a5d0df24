"""OnlineGenerator: libwpg's online walking generator, one control period per step()."""
import json

from . import _wpg
from ._overrides import override_items


class OnlineGenerator:
    """The online API of the pattern generator (paper Fig. 3: the NMPC every sampling period,
    the interpolation every control period, 5 ms for HRP-2), built from a scenario's walking
    parameters, generator settings, obstacles and robot mass. It starts standing at the origin
    with a zero command; the scenario's velocity schedule and pushes are not applied (give
    them with step(command=...) and push()).

        gen = wpg.OnlineGenerator("walk_forward")
        for _ in range(400):
            s = gen.step(command=(0.2, 0.0, 0.0))   # s.com, s.cop, s.left_foot, s.support, s.status
    """

    def __init__(self, scenario="walk_forward", overrides=None):
        """`scenario`: a shipped scenario's name or a YAML file; `overrides` as wpg.run()'s."""
        self._core = _wpg.OnlineCore(str(scenario), override_items(overrides))

    def step(self, command=None):
        """Runs one control period and returns its state: time, com, com_vel, com_acc (3,),
        cop (2,), left_foot, right_foot (4,: x, y, z, yaw), support ("double", "left",
        "right"), status (of the last NMPC iteration, as mpc/status), nmpc_sample (the NMPC ran
        in this period), landed, fallen, plan (at NMPC samples: a dict of what the NMPC
        predicted, the arrays of wpg.Plans for this one iteration, e.g. plan["com"] (N, 2);
        else None). `command` (vx [m/s], vy [m/s], omega [rad/s], robot
        frame), when given, replaces the current command from the next NMPC sample on."""
        return self._core.step(command)

    def set_obstacles(self, obstacles):
        """Replaces the obstacles, used from the next NMPC sample on. Each is a dict as in a
        scenario's `obstacles:` list, e.g. {"type": "circle", "center": [1.5, 0], "radius": 0.3,
        "margin": 0.2}; an empty list removes them. Raises wpg.InputError naming the key."""
        self._core.set_obstacles(json.dumps(list(obstacles), default=_json_value))

    def push(self, force, duration=0.1):
        """A horizontal force (fx, fy) [N, world] on the CoM during `duration` [s] from the next
        step on (divided by the scenario's robot_mass, as a scenario's pushes)."""
        fx, fy = (float(value) for value in force)
        self._core.push(fx, fy, float(duration))

    def reset(self, pose=(0.0, 0.0, 0.0)):
        """Standing again at pose (x, y, yaw), time 0, zero command, no push; obstacles kept."""
        x, y, yaw = (float(value) for value in pose)
        self._core.reset(x, y, yaw)

    @property
    def time(self):
        """[s] the instant the next step() starts at."""
        return self._core.time

    @property
    def control_period(self):
        """[s] the time one step() covers."""
        return self._core.control_period

    @property
    def command(self):
        """The current command (vx, vy, omega) as a numpy array."""
        return self._core.command


def _json_value(value):
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError("%s is not a number, list or dict" % type(value).__name__)
