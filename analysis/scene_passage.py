"""scene_passage.py: is there a passage through a scene of obstacles for a robot that follows a
constant velocity command, and how long is the shortest one (plot_obstacle_scenes.py, which
classifies the walks of docs/obstacle_scenes.md by it; tests/analysis/test_obstacle_scenes.py).

Is there a passage? In the plane of the CoM: a step centre keeps margin + obstacle_foot_radius
from each obstacle (the NMPC's bound; the radius from the stored walking map, else HRP-2's
0.1287 m), and two consecutive feet stand at least the minimal step width apart across the
command (least_step_width: 0.2 m for HRP-2), so the CoM between them needs margin +
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
"""
import math

import numpy as np

# HRP-2's step feasibility polygon (eq. 14: a left step in the right support foot's frame; its
# inner edge, y = 0.2 m from x = -0.28 to 0.28 m, is how close beside the support foot a step
# lands) and yaw bound (eq. 16), robots/hrp2/walking.yaml, for a stored scenario without them.
HRP2_FEASIBILITY = ((-0.28, 0.2), (-0.2, 0.3), (0.0, 0.4), (0.2, 0.3), (0.28, 0.2))  # [m]
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
# Points this close to a polygon's boundary are not inside it (coordinates of a few metres).
EPS = 1e-7  # [m]


def least_step_width(feasibility):
    """The least distance across its heading between two consecutive feet of the walk the
    generator plans: its feet face the command's heading (J2 keeps them along it), so a step
    lands at least the feasibility polygon's nearest vertex across (eq. 14), min |y|: 0.2 m for
    HRP-2, its minimal step width, and a doorway needs 0.2 + 2 (margin 0.2 + 0.1287) = 0.857 m
    (libwpg's WalkingParameters::leastStepWidth is the same bound). Feet toed in and out in turn
    by half the yaw bound (eq. 16) could come 0.2 cos(0.085) - 0.28 sin(0.085) = 0.1755 m close
    (a doorway of 0.833 m), a gait the NMPC does not plan (docs/obstacle_scenes.md). Turned
    sideways, a robot would need no width at all: the command's heading rules that out."""
    return min(abs(y) for _, y in feasibility)


# The minimal step width: the least distance across the command between two consecutive feet of
# HRP-2 facing its command, 0.2 m.
MIN_STEP_WIDTH = least_step_width(HRP2_FEASIBILITY)  # [m]


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
        # A segment whose two ends are outside the same edge's half-plane (of the polygon shrunk
        # by EPS) cannot cross the polygon (_segments_cross says the same of it): for a pair of
        # nodes that is one AND of their packed "outside" bits, where the clipping computes every
        # edge. Most pairs are such (two corners beside the same edge, or on the same side).
        normals, offsets = plane
        outside = np.packbits(offsets[None, :] - EPS - nodes @ normals.T <= 0.0, axis=1)
        open_pairs = np.flatnonzero(visible)
        apart = np.any(outside[first[open_pairs]] & outside[second[open_pairs]], axis=1)
        candidates = open_pairs[~apart]
        # In blocks of pairs: the clipping's arrays are (pairs x edges) numbers, and arrays of a
        # few MB cost more in page faults than in arithmetic (10 times on the 2-core CI machine);
        # blocks of 64 kB are reused from the heap.
        block = max(1, 8192 // max(len(offsets), 1))
        for start in range(0, len(candidates), block):
            pairs = candidates[start:start + block]
            visible[pairs] = ~_segments_cross(nodes[first[pairs]], nodes[second[pairs]], plane)
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
