// The FCL world: signed distances agree with libwpg's exact 2-D AnalyticObstacleDistance inside
// and outside every kind of obstacle, gradients agree with central differences, foot
// clearances match hand-computed configurations and an independent brute force, the
// configurations where FCL 0.7's EPA hangs are answered, and the after-run footstep checks.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "wpg/obstacles.hpp"
#include "wpg/planning/obstacle_checks.hpp"
#include "wpg/planning/world.hpp"

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using wpg::Obstacle;
using wpg::ObstacleType;
using wpg::planning::World;

constexpr double kSoleLength = 0.2172;  // HRP-2 (robots/hrp2/README.md)
constexpr double kSoleWidth = 0.138;

Obstacle circle(Vector2d center, double radius, double margin = 0.0) {
  Obstacle o;
  o.type = ObstacleType::kCircle;
  o.center = center;
  o.radius = radius;
  o.margin = margin;
  return o;
}

Obstacle box(Vector2d center, Vector2d size, double yaw, double margin = 0.0) {
  Obstacle o;
  o.type = ObstacleType::kBox;
  o.center = center;
  o.size = size;
  o.yaw = yaw;
  o.margin = margin;
  return o;
}

Obstacle polygon(std::vector<Vector2d> vertices, double margin = 0.0) {
  Obstacle o;
  o.type = ObstacleType::kPolygon;
  o.vertices = std::move(vertices);
  o.margin = margin;
  return o;
}

// Circles, axis-aligned and turned boxes, polygons in both orientations, a large box (deeper
// inside than the prism's default half height of 1 m), away from the origin.
std::vector<Obstacle> mixedObstacles() {
  std::vector<Vector2d> pentagon;
  for (int k = 0; k < 5; ++k) {
    const double a = 0.3 + 2.0 * M_PI * k / 5.0;
    pentagon.emplace_back(-2.0 + 0.5 * std::cos(a), 1.5 + 0.4 * std::sin(a));
  }
  return {circle({1.5, 0.0}, 0.3, 0.2),
          circle({-1.0, -2.0}, 0.05, 0.0),
          box({3.0, 1.0}, {0.4, 0.6}, 0.3, 0.1),
          box({0.0, 3.0}, {1.0, 0.2}, 0.0, 0.0),
          box({-6.0, 6.0}, {7.0, 6.0}, -0.7, 0.0),
          polygon({{4.0, -0.5}, {4.6, -0.4}, {4.3, 0.2}}, 0.1),
          polygon({{4.3, 0.2}, {4.6, -0.4}, {4.0, -0.5}}, 0.1),  // clockwise
          polygon(pentagon, 0.05)};
}

// Random points around an obstacle: about half inside, half outside (up to ~1 m away).
std::vector<Vector2d> pointsAround(const Obstacle& obstacle, std::mt19937* rng, int count) {
  Vector2d center;
  double radius = 0.0;
  wpg::boundingCircle(obstacle, &center, &radius);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vector2d> points;
  for (int k = 0; k < count; ++k) {
    const double reach = k % 2 ? radius : radius + 1.0;
    points.emplace_back(center.x() + reach * unit(*rng), center.y() + reach * unit(*rng));
  }
  return points;
}

TEST(World, SignedDistanceMatchesTheExact2DDistanceInsideAndOutside) {
  const std::vector<Obstacle> obstacles = mixedObstacles();
  const World world(obstacles);
  const wpg::AnalyticObstacleDistance exact(obstacles);
  ASSERT_EQ(world.obstacleCount(), static_cast<int>(obstacles.size()));
  std::mt19937 rng(7);
  for (int i = 0; i < world.obstacleCount(); ++i) {
    SCOPED_TRACE("obstacle " + std::to_string(i) + " (" + wpg::obstacleTypeName(obstacles[i].type) +
                 ")");
    int inside = 0, outside = 0;
    double worst = 0.0, worst_gradient = 0.0;
    for (const Vector2d& p : pointsAround(obstacles[i], &rng, 2000)) {
      Vector2d gradient, expected_gradient;
      const double d = world.signedDistance(i, p, &gradient);
      const double e = exact.signedDistance(i, p, &expected_gradient);
      ASSERT_TRUE(std::isfinite(d)) << p.transpose();
      worst = std::max(worst, std::abs(d - e));
      EXPECT_NEAR(d, e, 1e-6) << "at " << p.transpose();
      EXPECT_NEAR(gradient.norm(), 1.0, 1e-9);
      // The gradient is unique off the medial axis (inside, where two edges are nearly as close
      // it may pick either).
      if (e > 1e-6) {
        worst_gradient = std::max(worst_gradient, (gradient - expected_gradient).norm());
        EXPECT_LT((gradient - expected_gradient).norm(), 1e-6) << "at " << p.transpose();
      }
      (e < 0.0 ? inside : outside)++;
    }
    EXPECT_GT(inside, 200);
    EXPECT_GT(outside, 200);
    RecordProperty("worst_distance_error_" + std::to_string(i), std::to_string(worst));
    RecordProperty("worst_gradient_error_" + std::to_string(i), std::to_string(worst_gradient));
  }
}

TEST(World, GradientMatchesCentralDifferencesAwayFromTheMedialAxis) {
  const std::vector<Obstacle> obstacles = mixedObstacles();
  const World world(obstacles);
  const wpg::AnalyticObstacleDistance exact(obstacles);
  const double h = 1e-5;
  std::mt19937 rng(11);
  for (int i = 0; i < world.obstacleCount(); ++i) {
    SCOPED_TRACE("obstacle " + std::to_string(i));
    int checked = 0;
    for (const Vector2d& p : pointsAround(obstacles[i], &rng, 1000)) {
      Vector2d gradient;
      world.signedDistance(i, p, &gradient);
      // Off the medial axis (inside) and not within ~1 mm of a corner (outside): where central
      // differences of the exact distance itself reproduce its gradient (no kink, little
      // curvature within the step).
      Vector2d fd, fd_exact, exact_gradient;
      exact.signedDistance(i, p, &exact_gradient);
      for (int j = 0; j < 2; ++j) {
        const Vector2d step = h * Vector2d::Unit(j);
        fd[j] = (world.signedDistance(i, p + step, nullptr) -
                 world.signedDistance(i, p - step, nullptr)) /
                (2.0 * h);
        fd_exact[j] = (exact.signedDistance(i, p + step, nullptr) -
                       exact.signedDistance(i, p - step, nullptr)) /
                      (2.0 * h);
      }
      const bool smooth = (fd_exact - exact_gradient).norm() < 1e-7;
      if (!smooth) continue;
      ++checked;
      EXPECT_LT((fd - gradient).norm(), 1e-6)
          << "at " << p.transpose() << ": " << fd.transpose() << " vs " << gradient.transpose();
    }
    EXPECT_GT(checked, 800);
  }
}

TEST(World, SignConventionAndKnownValues) {
  const World world({circle({0.0, 0.0}, 0.5), box({3.0, 0.0}, {1.0, 2.0}, 0.0),
                     box({0.0, -3.0}, {1.0, 1.0}, M_PI / 4.0)});
  Vector2d g;
  EXPECT_NEAR(world.signedDistance(0, {2.0, 0.0}, &g), 1.5, 1e-9);
  EXPECT_NEAR((g - Vector2d(1.0, 0.0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(world.signedDistance(0, {0.0, -0.3}, &g), -0.2, 1e-12);  // inside: negative
  EXPECT_NEAR((g - Vector2d(0.0, -1.0)).norm(), 0.0, 1e-12);           // still away from it
  EXPECT_NEAR(world.signedDistance(1, {2.0, 0.5}, &g), 0.5, 1e-9);     // left face
  EXPECT_NEAR((g - Vector2d(-1.0, 0.0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(world.signedDistance(1, {4.5, 2.0}, &g), std::hypot(1.0, 1.0), 1e-9);  // corner
  EXPECT_NEAR((g - Vector2d(1.0, 1.0).normalized()).norm(), 0.0, 1e-9);
  EXPECT_NEAR(world.signedDistance(1, {3.1, 0.2}, &g), -0.4, 1e-12);  // nearest: right face
  EXPECT_NEAR((g - Vector2d(1.0, 0.0)).norm(), 0.0, 1e-12);
  // The turned box: a diamond with corners at distance sqrt(0.5) from its centre.
  EXPECT_NEAR(world.signedDistance(2, {0.0, -2.0}, &g), 1.0 - std::sqrt(0.5), 1e-9);
  EXPECT_NEAR((g - Vector2d(0.0, 1.0)).norm(), 0.0, 1e-9);
}

// FCL 0.7's EPA (its signed distance when shapes overlap) never returns for a point on or near
// a cylinder's axis, or for a small sphere at a box corner; the world must not go there.
TEST(World, ConfigurationsWhereFclEpaHangsAreAnswered) {
  const World world({circle({1.0, 2.0}, 0.3), box({0.0, 0.0}, {0.6, 0.6}, 0.0),
                     polygon({{-0.3, -0.3}, {0.3, -0.3}, {0.3, 0.3}, {-0.3, 0.3}})});
  Vector2d g;
  for (const Vector2d offset : {Vector2d(0.0, 0.0), Vector2d(1e-9, 0.0), Vector2d(0.0, 1e-7),
                                Vector2d(1e-6, 0.0), Vector2d(1e-3, 0.0)}) {
    EXPECT_NEAR(world.signedDistance(0, Vector2d(1.0, 2.0) + offset, &g), offset.norm() - 0.3,
                1e-12);
  }
  for (const int i : {1, 2}) {
    EXPECT_NEAR(world.signedDistance(i, {0.3, 0.3}, &g), 0.0, 1e-12);        // corner
    EXPECT_NEAR(world.signedDistance(i, {0.0, 0.0}, &g), -0.3, 1e-12);       // centre
    EXPECT_NEAR(world.signedDistance(i, {0.3, 0.0}, &g), 0.0, 1e-12);        // on an edge
    EXPECT_NEAR(world.signedDistance(i, {0.3005, 0.0}, &g), 0.0005, 1e-12);  // touches the probe
  }
}

TEST(World, DeepInsideALargeObstacleIsNotTheVerticalWayOut) {
  const World world({box({0.0, 0.0}, {10.0, 8.0}, 0.2), circle({20.0, 0.0}, 5.0)});
  EXPECT_NEAR(world.signedDistance(0, {0.0, 0.0}, nullptr), -4.0, 1e-12);
  EXPECT_NEAR(world.signedDistance(1, {20.5, 0.0}, nullptr), -4.5, 1e-12);
  // The sole (yaw 0) inside the box (yaw 0.2): out along the box's y axis.
  EXPECT_NEAR(world.footClearance({0.0, 0.0, 0.0}, kSoleLength, kSoleWidth, 0),
              -(4.0 + 0.5 * kSoleLength * std::sin(0.2) + 0.5 * kSoleWidth * std::cos(0.2)), 1e-9);
}

TEST(World, FootClearanceOfKnownConfigurations) {
  const World world({box({2.0, 0.0}, {1.0, 1.0}, 0.0, 0.1),                     // 0
                     circle({0.0, 1.0}, 0.3, 0.05),                             // 1
                     circle({1.0, 1.0}, 0.2, 0.0),                              // 2
                     box({0.0, 0.0}, {1.0, 1.0}, 0.0, 0.1),                     // 3
                     circle({0.2, 0.0}, 0.15, 0.0),                             // 4
                     polygon({{0.5, -1.0}, {1.0, -1.0}, {0.5, -0.5}}, 0.02)});  // 5
  const double hx = 0.5 * kSoleLength, hy = 0.5 * kSoleWidth;
  auto clearance = [&](Vector3d pose, int i) {
    return world.footClearance(pose, kSoleLength, kSoleWidth, i);
  };
  // Separated, face to face: front edge x = 1 + hx, box from x = 1.5.
  EXPECT_NEAR(clearance({1.0, 0.0, 0.0}, 0), 1.5 - (1.0 + hx) - 0.1, 1e-9);
  // Side of the foot towards a circle; turned by 90 degrees the long side faces it.
  EXPECT_NEAR(clearance({0.0, 0.0, 0.0}, 1), 0.7 - hy - 0.05, 1e-7);
  EXPECT_NEAR(clearance({0.0, 0.0, M_PI / 2.0}, 1), 0.7 - hx - 0.05, 1e-7);
  // A corner of the sole is nearest.
  EXPECT_NEAR(clearance({0.0, 0.0, 0.0}, 2), (Vector2d(1.0, 1.0) - Vector2d(hx, hy)).norm() - 0.2,
              1e-7);
  // Overlapping: minus the penetration depth, minus the margin.
  EXPECT_NEAR(clearance({0.0, 0.0, 0.0}, 3), -(0.5 + hy) - 0.1, 1e-12);
  EXPECT_NEAR(clearance({0.5, 0.0, 0.0}, 3), -hx - 0.1, 1e-12);  // half the sole inside
  EXPECT_NEAR(clearance({0.0, 0.0, 0.0}, 4), -(0.15 - (0.2 - hx)), 1e-12);
  // The triangle's corner (0.5, -0.5) is nearest to the sole's corner (hx, -hy) of a foot at
  // (0.3, -0.3) (the hypotenuse x + y = 0 and the edge x = 0.5 end there).
  const Vector2d corner = Vector2d(0.3, -0.3) + Vector2d(hx, -hy);
  EXPECT_NEAR(clearance({0.3, -0.3, 0.0}, 5), (Vector2d(0.5, -0.5) - corner).norm() - 0.02, 1e-9);
}

// Independent brute force for convex polygons: overlap by separating axes, distance by
// vertex-edge pairs.
double segmentDistance(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
  const Vector2d e = b - a;
  const double s = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (p - a - s * e).norm();
}

double bruteForceSignedDistance(const std::vector<Vector2d>& a, const std::vector<Vector2d>& b) {
  double depth = std::numeric_limits<double>::infinity();
  for (const auto* polygon : {&a, &b}) {
    for (std::size_t i = 0; i < polygon->size(); ++i) {
      const Vector2d e = (*polygon)[(i + 1) % polygon->size()] - (*polygon)[i];
      const Vector2d axis = Vector2d(e.y(), -e.x()).normalized();
      double a0 = 1e9, a1 = -1e9, b0 = 1e9, b1 = -1e9;
      for (const Vector2d& v : a) {
        a0 = std::min(a0, axis.dot(v));
        a1 = std::max(a1, axis.dot(v));
      }
      for (const Vector2d& v : b) {
        b0 = std::min(b0, axis.dot(v));
        b1 = std::max(b1, axis.dot(v));
      }
      depth = std::min(depth, std::min(a1 - b0, b1 - a0));
    }
  }
  if (depth > 0.0) return -depth;
  double distance = std::numeric_limits<double>::infinity();
  for (const Vector2d& p : a)
    for (std::size_t i = 0; i < b.size(); ++i)
      distance = std::min(distance, segmentDistance(p, b[i], b[(i + 1) % b.size()]));
  for (const Vector2d& p : b)
    for (std::size_t i = 0; i < a.size(); ++i)
      distance = std::min(distance, segmentDistance(p, a[i], a[(i + 1) % a.size()]));
  return distance;
}

std::vector<Vector2d> sole(const Vector3d& pose) {
  std::vector<Vector2d> corners;
  const Eigen::Rotation2Dd rotation(pose.z());
  for (const Vector2d local :
       {Vector2d(-1, -1), Vector2d(1, -1), Vector2d(1, 1), Vector2d(-1, 1)}) {
    corners.push_back(pose.head<2>() + rotation * Vector2d(0.5 * kSoleLength * local.x(),
                                                           0.5 * kSoleWidth * local.y()));
  }
  return corners;
}

TEST(World, FootClearanceMatchesABruteForceAtRandomPoses) {
  const std::vector<Obstacle> obstacles = mixedObstacles();
  const World world(obstacles);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> yaw(-M_PI, M_PI);
  for (int i = 0; i < world.obstacleCount(); ++i) {
    SCOPED_TRACE("obstacle " + std::to_string(i));
    const Obstacle& o = obstacles[i];
    int overlapping = 0, separated = 0;
    for (const Vector2d& p : pointsAround(o, &rng, 600)) {
      const Vector3d pose(p.x(), p.y(), yaw(rng));
      double expected;
      if (o.type == ObstacleType::kCircle) {
        // Circle: radius - signed distance of its centre to the sole (exact for convex shapes).
        const std::vector<Vector2d> rectangle = sole(pose);
        const wpg::AnalyticObstacleDistance rect({polygon(rectangle)});
        expected = rect.signedDistance(0, o.center, nullptr) - o.radius;
      } else {
        expected = bruteForceSignedDistance(sole(pose), o.worldVertices());
      }
      const double got = world.footClearance(pose, kSoleLength, kSoleWidth, i) + o.margin;
      EXPECT_NEAR(got, expected, 1e-6) << "foot at " << pose.transpose();
      (expected < 0.0 ? overlapping : separated)++;
    }
    EXPECT_GT(overlapping, 50);
    EXPECT_GT(separated, 50);
  }
}

TEST(World, ClearanceAndStateValidity) {
  const World world({circle({2.0, 0.0}, 0.5, 0.2), box({0.0, 2.0}, {1.0, 1.0}, 0.0, 0.1)});
  int nearest = -2;
  EXPECT_NEAR(world.clearance({0.0, 0.0}, &nearest), 1.3, 1e-9);  // 2 - 0.5 - 0.2
  EXPECT_EQ(nearest, 0);
  EXPECT_NEAR(world.clearance({0.0, 1.2}, &nearest), 0.2, 1e-9);  // 1.5 - 1.2 - 0.1
  EXPECT_EQ(nearest, 1);
  EXPECT_TRUE(world.isStateValid(0.0, 0.0, 0.3));
  EXPECT_FALSE(world.isStateValid(0.0, 1.2, 0.3));
  EXPECT_TRUE(world.isStateValid(0.0, 1.2, 0.19));
  EXPECT_FALSE(world.isStateValid(2.0, 0.0, 0.0));  // inside
  EXPECT_FALSE(world.isStateValid(std::nan(""), 0.0, 0.1));
  const World empty({});
  EXPECT_EQ(empty.clearance({0.0, 0.0}, &nearest), std::numeric_limits<double>::infinity());
  EXPECT_EQ(nearest, -1);
  EXPECT_TRUE(empty.isStateValid(0.0, 0.0, 10.0));
}

TEST(World, InvalidObstaclesAndIndicesAreRejected) {
  try {
    World({circle({0.0, 0.0}, 0.3), circle({1.0, 0.0}, -0.1)});
    FAIL() << "a negative radius was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("obstacles[1]"), std::string::npos) << e.what();
  }
  EXPECT_THROW(World({polygon({{0, 0}, {1, 0}, {0.2, 0.2}, {0, 1}})}),
               std::invalid_argument);                                              // non-convex
  EXPECT_THROW(World({polygon({{0, 0}, {1, 0}, {2, 0}})}), std::invalid_argument);  // degenerate
  const World world({circle({0.0, 0.0}, 0.3)});
  EXPECT_THROW(world.signedDistance(1, {0.0, 0.0}, nullptr), std::out_of_range);
  EXPECT_THROW(world.signedDistance(-1, {0.0, 0.0}, nullptr), std::out_of_range);
  EXPECT_THROW(world.footClearance({0, 0, 0}, kSoleLength, kSoleWidth, 1), std::out_of_range);
  EXPECT_THROW(world.footClearance({0, 0, 0}, 0.0, kSoleWidth, 0), std::invalid_argument);
}

TEST(World, CopiesAnswerTheSame) {
  const World world(mixedObstacles());
  World copy = world;
  World moved = std::move(copy);
  for (int i = 0; i < world.obstacleCount(); ++i) {
    EXPECT_EQ(moved.signedDistance(i, {0.3, -0.2}, nullptr),
              world.signedDistance(i, {0.3, -0.2}, nullptr));
  }
  EXPECT_EQ(moved.obstacles().size(), world.obstacles().size());
}

// Batch workers share one world (read-only): concurrent queries give the same answers.
TEST(World, ConcurrentQueriesAgreeWithSequentialOnes) {
  const World world(mixedObstacles());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-7.0, 7.0);
  std::vector<Vector2d> points;
  for (int k = 0; k < 2000; ++k) points.emplace_back(coordinate(rng), coordinate(rng));
  std::vector<double> expected;
  for (const Vector2d& p : points)
    for (int i = 0; i < world.obstacleCount(); ++i)
      expected.push_back(world.signedDistance(i, p, nullptr));
  std::vector<std::vector<double>> got(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < got.size(); ++t) {
    threads.emplace_back([&, t] {
      const World copy = world;  // copies share the geometry
      for (const Vector2d& p : points)
        for (int i = 0; i < copy.obstacleCount(); ++i)
          got[t].push_back(copy.signedDistance(i, p, nullptr));
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (const std::vector<double>& values : got) EXPECT_EQ(values, expected);
}

TEST(ObstacleChecks, PerStepMinimaAndSummary) {
  const World world({circle({1.0, 0.0}, 0.2, 0.1), box({0.0, 1.0}, {0.4, 0.4}, 0.0, 0.05)});
  wpg::WalkingParameters parameters;
  wpg::WalkTrajectory trajectory;
  for (const Vector3d pose : {Vector3d(0.0, 0.095, 0.0), Vector3d(0.0, -0.095, 0.0),
                              Vector3d(0.6, 0.0, 0.0), Vector3d(0.0, 0.5, 0.0)}) {
    wpg::Footstep step;
    step.pose = pose;
    trajectory.footsteps.push_back(step);
  }
  const wpg::planning::FootstepObstacleReport report =
      wpg::planning::checkFootsteps(world, parameters, trajectory);
  ASSERT_EQ(report.clearance.size(), 4u);
  // Step 2 at (0.6, 0): centre 0.4 - 0.2 - 0.1 = 0.1 from the circle's margin, 0.1 - 0.1287 < 0
  // from the NMPC's constraint (margin grown by obstacle_foot_radius); its front edge
  // 0.6 + 0.1086 is 0.2914 from the circle, 0.1914 from the margin.
  const double foot = parameters.obstacle_foot_radius;
  ASSERT_GT(foot, 0.1);
  EXPECT_EQ(report.centre_clearance_obstacle[2], 0);
  EXPECT_NEAR(report.centre_clearance[2], 0.1 - foot, 1e-9);
  EXPECT_LT(report.centre_clearance[2], 0.0);
  EXPECT_EQ(report.clearance_obstacle[2], 0);
  EXPECT_NEAR(report.clearance[2], 1.0 - 0.2 - (0.6 + 0.5 * parameters.foot_length) - 0.1, 1e-7);
  EXPECT_NEAR(report.foot_distance[2], report.clearance[2] + 0.1, 1e-12);
  // Step 3 at (0, 0.5): box from y = 0.8; centre 0.3 - 0.05 - foot, sole 0.3 - 0.069 - 0.05.
  EXPECT_EQ(report.centre_clearance_obstacle[3], 1);
  EXPECT_NEAR(report.centre_clearance[3], 0.25 - foot, 1e-9);
  EXPECT_NEAR(report.clearance[3], 0.3 - 0.5 * parameters.foot_width - 0.05, 1e-9);
  EXPECT_EQ(report.min_clearance_step, 2);
  EXPECT_DOUBLE_EQ(report.min_clearance, report.clearance[2]);
  EXPECT_EQ(report.min_centre_clearance_step, 2);
  EXPECT_DOUBLE_EQ(report.min_centre_clearance, report.centre_clearance[2]);

  const wpg::planning::FootstepObstacleReport none =
      wpg::planning::checkFootsteps(World({}), parameters, trajectory);
  ASSERT_EQ(none.clearance.size(), 4u);
  EXPECT_EQ(none.clearance[0], std::numeric_limits<double>::infinity());
  EXPECT_EQ(none.clearance_obstacle[0], -1);
  EXPECT_EQ(none.min_centre_clearance, std::numeric_limits<double>::infinity());
  EXPECT_EQ(none.min_clearance_step, -1);
}

}  // namespace

namespace {

// A motion whose straight line passes `gap` outside (> 0) or inside (< 0) the rounded corner of
// the unit box grown by the disc's radius, tangent to its corner's circle at 45 degrees.
struct CornerMotion {
  Vector2d from, to;
};
CornerMotion cornerMotion(double radius, double gap) {
  // The corner (0.5, 0.5); the line x + y = 1 + sqrt(2) (radius + gap) passes radius + gap from it.
  const double c = 1.0 + std::sqrt(2.0) * (radius + gap);
  return {Vector2d(c / 2.0 - 0.4, c / 2.0 + 0.4), Vector2d(c / 2.0 + 0.4, c / 2.0 - 0.4)};
}

}  // namespace

// A motion is checked whole, not at sampled points: a line that cuts the grown corner by 10 um
// passes every check at 2 cm (the points the planner once checked), and is still refused.
TEST(World, AMotionThatGrazesAGrownCornerBetweenSampledPointsIsRefused) {
  const World world({box(Vector2d::Zero(), Vector2d(1.0, 1.0), 0.0)});
  constexpr double kRadius = 0.1;
  const CornerMotion cut = cornerMotion(kRadius, -1e-5);
  const double length = (cut.to - cut.from).norm();
  const int pieces = static_cast<int>(std::ceil(length / 0.02));
  for (int k = 0; k <= pieces; ++k) {
    const Vector2d p = cut.from + (cut.to - cut.from) * k / pieces;
    EXPECT_TRUE(world.isStateValid(p.x(), p.y(), kRadius)) << "sampled point " << k;
  }
  const double cut_fraction = world.freeFraction(cut.from, cut.to, kRadius);
  EXPECT_LT(cut_fraction, 0.5);  // it reaches the corner at the middle of the motion
  EXPECT_GT(cut_fraction, 0.49);
  // Every point before the fraction is clear.
  for (int k = 0; k <= 1000; ++k) {
    const Vector2d p = cut.from + (cut.to - cut.from) * (cut_fraction * k / 1000.0);
    EXPECT_GE(world.clearance(p) - kRadius, -1e-9) << k;
  }
  // 1 um outside: clear all the way; a motion starting inside: nothing of it.
  const CornerMotion clear = cornerMotion(kRadius, 1e-6);
  EXPECT_EQ(world.freeFraction(clear.from, clear.to, kRadius), 1.0);
  EXPECT_EQ(world.freeFraction(Vector2d(0.55, 0.0), Vector2d(2.0, 0.0), kRadius), 0.0);
  EXPECT_EQ(world.freeFraction(Vector2d(2.0, 0.0), Vector2d(2.0, 0.0), kRadius), 1.0);
  EXPECT_EQ(World({}).freeFraction(Vector2d(0.0, 0.0), Vector2d(5.0, 0.0), kRadius), 1.0);
}
