"""Plane geometry of the top views: sole rectangles, outlines grown by a margin, convex hulls
(also used by plot_compare.py)."""
import math

import numpy as np


def sole_corners(x, y, yaw, length, width):
    c, s = math.cos(yaw), math.sin(yaw)
    corners = []
    for dx, dy in ((0.5, 0.5), (-0.5, 0.5), (-0.5, -0.5), (0.5, -0.5)):
        px, py = dx * length, dy * width
        corners.append((x + c * px - s * py, y + s * px + c * py))
    return corners


def grown_outline(outline, margin, circle):
    """The outline grown by `margin` (Minkowski sum with a disc), as a polygon."""
    if circle is not None:
        _, cx, cy, radius = circle
        return [(cx + (radius + margin) * math.cos(a), cy + (radius + margin) * math.sin(a))
                for a in np.linspace(0.0, 2.0 * math.pi, 64, endpoint=False)]
    points = []
    for x, y in outline:
        for a in np.linspace(0.0, 2.0 * math.pi, 24, endpoint=False):
            points.append((x + margin * math.cos(a), y + margin * math.sin(a)))
    return convex_hull(points)


def convex_hull(points):
    points = sorted(set(points))
    if len(points) < 3:
        return points

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in points:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(points):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]
