#!/usr/bin/python3
"""plot_obstacle_scenes.py BATCH.h5 -o FIG.png [--table TABLE.md]: the outcome of each walk of
the obstacle-scenes study (datasets/studies/obstacle_scenes.yaml, docs/obstacle_scenes.md):
slaloms, boxes and polygons, mixed obstacles, doorways, scenes without a passage, obstacles met
while turning and on lateral or diagonal commands.

Per run, from its stored scenario (obstacles, velocity command, walking parameters) and its
fields (com, com_vel, free_flyer_yaw, footsteps, checks/step_centre_clearance, mpc/status):

The command: the reference's last entry, held from t0 on (the first time after which the
schedule no longer changes). The robot starts at the origin facing +x: the command's frame is
the world's at t0 and turns by omega (t - t0) after it (the commanded heading).

Is there a passage? In the plane of the CoM: a step centre keeps margin + obstacle_foot_radius
from each obstacle (the NMPC's bound; the radius from the stored walking map, else HRP-2's
0.1287 m), and two consecutive feet stand at least the minimal step width apart across the
command (least_step_width: 0.1755 m for HRP-2), so the CoM between them needs margin +
obstacle_foot_radius + half that from every obstacle. Each obstacle grown by that much is a
convex polygon (its edges moved out exactly, the corners' arcs and circles as polygons
circumscribed about them in pieces of at most 2 pi / ARC_SEGMENTS: at most 1/cos(pi/64) - 1 =
0.12 % of the growth further out, and exact along the edges of boxes and polygons). The CoM may
go anywhere within BAND of the commanded path (of its circle, for a turning command) and no
further than BEHIND behind the start: a detour beyond that is a route to plan (a walk to a goal,
docs/goals-and-planners.md), not a command to follow. That region is convex, so that the
shortest path in it round convex obstacles bends only at their corners: the shortest path of
the visibility graph of the start, the goal and the polygons' vertices (Dijkstra), exact for
the polygons, never shorter than round the exact shapes (round a circle at most 0.074 % longer
than the analytic length, r / a from 0.1 to 0.99: tests/analysis/test_obstacle_scenes.py, which
allows the polygon's 0.12 %). The goal: the point of the commanded path as far along it as the
furthest grown obstacle reaches. A passage exists when the visibility graph connects the start to the goal.

Along the command, a point's progress is its distance along the commanded line from the start
(for a turning command, its angle about the circle's centre from the start, times the radius).
- past: the first sample from t0 on at which the CoM's progress reaches the furthest progress
  of any obstacle grown by its margin (the far side of the last margin);
- time to pass: past - t0;
- allowed: ALLOWED_FACTOR x L / v + ALLOWED_EXTRA, L the shortest free path (for a turning
  command the longer of it and the commanded arc, which a straight path round nothing cuts
  short; without a passage, the commanded path's length), v the commanded speed;
- inside: a landed step's centre inside a margin (checks/step_centre_clearance below
  -obstacle_foot_radius);
- relaxed: NMPC iterations with the status relaxed_obstacle (mpc/status, by its codes);
- walks on: over the last WALK_ON_WINDOW s the CoM's velocity along the commanded direction
  averages at least WALK_ON_FRACTION of the commanded speed, and the free-flyer yaw ends within
  WALK_ON_HEADING of the commanded heading (plot_obstacle_passing.py's test, for any command).
Outcome: "failed" when the walk failed (the run's attribute success is 0: a fall, a step landed
inside the NMPC's bound); else "blocked" when never past; "passed" when past within the
allowed time, never inside, never relaxed, walking on; "slow" otherwise (the table says why).
A run's `blocked` attribute (with `blocked_since`), when the file has one and it is set, says
the walk was stopped on purpose: its success 0 then counts as failed only for a fall (an
iteration with the status fallen) or a step landed inside the NMPC's bound, and the table names
it. A walk is "correct" when it passed a scene with a passage, or was blocked by a scene
without one.

The kind of a scene is the first word of its label (the run's swept `name`, as the study's zip
gives it; the run's name without one), its row in the figure the label without that word and
its last, its column the last word (the commanded speed, mostly). The figure: per kind, the top
view of one walk (the scene with the longest detour, at the speed nearest 0.2 m/s) and a grid
of every walk, coloured by its time to pass over the time allowed. Checked reads
(wpg_file_reading.py): a bad file is one line and exit status 2.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_obstacle_passing import WALK_ON_FRACTION, WALK_ON_WINDOW  # noqa: E402
from run_figure.geometry import sole_corners  # noqa: E402
from run_figure.scenario_text import scenario_obstacles  # noqa: E402
from run_figure.styles import (COM_COLOUR, DEFAULT_FOOT_LENGTH,  # noqa: E402
                               DEFAULT_FOOT_WIDTH, LEFT_COLOUR, RIGHT_COLOUR)
from run_figure.top_view import draw_obstacles  # noqa: E402
from wpg_file_reading import (BadFile, Reader, import_h5py, open_file,  # noqa: E402
                              parse_scenario, png_metadata, run_script, save_figure,
                              walking_number)

SCRIPT = "plot_obstacle_scenes.py"
import_h5py(SCRIPT)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Polygon, Rectangle  # noqa: E402

# HRP-2's step feasibility polygon (eq. 14: a left step in the right support foot's frame; its
# inner edge, y = 0.2 m from x = -0.28 to 0.28 m, is how close beside the support foot a step
# lands) and yaw bound (eq. 16), robots/hrp2/walking.yaml, for a stored scenario without them.
HRP2_FEASIBILITY = ((-0.28, 0.2), (-0.2, 0.3), (0.0, 0.4), (0.2, 0.3), (0.28, 0.2))  # [m]
HRP2_MAX_STEP_YAW_CHANGE = 0.17  # [rad]
# HRP-2's sole half diagonal, walking.obstacle_foot_radius, for a stored scenario without it.
DEFAULT_FOOT_RADIUS = 0.1287  # [m]
# Circles and rounded corners: polygons of this many sides about the full circle (a multiple of
# 4, so that a circle's polygon has the circle's extent along the axes).
ARC_SEGMENTS = 64
# The region a command is expected to lead through: within BAND of the commanded path (a wall
# 6 m long across the path, 3.33 m either side with its margin and the foot, leaves no way
# round), at most BEHIND behind the start (the open end of a U round the start is no way out).
BAND = 2.5  # [m]
BEHIND = 0.5  # [m]
# Allowed time to pass: ALLOWED_FACTOR x the shortest free path at the commanded speed, plus
# ALLOWED_EXTRA for the start of the walk (the first step lifts off 0.8 s after the command) and
# the steps round an obstacle, slower along the command than straight ones.
ALLOWED_FACTOR = 1.5
ALLOWED_EXTRA = 5.0  # [s]
# Walking on: the yaw at the end within this of the commanded heading (plot_obstacle_passing.py).
WALK_ON_HEADING = 0.1  # [rad]
# Points this close to a polygon's boundary are not inside it (coordinates of a few metres).
EPS = 1e-7  # [m]

# Kinds of scene (the first word of a label), in the figure's order, with their titles.
KINDS = (("slalom", "slalom of circles"), ("shape", "a box or a polygon on the path"),
         ("mixed", "two or three mixed obstacles"), ("gap", "a doorway between two walls"),
         ("closed", "no passage: a wall, an enclosure"), ("turning", "met while turning"),
         ("sideways", "lateral and diagonal commands"))
OUTCOMES = ("passed", "slow", "blocked", "failed")
OUTCOME_MARK = {"passed": "", "slow": "s", "blocked": "B", "failed": "F"}
# The grid's colour scale: time to pass over the time allowed (1 = the limit).
RATIO_TOP = 1.5


# --- geometry ------------------------------------------------------------------------------


def _number(value, low=0.0):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and \
        math.isfinite(value) and value >= low


def least_step_width(feasibility, max_step_yaw_change):
    """The least distance across its heading between two consecutive feet of a robot that
    faces its command: a step lands in the feasibility polygon of the support foot's frame
    (eq. 14), 0.2 m beside it at least for HRP-2, but the feet may toe in and out in turn by
    half the yaw bound (eq. 16), which turns the polygon: its corner (0.28, 0.2) then lies
    0.2 cos(0.085) - 0.28 sin(0.085) = 0.1755 m across for HRP-2 (side by side, a doorway
    needs 0.2 + 2 (margin 0.2 + 0.1287) = 0.857 m; docs/obstacle_scenes.md; libwpg's
    WalkingParameters::leastStepWidth is the same bound). Turned sideways,
    a robot would need no width at all: the command's heading, which J2 holds, rules that out."""
    half = 0.5 * max_step_yaw_change
    return min(abs(y) * math.cos(half) - abs(x) * math.sin(half) for x, y in feasibility)


# The minimal step width: the least distance across the command between two consecutive feet of
# HRP-2 facing its command, 0.1755 m (0.2 m side by side).
MIN_STEP_WIDTH = least_step_width(HRP2_FEASIBILITY, HRP2_MAX_STEP_YAW_CHANGE)  # [m]


def _arc_points(centre, radius, start, sweep):
    """The polyline circumscribed about the arc of `radius` about `centre` from the angle
    `start` over `sweep` (>= 0) rad, in pieces of at most 2 pi / ARC_SEGMENTS: its two ends on
    the arc, its edges tangent to it (the polygon made of such polylines holds the disc, and
    meets it at every piece's middle)."""
    pieces = max(1, int(math.ceil(sweep / (2.0 * math.pi / ARC_SEGMENTS) - 1e-9)))
    step = sweep / pieces
    angles = start + step * (np.arange(pieces) + 0.5)
    reach = radius / math.cos(0.5 * step)
    points = [(centre[0] + radius * math.cos(start), centre[1] + radius * math.sin(start))]
    points += [(centre[0] + reach * math.cos(a), centre[1] + reach * math.sin(a)) for a in angles]
    points.append((centre[0] + radius * math.cos(start + sweep),
                   centre[1] + radius * math.sin(start + sweep)))
    return points


def _circle_points(centre, radius):
    """ARC_SEGMENTS vertices of the polygon circumscribed about the circle (it holds it), its
    edges tangent to it facing +x, +y, -x, -y (ARC_SEGMENTS is a multiple of 4): its extent
    along the axes is the circle's."""
    angles = 2.0 * math.pi * (np.arange(ARC_SEGMENTS) + 0.5) / ARC_SEGMENTS
    reach = radius / math.cos(math.pi / ARC_SEGMENTS)
    return np.column_stack((centre[0] + reach * np.cos(angles),
                            centre[1] + reach * np.sin(angles)))


def grown_polygon(shape, growth):
    """The obstacle `shape` ((outline, margin, circle, known) of scenario_obstacles) grown by
    `growth` m (its margin is not added): a counter-clockwise convex polygon holding the exact
    grown shape (the Minkowski sum with a disc): the outline's edges moved out by `growth`,
    exactly, joined by polylines circumscribed about the corners' arcs; a circle as a polygon
    circumscribed about the grown circle."""
    outline, _margin, circle, _known = shape
    if circle is not None:
        return _circle_points(circle[1:3], circle[3] + growth)
    corners = np.asarray(outline, dtype=float)
    area = np.sum(corners[:, 0] * np.roll(corners[:, 1], -1) -
                  np.roll(corners[:, 0], -1) * corners[:, 1])
    if area < 0.0:
        corners = corners[::-1]
    if growth <= 0.0:
        return corners
    edges = np.roll(corners, -1, axis=0) - corners
    outward = np.arctan2(-edges[:, 0], edges[:, 1])   # the angle of each edge's outer normal
    points = []
    for i, corner in enumerate(corners):
        before, after = outward[i - 1], outward[i]
        points += _arc_points(corner, growth, before, np.mod(after - before, 2.0 * math.pi))
    return np.array(points)


def _half_planes(polygon):
    """Outward unit normals n and offsets d of a counter-clockwise polygon: inside is n.x < d."""
    edges = np.roll(polygon, -1, axis=0) - polygon
    normals = np.column_stack((edges[:, 1], -edges[:, 0]))
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    return normals, np.einsum("ij,ij->i", normals, polygon)


def _strictly_inside(points, planes):
    normals, offsets = planes
    return np.all(points @ normals.T < offsets - EPS, axis=1)


def _segments_cross(p, q, planes):
    """Whether each segment p[i] q[i] crosses the polygon's interior (Cyrus-Beck clipping
    against the polygon shrunk by EPS: segments along its boundary do not)."""
    normals, offsets = planes
    room = offsets[None, :] - EPS - p @ normals.T      # > 0: p inside that edge's half-plane
    rate = (q - p) @ normals.T                         # its change from p to q
    with np.errstate(divide="ignore", invalid="ignore"):
        bound = room / rate
    parallel = np.abs(rate) <= 1e-12
    low = np.max(np.where(rate < -1e-12, bound, -np.inf), axis=1, initial=-np.inf)
    high = np.min(np.where(rate > 1e-12, bound, np.inf), axis=1, initial=np.inf)
    low, high = np.maximum(low, 0.0), np.minimum(high, 1.0)
    return (low < high) & np.all(~parallel | (room > 0.0), axis=1)


def shortest_path(start, goal, polygons, region=None):
    """The shortest path from `start` to `goal` round the convex `polygons` (counter-clockwise
    vertex arrays) inside the convex region `region(points) -> bool array` (None: the plane):
    (length, vertices), or (nan, None) when there is none."""
    start, goal = np.asarray(start, float), np.asarray(goal, float)
    planes = [_half_planes(p) for p in polygons]
    ends = np.array([start, goal])
    if region is not None and not np.all(region(ends)):
        return math.nan, None
    if any(np.any(_strictly_inside(ends, plane)) for plane in planes):
        return math.nan, None
    corners = np.concatenate(polygons) if polygons else np.zeros((0, 2))
    keep = np.ones(len(corners), dtype=bool)
    if region is not None and len(corners):
        keep &= region(corners)
    for plane in planes:
        keep &= ~_strictly_inside(corners, plane)
    nodes = np.concatenate((ends, corners[keep]))
    n = len(nodes)
    first, second = np.triu_indices(n, 1)
    visible = np.ones(len(first), dtype=bool)
    for plane in planes:
        open_pairs = np.flatnonzero(visible)
        visible[open_pairs] = ~_segments_cross(nodes[first[open_pairs]],
                                               nodes[second[open_pairs]], plane)
    weights = np.full((n, n), np.inf)
    lengths = np.linalg.norm(nodes[first] - nodes[second], axis=1)
    weights[first[visible], second[visible]] = lengths[visible]
    weights[second[visible], first[visible]] = lengths[visible]
    # Dijkstra on the dense graph (a few hundred nodes).
    distance = np.full(n, np.inf)
    previous = np.full(n, -1)
    distance[0] = 0.0
    done = np.zeros(n, dtype=bool)
    for _ in range(n):
        current = int(np.argmin(np.where(done, np.inf, distance)))
        if done[current] or not math.isfinite(distance[current]) or current == 1:
            break
        done[current] = True
        through = distance[current] + weights[current]
        better = through < distance
        distance[better] = through[better]
        previous[better] = current
    if not math.isfinite(distance[1]):
        return math.nan, None
    path, node = [], 1
    while node != -1:
        path.append(nodes[node])
        node = previous[node]
    return float(distance[1]), np.array(path[::-1])


class CommandPath:
    """The path a constant command (vx, vy, omega), robot frame, walks from the origin facing
    +x: a line, or for omega != 0 a circle; progress along it, its points, the region within
    BAND of it."""

    def __init__(self, command):
        vx, vy, omega = (float(v) for v in command)
        self.speed = math.hypot(vx, vy)
        if self.speed <= 0.0:
            raise ValueError("a command that does not walk")
        self.direction = np.array([vx, vy]) / self.speed
        self.omega = omega
        self.turn = 0.0 if omega == 0.0 else math.copysign(1.0, omega)
        if self.turn:
            self.radius = self.speed / abs(omega)
            left = np.array([-self.direction[1], self.direction[0]])
            self.centre = self.turn * self.radius * left

    def progress(self, points):
        points = np.atleast_2d(points)
        if not self.turn:
            return points @ self.direction
        start = -self.centre
        offset = points - self.centre
        angle = np.arctan2(start[0] * offset[:, 1] - start[1] * offset[:, 0],
                           offset @ start) * self.turn
        # Angles in [-pi/2, 3pi/2): a little behind the start, up to most of a turn ahead.
        return self.radius * (np.mod(angle + 0.5 * math.pi, 2.0 * math.pi) - 0.5 * math.pi)

    def point(self, progress):
        if not self.turn:
            return progress * self.direction
        angle = self.turn * progress / self.radius
        c, s = math.cos(angle), math.sin(angle)
        start = -self.centre
        return self.centre + np.array([c * start[0] - s * start[1], s * start[0] + c * start[1]])

    def region(self, points):
        """Within BAND of the commanded line (circle) and at most BEHIND behind the start."""
        points = np.atleast_2d(points)
        ahead = points @ self.direction >= -BEHIND - EPS
        if not self.turn:
            side = np.abs(points @ np.array([-self.direction[1], self.direction[0]]))
            return ahead & (side <= BAND + EPS)
        return ahead & (np.linalg.norm(points - self.centre, axis=1) <= self.radius + BAND + EPS)

    def inner_obstacle(self):
        """For a turn wider than BAND, the disc inside the region's inner circle."""
        if self.turn and self.radius > BAND:
            return _circle_points(self.centre, self.radius - BAND)
        return None

    def heading(self, elapsed):
        return self.omega * elapsed

    def world_direction(self, elapsed):
        """The commanded direction of motion, world frame, `elapsed` s after t0 (an array)."""
        angle = self.heading(np.asarray(elapsed, float))
        c, s = np.cos(angle), np.sin(angle)
        return np.column_stack((c * self.direction[0] - s * self.direction[1],
                                s * self.direction[0] + c * self.direction[1]))


def analyse_scene(shapes, command, foot_radius=DEFAULT_FOOT_RADIUS, min_width=MIN_STEP_WIDTH):
    """The geometry of one scene: `shapes` as scenario_obstacles gives them, the constant
    command (vx, vy, omega). Returns a dict: path (CommandPath), past (the progress at which the
    CoM is past every margin), passage, length (the shortest free path, nan without passage),
    route (its vertices), goal, commanded (the commanded path's length to the goal)."""
    path = CommandPath(command)
    margins = [grown_polygon(s, s[1]) for s in shapes]
    free = [grown_polygon(s, s[1] + foot_radius + 0.5 * min_width) for s in shapes]
    past = max((float(np.max(path.progress(p))) for p in margins), default=0.0)
    reach = max((float(np.max(path.progress(p))) for p in free), default=0.0)
    goal = path.point(reach + 0.01)
    obstacles = list(free)
    inner = path.inner_obstacle()
    if inner is not None:
        obstacles.append(inner)
    length, route = shortest_path((0.0, 0.0), goal, obstacles, path.region)
    commanded = reach + 0.01
    return dict(path=path, past=past, passage=route is not None, length=length, route=route,
                goal=goal, commanded=commanded, margins=margins, free=free)


def allowed_time(scene):
    """ALLOWED_FACTOR x the path to walk at the commanded speed + ALLOWED_EXTRA, s after t0."""
    length = scene["commanded"]
    if scene["passage"]:
        length = max(length, scene["length"])
    return ALLOWED_FACTOR * length / scene["path"].speed + ALLOWED_EXTRA


def scene_walking(scenario):
    """(obstacle_foot_radius, least_step_width) of a stored scenario's walking map, HRP-2's
    where it lacks them."""
    walking = scenario.get("walking") if isinstance(scenario.get("walking"), dict) else {}
    radius = walking.get("obstacle_foot_radius")
    radius = float(radius) if _number(radius) else DEFAULT_FOOT_RADIUS
    xs, ys = walking.get("feasibility_x"), walking.get("feasibility_y")
    feasibility = HRP2_FEASIBILITY
    if isinstance(xs, list) and isinstance(ys, list) and len(xs) == len(ys) and xs and \
            all(_number(v, -math.inf) for v in xs) and all(_number(v, -math.inf) for v in ys):
        feasibility = tuple(zip((float(v) for v in xs), (float(v) for v in ys)))
    yaw = walking.get("max_step_yaw_change")
    yaw = float(yaw) if _number(yaw) else HRP2_MAX_STEP_YAW_CHANGE
    return radius, least_step_width(feasibility, yaw)


def scene_command(scenario):
    """(t0, (vx, vy, omega)): the last command of the reference and since when it holds."""
    reference = scenario.get("reference")
    if not isinstance(reference, list) or not reference:
        raise ValueError("expected a velocity command")
    last = [float(v) for v in reference[-1]["v"]]
    start = float(reference[-1]["t"])
    for entry in reversed(reference[:-1]):
        if [float(v) for v in entry["v"]] != last:
            break
        start = float(entry["t"])
    return start, last


# --- the walks -----------------------------------------------------------------------------


def status_code(reader, status, name):
    """The code of the status `name` in mpc/status's `codes` ("0=solved, 1=relaxed_obstacle")."""
    codes = reader.attribute(status, "codes", kind="text")
    for item in codes.split(","):
        code, _, label = item.strip().partition("=")
        if label.strip() == name and code.strip().isdigit():
            return int(code)
    reader.fail(status.name + ":codes", "expected the code of %s" % name)


def walk(path, reader, run, scenes):
    where = run.name + ":scenario"
    scenario = parse_scenario(path, where, reader.attribute(run, "scenario", kind="text"))
    label = reader.attribute(run, "sweep.name", kind="text", optional=True) or \
        run.name.rsplit("/", 1)[-1]
    try:
        t0, command = scene_command(scenario)
        shapes = scenario_obstacles(scenario)
        foot_radius, min_width = scene_walking(scenario)
        key = (repr(scenario.get("obstacles")), tuple(command), foot_radius, min_width)
        if shapes and key not in scenes:
            scenes[key] = analyse_scene(shapes, command, foot_radius, min_width)
    except (KeyError, IndexError, TypeError, ValueError, AttributeError):
        raise BadFile("%s: %s: expected a constant velocity command that walks, and obstacles"
                      % (path, where))
    if not shapes:
        raise BadFile("%s: %s: expected obstacles" % (path, where))
    scene = scenes[key]
    time = reader.dataset(run, "time")
    com = reader.dataset(run, "com", columns=3, rows=len(time))
    com_vel = reader.dataset(run, "com_vel", columns=3, rows=len(time))
    yaw = reader.dataset(run, "free_flyer_yaw", rows=len(time))
    steps = reader.dataset(run, "footsteps", columns=4)
    sides = reader.dataset(run, "footstep_side", kind="integer", rows=len(steps))
    clearance = reader.dataset(reader.group(run, "checks"), "step_centre_clearance",
                               rows=len(steps))
    mpc = reader.group(run, "mpc")
    statuses = reader.dataset(mpc, "status", kind="integer")
    relaxed = int(np.count_nonzero(statuses == status_code(reader, mpc["status"],
                                                           "relaxed_obstacle")))
    fell = bool(np.any(statuses == status_code(reader, mpc["status"], "fallen")))
    if not len(time):
        reader.fail(run.name + "/time", "expected samples")
    command_path = scene["path"]
    beyond = np.flatnonzero((command_path.progress(com[:, :2]) >= scene["past"]) & (time >= t0))
    window = time >= time[-1] - WALK_ON_WINDOW
    along = np.einsum("ij,ij->i", com_vel[window, :2],
                      command_path.world_direction(time[window] - t0))
    turned = abs(math.remainder(float(yaw[-1]) - command_path.heading(time[-1] - t0),
                                2.0 * math.pi))
    landed = steps[:, 0] > 0.0   # the two initial feet stand where the scenario puts them
    blocked = reader.attribute(run, "blocked", optional=True)
    return dict(
        label=label, kind=label.split("_")[0], shapes=shapes, scene=scene, command=command,
        allowed=allowed_time(scene),
        past=float(time[beyond[0]] - t0) if len(beyond) else math.nan,
        inside=bool(np.any(clearance[landed] < -foot_radius - 1e-9)),
        # As the walk's own check (libwpg's walk loop): a step centre inside the NMPC's bound.
        stepped_in=bool(np.any(clearance[landed] < -1e-6)), fell=fell,
        clearance=float(np.min(clearance[landed])) if np.any(landed) else math.nan,
        relaxed=relaxed,
        walks_on=float(np.mean(along)) >= WALK_ON_FRACTION * command_path.speed and
        turned < WALK_ON_HEADING,
        success=reader.attribute(run, "success") == 1,
        blocked_attribute=blocked is not None and blocked != 0,
        blocked_since=reader.attribute(run, "blocked_since", optional=True),
        com=com, steps=steps, sides=sides,
        foot_length=walking_number(scenario, "foot_length", DEFAULT_FOOT_LENGTH),
        foot_width=walking_number(scenario, "foot_width", DEFAULT_FOOT_WIDTH))


def classify(w):
    """Sets w["outcome"], w["why"] (what kept it from passing) and w["correct"]."""
    why = []
    if not w["success"] and (not w["blocked_attribute"] or w["fell"] or w["stepped_in"]):
        outcome = "failed"
    elif math.isnan(w["past"]):
        outcome = "blocked"
    else:
        for fault, reason in ((w["past"] > w["allowed"], "late"),
                              (w["inside"], "a step inside a margin"),
                              (w["relaxed"] > 0, "relaxed"),
                              (not w["walks_on"], "not walking on")):
            if fault:
                why.append(reason)
        outcome = "slow" if why else "passed"
    if w["blocked_attribute"]:
        why.append("blocked attribute" + (
            "" if w["blocked_since"] is None else " since %.1f s" % w["blocked_since"]))
    w["outcome"] = outcome
    w["why"] = ", ".join(why)
    w["correct"] = outcome == ("passed" if w["scene"]["passage"] else "blocked")
    return w


def read(path):
    walks, scenes = [], {}
    with open_file(path) as f:
        reader = Reader(path, f)
        table = reader.group(reader.group(f, "batch"), "summary")
        columns = reader.attribute(table, "columns", kind="texts")
        for name in ("name", "done"):
            if name not in columns:
                raise BadFile("%s: /batch/summary:columns: expected the column %s" % (path, name))
        done = reader.dataset(table, "done")
        names = reader.dataset(table, "name", kind="text", rows=len(done))
        runs = reader.group(f, "runs")
        for i in np.flatnonzero(done == 1):
            walks.append(classify(walk(path, reader, reader.group(runs, names[i]), scenes)))
    if not walks:
        raise BadFile("%s: /batch/summary: expected a finished run" % path)
    return walks


# --- the table and the figure --------------------------------------------------------------


def in_order(values):
    """The distinct values in their order of first appearance (the study's)."""
    return list(dict.fromkeys(values))


def kinds_of(walks):
    known = [k for k, _ in KINDS if any(w["kind"] == k for w in walks)]
    return known + in_order(w["kind"] for w in walks if w["kind"] not in known)


def count_line(walks):
    n = {o: sum(w["outcome"] == o for w in walks) for o in OUTCOMES}
    return ", ".join("%d %s" % (n[o], o) for o in OUTCOMES if n[o]) + \
        "; %d of %d correct" % (sum(w["correct"] for w in walks), len(walks))


def fmt(value, digits=1):
    """The number rounded to `digits`, never "-0.000"; "-" for none."""
    if value is None or math.isnan(value):
        return "-"
    return "%.*f" % (digits, round(value, digits) + 0.0)


def write_table(walks, path):
    lines = ["| scene | command [m/s, m/s, rad/s] | obstacles | passage | shortest path [m] "
             "| allowed [s] | outcome | time to pass [s] | least step clearance [m] "
             "| relaxed iterations | correct | why not passed |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for w in walks:
        lines.append("| %s | [%s] | %d | %s | %s | %s | %s | %s | %s | %d | %s | %s |" % (
            w["label"], ", ".join("%g" % v for v in w["command"]), len(w["shapes"]),
            "yes" if w["scene"]["passage"] else "no", fmt(w["scene"]["length"], 2),
            fmt(w["allowed"]), w["outcome"], fmt(w["past"]), fmt(w["clearance"], 3),
            w["relaxed"], "yes" if w["correct"] else "no", w["why"] or "-"))
    lines += ["", "| kind | walks | with a passage | passed | slow | blocked | failed | correct |",
              "|---|---|---|---|---|---|---|---|"]
    for kind in kinds_of(walks) + ["all"]:
        group = [w for w in walks if kind == "all" or w["kind"] == kind]
        lines.append("| %s | %d | %d | %s | %d |" % (
            kind, len(group), sum(w["scene"]["passage"] for w in group),
            " | ".join(str(sum(w["outcome"] == o for w in group)) for o in OUTCOMES),
            sum(w["correct"] for w in group)))
    lines += ["", "%d walks: %s." % (len(walks), count_line(walks))]
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def cell_of(w):
    """(row, column) of a walk in its kind's grid: its label without the kind, and the last
    word."""
    words = w["label"].split("_")
    if len(words) < 3:
        return "_".join(words[1:]) or w["label"], ""
    return "_".join(words[1:-1]), words[-1]


def representative(group):
    """The walk drawn for a kind: a scene with a passage if any, the longest detour (shortest
    free path over the commanded path), the most obstacles, the speed nearest 0.2 m/s; the
    first in the file on ties."""
    def detour(w):
        scene = w["scene"]
        return scene["length"] / scene["commanded"] if scene["passage"] else 0.0
    return min(group, key=lambda w: (not w["scene"]["passage"], -round(detour(w), 6),
                                     -len(w["shapes"]),
                                     round(abs(w["scene"]["path"].speed - 0.2), 6)))


def draw_scene(ax, w):
    scene = w["scene"]
    draw_obstacles(ax, w["shapes"])
    for polygon in scene["free"]:
        ax.add_patch(Polygon(polygon, closed=True, fill=False, edgecolor="0.55",
                             linestyle=":", linewidth=0.9))
    for (_landing, x, y, yaw), side in zip(w["steps"], w["sides"]):
        colour = LEFT_COLOUR if int(side) == 1 else RIGHT_COLOUR
        ax.add_patch(Polygon(sole_corners(x, y, yaw, w["foot_length"], w["foot_width"]),
                             closed=True, facecolor=colour, alpha=0.15, edgecolor=colour,
                             linewidth=0.5))
    commanded = np.array([scene["path"].point(s)
                          for s in np.linspace(0.0, scene["commanded"], 60)])
    ax.plot(commanded[:, 0], commanded[:, 1], color="tab:cyan", linewidth=1.0)
    shown = [np.zeros((1, 2)), commanded]
    if scene["route"] is not None:
        ax.plot(scene["route"][:, 0], scene["route"][:, 1], color="tab:purple", linewidth=1.3,
                linestyle="--")
        shown.append(scene["route"])
    ax.plot(w["com"][:, 0], w["com"][:, 1], color=COM_COLOUR, linewidth=1.2)
    # The scene round the commanded path and the free path, not the whole of long walls.
    shown = np.concatenate(shown)
    low, high = shown.min(axis=0) - 0.9, shown.max(axis=0) + 0.9
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_aspect("equal", adjustable="datalim")
    ax.tick_params(labelsize=7)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    ax.set_title("%s: %s%s" % (w["label"], w["outcome"], "" if math.isnan(w["past"]) else
                               ", past after %.1f s of %.1f allowed" % (w["past"], w["allowed"])),
                 fontsize=8)


def draw_grid(ax, group, cmap):
    rows = in_order(cell_of(w)[0] for w in group)
    columns = in_order(cell_of(w)[1] for w in group)
    ratio = np.full((len(rows), len(columns)), np.nan)
    for w in group:
        row, column = cell_of(w)
        y, x = rows.index(row), columns.index(column)
        if not math.isnan(w["past"]):
            ratio[y, x] = min(w["past"] / w["allowed"], RATIO_TOP)
        mark = OUTCOME_MARK[w["outcome"]] + ("!" if w["inside"] else "")
        if mark:
            ax.text(x, y, mark, ha="center", va="center", fontsize=6)
        if not w["scene"]["passage"]:
            ax.add_patch(Rectangle((x - 0.5, y - 0.5), 1.0, 1.0, fill=False, edgecolor="black",
                                   linewidth=1.2))
    image = ax.imshow(ratio, cmap=cmap, vmin=0.0, vmax=RATIO_TOP, aspect="auto",
                      interpolation="nearest")
    ax.set_facecolor("0.55")
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels(rows, fontsize=6)
    ax.set_xticks(range(len(columns)))
    ax.set_xticklabels(columns, fontsize=6)
    ax.xaxis.tick_top()
    ax.set_title("%d walks: %s" % (len(group), count_line(group)), fontsize=7, pad=14)
    return image


def draw(walks, output, source):
    kinds = kinds_of(walks)
    heights = [max(2.6, 0.14 * len(in_order(cell_of(w)[0] for w in walks if w["kind"] == k))
                   + 1.0) for k in kinds]
    height = sum(heights) + 2.0   # in; the title and the legend above the panels
    fig = plt.figure(figsize=(12.0, height))
    grid = fig.add_gridspec(len(kinds), 2, height_ratios=heights, width_ratios=(2.3, 1.0),
                            hspace=0.42, wspace=0.22, top=1.0 - 1.5 / height,
                            bottom=0.5 / height, left=0.05, right=0.93)
    cmap = plt.get_cmap("RdYlGn_r")
    image = None
    for index, kind in enumerate(kinds):
        group = [w for w in walks if w["kind"] == kind]
        sketch = fig.add_subplot(grid[index, 0])
        draw_scene(sketch, representative(group))
        sketch.text(-0.06, 1.12, dict(KINDS).get(kind, kind), transform=sketch.transAxes,
                    fontsize=10, fontweight="bold", ha="left")
        image = draw_grid(fig.add_subplot(grid[index, 1]), group, cmap)
    bar = fig.colorbar(image, ax=fig.axes, shrink=0.25, pad=0.02, fraction=0.02,
                       anchor=(0.0, 1.0))
    bar.set_label("time to pass / time allowed (grey: never past)", fontsize=8)
    handles = [Line2D([], [], color=COM_COLOUR, linewidth=1.2, label="CoM"),
               Line2D([], [], color="tab:cyan", linewidth=1.0, label="commanded path"),
               Line2D([], [], color="tab:purple", linestyle="--", linewidth=1.3,
                      label="shortest free path"),
               Line2D([], [], color="0.55", linestyle=":",
                      label="room the CoM needs (margin + foot + half the step width)"),
               Line2D([], [], color="0.35", linestyle="--", label="margin")]
    fig.legend(handles=handles, loc="upper left", ncol=5, fontsize=8,
               bbox_to_anchor=(0.04, 1.0 - 0.65 / height))
    fig.text(0.04, 1.0 - 0.12 / height,
             "%s: %d walks, %s.\nTop views: one walk per kind of scene (left foot blue, right "
             "red). Grids: every walk; s past late, relaxed or not walking on, B blocked,\n"
             "F failed, ! a step centre inside a margin; framed: a scene without a passage (the "
             "robot should stop: B)."
             % (source, len(walks), count_line(walks)), fontsize=9, va="top")
    save_figure(fig, output, dpi=80, metadata=png_metadata(source))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("batch_file")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--table", help="also write the table of every walk (Markdown)")
    args = parser.parse_args()
    walks = read(args.batch_file)
    draw(walks, args.output, os.path.basename(args.batch_file))
    if args.table:
        write_table(walks, args.table)
    for kind in kinds_of(walks):
        group = [w for w in walks if w["kind"] == kind]
        print("%-9s %3d walks: %s" % (kind, len(group), count_line(group)))
    print("%d walks: %s" % (len(walks), count_line(walks)))
    return 0


if __name__ == "__main__":
    run_script(SCRIPT, main)
