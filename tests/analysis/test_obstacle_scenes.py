#!/usr/bin/python3
"""test_obstacle_scenes.py: the geometry and the rules of analysis/plot_obstacle_scenes.py, and
the study it reads (datasets/studies/obstacle_scenes.yaml). Debian's python3 with numpy,
matplotlib and PyYAML (what the plot scripts need); unittest, exit 0 when every test passes.

- round a circle of radius r from (-a, 0) to (a, 0) the shortest path has the analytic length
  2 sqrt(a^2 - r^2) + r (pi - 2 acos(r / a)): the visibility graph's is never shorter, and at
  most the circumscribed polygon's excess, 1 / cos(pi / 64) - 1, longer;
- a doorway 1 mm narrower than 2 (margin + obstacle_foot_radius) + the minimal step width has
  no passage, 1 mm wider has one, straight or turned; the minimal step width of HRP-2 facing its
  command is 0.2 m, its feasibility polygon's nearest vertex across;
- a wall across the path within the region a command leads through (BAND either side) has a
  way round, one beyond it has none; a U round the start has none;
- the outcome rules: a failed walk is "failed" unless a `blocked` attribute says it was stopped
  and it neither fell nor landed a step inside the NMPC's bound;
- the study: every entry's duration holds the time allowed to pass and the walking on, its
  scenes have a passage but for the closed ones and the doorways narrower than needed.
"""
import math
import os
import sys
import unittest

import yaml

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "analysis"))
import plot_obstacle_scenes as scenes  # noqa: E402
from run_figure.geometry import sole_corners  # noqa: E402
from run_figure.scenario_text import scenario_obstacles  # noqa: E402

STUDY = os.path.join(SOURCE, "datasets", "studies", "obstacle_scenes.yaml")
MARGIN = 0.2  # [m], every obstacle of the study


def circle(x, y, radius, margin=MARGIN):
    return ([], margin, ("circle", x, y, radius), True)


def box(x, y, length, width, yaw=0.0, margin=MARGIN):
    return (sole_corners(x, y, yaw, length, width), margin, None, True)


def doorway(width, depth=1.0, yaw=0.0, x=2.5):
    """Two walls `depth` deep and 3 m long across the path, `width` apart, turned by `yaw`
    about the doorway's centre (x, 0)."""
    c, s = math.cos(yaw), math.sin(yaw)
    walls = []
    for side in (1.0, -1.0):
        offset = side * (0.5 * width + 1.5)
        walls.append(box(x - s * offset, c * offset, depth, 3.0, yaw))
    return walls


class ShortestPath(unittest.TestCase):
    def test_round_a_circle_has_the_analytic_length(self):
        excess = 1.0 / math.cos(math.pi / scenes.ARC_SEGMENTS) - 1.0
        for a in (1.0, 3.5):
            for ratio in (0.1, 0.5, 0.9, 0.99):
                r = ratio * a
                exact = 2.0 * math.sqrt(a * a - r * r) + r * (math.pi - 2.0 * math.acos(r / a))
                polygon = scenes.grown_polygon(circle(0.0, 0.0, r, margin=0.0), 0.0)
                length, route = scenes.shortest_path((-a, 0.0), (a, 0.0), [polygon])
                with self.subTest(a=a, r=r):
                    self.assertIsNotNone(route)
                    self.assertGreaterEqual(length, exact - 1e-12)
                    self.assertLessEqual(length, exact * (1.0 + excess))

    def test_the_grown_box_is_exact_along_its_edges(self):
        # A box 1 x 0.5 m grown by 0.2 m reaches 0.7 m and 0.45 m from its centre, no further.
        polygon = scenes.grown_polygon(box(0.0, 0.0, 1.0, 0.5, margin=0.0), 0.2)
        self.assertAlmostEqual(polygon[:, 0].max(), 0.7, places=12)
        self.assertAlmostEqual(polygon[:, 1].max(), 0.45, places=12)

    def test_a_straight_path_past_nothing_in_the_way(self):
        scene = scenes.analyse_scene([circle(2.0, 1.5, 0.15)], (0.2, 0.0, 0.0))
        self.assertTrue(scene["passage"])
        self.assertAlmostEqual(scene["length"], scene["commanded"], places=9)


class Passage(unittest.TestCase):
    def test_the_minimal_step_width_of_hrp2(self):
        self.assertEqual(scenes.MIN_STEP_WIDTH, 0.2)

    def test_a_doorway_below_the_minimal_width_has_no_passage(self):
        needed = 2.0 * (MARGIN + scenes.DEFAULT_FOOT_RADIUS) + scenes.MIN_STEP_WIDTH
        for yaw in (0.0, 0.3):
            for command in ((0.2, 0.0, 0.0), (0.1, 0.0, 0.0)):
                with self.subTest(yaw=yaw, command=command):
                    below = scenes.analyse_scene(doorway(needed - 0.001, yaw=yaw), command)
                    above = scenes.analyse_scene(doorway(needed + 0.001, yaw=yaw), command)
                    self.assertFalse(below["passage"])
                    self.assertTrue(math.isnan(below["length"]))
                    self.assertTrue(above["passage"])
                    self.assertGreater(above["length"], above["commanded"] - 1e-9)

    def test_a_wall_across_the_path_leaves_a_way_round_within_the_band_only(self):
        # Grown by 0.2 + 0.1287 + 0.2 / 2 = 0.4287 m, a wall 4.1 m long across the path
        # ends 2.4787 m either side of it (within BAND = 2.5 m), one 4.2 m long 2.5287 m.
        short = scenes.analyse_scene([box(2.0, 0.0, 0.3, 4.1)], (0.2, 0.0, 0.0))
        long = scenes.analyse_scene([box(2.0, 0.0, 0.3, 4.2)], (0.2, 0.0, 0.0))
        self.assertTrue(short["passage"])
        self.assertFalse(long["passage"])

    def test_a_u_round_the_start_has_no_passage(self):
        enclosure = [box(3.0, 0.0, 0.3, 1.9), box(1.0, 0.8, 4.0, 0.3), box(1.0, -0.8, 4.0, 0.3)]
        self.assertFalse(scenes.analyse_scene(enclosure, (0.2, 0.0, 0.0))["passage"])
        # Its arms from 0.8 m ahead of the start instead of 1 m behind: a way out sideways.
        shorter = [box(3.0, 0.0, 0.3, 1.9), box(1.9, 0.8, 2.2, 0.3), box(1.9, -0.8, 2.2, 0.3)]
        self.assertTrue(scenes.analyse_scene(shorter, (0.2, 0.0, 0.0))["passage"])

    def test_progress_along_a_turning_command(self):
        # [0.2, 0, 0.1]: a circle of 2 m about (0, 2); a quarter turn is pi m along it.
        path = scenes.CommandPath((0.2, 0.0, 0.1))
        self.assertAlmostEqual(float(path.progress((2.0, 2.0))[0]), math.pi, places=12)
        self.assertAlmostEqual(float(path.progress((0.0, 0.0))[0]), 0.0, places=12)
        point = path.point(math.pi)
        self.assertAlmostEqual(point[0], 2.0, places=12)
        self.assertAlmostEqual(point[1], 2.0, places=12)


class Outcomes(unittest.TestCase):
    def walk(self, **fields):
        w = dict(success=True, blocked_attribute=False, blocked_since=None, past=20.0,
                 allowed=30.0, inside=False, stepped_in=False, fell=False, relaxed=0,
                 walks_on=True, scene=dict(passage=True))
        w.update(fields)
        return scenes.classify(w)

    def test_the_rules(self):
        self.assertEqual(self.walk()["outcome"], "passed")
        self.assertTrue(self.walk()["correct"])
        self.assertEqual(self.walk(past=31.0)["why"], "late")
        self.assertEqual(self.walk(relaxed=1)["outcome"], "slow")
        self.assertEqual(self.walk(walks_on=False)["outcome"], "slow")
        self.assertEqual(self.walk(past=math.nan)["outcome"], "blocked")
        self.assertEqual(self.walk(success=False)["outcome"], "failed")
        blocked = self.walk(past=math.nan, scene=dict(passage=False))
        self.assertEqual(blocked["outcome"], "blocked")
        self.assertTrue(blocked["correct"])
        self.assertFalse(self.walk(scene=dict(passage=False))["correct"])

    def test_a_blocked_attribute_is_not_a_failure(self):
        w = self.walk(success=False, blocked_attribute=True, blocked_since=12.5, past=math.nan,
                      scene=dict(passage=False))
        self.assertEqual(w["outcome"], "blocked")
        self.assertTrue(w["correct"])
        self.assertIn("since 12.5 s", w["why"])
        # ... but a fall, or a step landed inside the NMPC's bound, is.
        for fault in ("fell", "stepped_in"):
            self.assertEqual(self.walk(success=False, blocked_attribute=True, past=math.nan,
                                       **{fault: True})["outcome"], "failed")


class Study(unittest.TestCase):
    def test_every_entry(self):
        with open(STUDY) as f:
            study = yaml.safe_load(f)
        entries = study["sweep"]["zip"]
        names = entries["name"]
        self.assertEqual(len(set(names)), len(names))
        for key in ("reference[1].v", "duration", "obstacles"):
            self.assertEqual(len(entries[key]), len(names), key)
        t0 = study["base"]["reference"][1]["t"]
        needed = 2.0 * (MARGIN + scenes.DEFAULT_FOOT_RADIUS) + scenes.MIN_STEP_WIDTH
        cache = {}
        for name, command, duration, obstacles in zip(
                names, entries["reference[1].v"], entries["duration"], entries["obstacles"]):
            key = (repr(obstacles), tuple(command))
            if key not in cache:
                cache[key] = scenes.analyse_scene(
                    scenario_obstacles({"obstacles": obstacles}), command)
            scene = cache[key]
            kind = name.split("_")[0]
            with self.subTest(name=name):
                self.assertIn(kind, dict(scenes.KINDS))
                self.assertTrue(all(o["margin"] == MARGIN for o in obstacles))
                self.assertGreaterEqual(
                    duration, t0 + scenes.allowed_time(scene) + scenes.WALK_ON_WINDOW)
                self.assertLess(duration, t0 + scenes.allowed_time(scene) +
                                scenes.WALK_ON_WINDOW + 1.0)
                if kind == "closed":
                    self.assertFalse(scene["passage"])
                elif kind == "gap":
                    width = float(name.split("_")[1][1:])
                    self.assertEqual(scene["passage"], width >= needed)
                else:
                    self.assertTrue(scene["passage"])


if __name__ == "__main__":
    unittest.main()
