"""The kinematic reach of a steady two-step gait (docs/command_tracking.md, "Which commands a
robot can walk"): for a robot-frame command (vx, vy, omega), the largest factor lambda such that
lambda (vx, vy) at omega can be walked by a periodic gait whose steps all land inside the step
feasibility polygon (paper eq. 14, Fig. 5) and turn by omega T_step each.

A stride is a left step p1 in the right foot's frame (yaw 0) and a right step p2 in the left
foot's frame (yaw delta = omega T_step); the stride moves the robot's frame (the point between
the feet at a landing, yaw halfway between them) by tau = R(delta/2) ((R(2 delta) - I) m + p1 +
R(delta) p2), m = -R(-delta) p2 / 2, and turns it by 2 delta. A constant twist (v, omega) over
the stride's 2 T_step gives the same motion when v = R(-delta) tau / (2 T_step sinc(delta)): v is
linear in (p1, p2), and lambda the largest factor for which v = lambda (vx, vy) with p1, p2 in
their polygons. `regular=True` also asks both steps to reach equally far forward in their
frames (p1.x = p2.x): no limping. The reach is a bound of the kinematics only (no dynamics, the
CoP or the cost); anchored at the left or the right step it differs by a few % when turning
(the frame's origin), and the larger of the two is returned (the reach a command must not be
excused beyond).
"""
import math

import numpy as np


def _rotation(angle):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])


def _half_planes(vertices):
    """A x <= b of a convex polygon given in either orientation."""
    v = np.asarray(vertices, dtype=float)
    area = np.sum(v[:, 0] * np.roll(v[:, 1], -1) - np.roll(v[:, 0], -1) * v[:, 1])
    if area < 0:
        v = v[::-1]
    rows, rhs = [], []
    for a, b in zip(v, np.roll(v, -1, axis=0)):
        edge = b - a
        outward = np.array([edge[1], -edge[0]])
        rows.append(outward)
        rhs.append(outward @ a)
    return np.array(rows), np.array(rhs)


def _feasible_2d(rows, rhs):
    """Whether {x : rows x <= rhs} (a bounded set in 2-D) is not empty: clip a large box."""
    polygon = [np.array(p) for p in ((-10.0, -10.0), (10.0, -10.0), (10.0, 10.0), (-10.0, 10.0))]
    for a, b in zip(rows, rhs):
        clipped = []
        for i, p in enumerate(polygon):
            q = polygon[(i + 1) % len(polygon)]
            fp, fq = a @ p - b, a @ q - b
            if fp <= 1e-12:
                clipped.append(p)
            if (fp < -1e-12 and fq > 1e-12) or (fp > 1e-12 and fq < -1e-12):
                clipped.append(p + (q - p) * fp / (fp - fq))
        polygon = clipped
        if not polygon:
            return False
    return True


def _feasible_line(rows, rhs, point, direction):
    """Whether {point + s direction} meets {x : rows x <= rhs}."""
    low, high = -math.inf, math.inf
    for a, b in zip(rows, rhs):
        slope, room = a @ direction, b - a @ point
        if abs(slope) < 1e-15:
            if room < -1e-12:
                return False
        elif slope > 0:
            high = min(high, room / slope)
        else:
            low = max(low, room / slope)
    return low <= high + 1e-12


def _reach(velocity, omega, step_duration, left, right, regular, left_first):
    delta = omega * step_duration
    rot = _rotation
    m = -0.5 * rot(-delta)  # m = M p2
    a1 = rot(delta / 2)
    a2 = rot(delta / 2) @ ((rot(2 * delta) - np.eye(2)) @ m + rot(delta))
    sinc = math.sin(delta) / delta if abs(delta) > 1e-12 else 1.0
    k = rot(-delta) / (2 * step_duration * sinc)
    v1, v2 = k @ a1, k @ a2
    first, second = (left, right) if left_first else (right, left)
    rows1, rhs1 = _half_planes(first)
    rows2, rhs2 = _half_planes(second)
    v2_inverse = np.linalg.inv(v2)
    target = np.asarray(velocity, dtype=float)

    def feasible(scale):
        # p2 = V2^-1 (scale v - V1 p1) inside the second polygon: a condition on p1
        rows = np.vstack([rows1, -rows2 @ v2_inverse @ v1])
        rhs = np.concatenate([rhs1, rhs2 - scale * rows2 @ v2_inverse @ target])
        if not regular:
            return _feasible_2d(rows, rhs)
        # p1.x = p2.x: (e1 + (V2^-1 V1)^T e1) . p1 = scale (V2^-1 v).x
        normal = np.array([1.0, 0.0]) + (v2_inverse @ v1)[0]
        value = scale * (v2_inverse @ target)[0]
        if np.linalg.norm(normal) < 1e-15:
            return abs(value) < 1e-12 and _feasible_2d(rows, rhs)
        point = normal * value / (normal @ normal)
        return _feasible_line(rows, rhs, point, np.array([-normal[1], normal[0]]))

    if not feasible(0.0):
        return 0.0
    low, high = 0.0, 1.0
    while feasible(high) and high < 64.0:
        low, high = high, 2.0 * high
    for _ in range(60):
        middle = 0.5 * (low + high)
        low, high = (middle, high) if feasible(middle) else (low, middle)
    return low


def gait_reach(velocity, omega, step_duration, feasibility_x, feasibility_y, regular=False):
    """lambda for the robot-frame (vx, vy) = velocity at omega [rad/s] (inf for a zero
    velocity); the feasibility polygon of a left step in the right foot's frame, a right step
    its mirror image."""
    if abs(velocity[0]) < 1e-12 and abs(velocity[1]) < 1e-12:
        return math.inf
    left = list(zip(feasibility_x, feasibility_y))
    right = [(x, -y) for x, y in left]
    return max(_reach(velocity, omega, step_duration, left, right, regular, first)
               for first in (True, False))
