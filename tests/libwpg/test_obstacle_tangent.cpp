// The command_tangent linearization of the obstacle rows (wpg/obstacle_tangent.hpp): which
// half-plane for circles, boxes and polygons, which side, how J1's reference is turned, and
// that the selector's border only turns towards the command, for one obstacle or several.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "wpg/obstacle_selector.hpp"
#include "wpg/obstacle_tangent.hpp"
#include "wpg/walking_parameters.hpp"

namespace {

using Eigen::Vector2d;

const Vector2d kCenter(1.4, 0.0);
const double kRadius = 0.63;    // grown circle [m]
const double kClearance = 0.3;  // CoM from the border [m]
const Vector2d kForward(0.2, 0.0);

// The circle of kCenter, R 0.25 m, margin 0.25 m: kRadius once grown with parameters whose
// obstacle_foot_radius is kRadius - 0.5.
wpg::Obstacle kCircle() {
  wpg::Obstacle circle;
  circle.center = kCenter;
  circle.radius = 0.25;
  circle.margin = 0.25;
  return circle;
}

// A bound on the detour that no scene of these tests reaches.
constexpr double kNoDetourLimit = 1e9;

// A circle's border: its centre, grown by kRadius.
Vector2d circleBorder(const Vector2d& com, const Vector2d& direction, int side) {
  return wpg::borderNormal({kCenter}, kRadius, com, direction, side, kClearance,
                           (com - kCenter).normalized());
}

TEST(ObstacleTangent, ObstacleAheadGivesATangentTurnedTowardsThePassingSide) {
  const Vector2d com(0.0, 0.0);
  const Vector2d n = circleBorder(com, kForward, +1);
  EXPECT_NEAR(n.norm(), 1.0, 1e-12);
  // the CoM keeps exactly `clearance` from the border, which is turned to the left (n has a
  // positive y: the free side is up-left) and still faces the robot (n.x < 0)
  EXPECT_NEAR(n.dot(com - kCenter) - kRadius, kClearance, 1e-12);
  EXPECT_GT(n.y(), 0.0);
  EXPECT_LT(n.x(), 0.0);
  // the other side is the mirror image
  const Vector2d m = circleBorder(com, kForward, -1);
  EXPECT_NEAR(m.x(), n.x(), 1e-12);
  EXPECT_NEAR(m.y(), -n.y(), 1e-12);
}

// Abreast of the circle (its CoM well clear of it), the border turns past the command's line
// towards the command (behind the robot) as far as keeps it `clearance` beside the CoM: the
// space ahead and across is free for the next obstacle's way round.
TEST(ObstacleTangent, AbreastOfTheCircleTheBorderTurnsBehindTheRobot) {
  const Vector2d com(1.4, 1.3);  // 0.67 m from the grown circle: the whole clearance
  const Vector2d n = circleBorder(com, kForward, +1);
  EXPECT_NEAR(n.norm(), 1.0, 1e-12);
  EXPECT_GT(n.x(), 0.0);  // facing forward: walking on along +x moves away from it
  EXPECT_NEAR(n.dot(com - kCenter) - kRadius, kClearance, 1e-12);
  // far past it, the border is square to the command behind the robot
  const Vector2d past(4.0, 0.3);
  const Vector2d m = circleBorder(past, kForward, +1);
  EXPECT_NEAR(m.x(), 1.0, 1e-12);
  EXPECT_NEAR(m.y(), 0.0, 1e-12);
}

TEST(ObstacleTangent, CloseToTheCircleTheBorderFacesTheCom) {
  const Vector2d com(0.6, 0.3);  // 0.85 m from the centre, below r + clearance
  const Vector2d n = circleBorder(com, kForward, +1);
  EXPECT_NEAR((n - (com - kCenter).normalized()).norm(), 0.0, 1e-12);
}

TEST(ObstacleTangent, SideIsWhereTheFeetAreTiesToTheLeft) {
  EXPECT_EQ(wpg::obstacleSide(kCenter, {0.0, 0.0}, {1.0, 0.0}), 1);
  EXPECT_EQ(wpg::obstacleSide(kCenter, {0.0, -0.005}, {1.0, 0.0}), 1);  // within the 1 cm tie
  EXPECT_EQ(wpg::obstacleSide(kCenter, {0.0, -0.02}, {1.0, 0.0}), -1);
  EXPECT_EQ(wpg::obstacleSide({1.4, -0.2}, {0.0, 0.0}, {1.0, 0.0}), 1);
  EXPECT_EQ(wpg::obstacleSide({1.4, 0.2}, {0.0, 0.0}, {1.0, 0.0}), -1);
}

// Walking straight on towards the obstacle, the selector keeps the first border (a border
// recomputed beside the advancing CoM would recede in front of it) until the CoM crosses it;
// moving to the passing side, the border turns towards the command.
TEST(ObstacleTangent, SelectorBorderOnlyTurnsTowardsTheCommand) {
  wpg::ObstacleSelector selector;
  selector.set({kCircle()});
  Eigen::VectorXi slots(1);
  Eigen::Matrix2Xd normals(2, 1);
  Eigen::VectorXd offsets(1);
  wpg::WalkingParameters parameters;
  parameters.obstacle_foot_radius = kRadius - 0.5;
  selector.select({0.0, 0.0}, 1.5, slots);
  ASSERT_EQ(slots(0), 0);
  selector.borderNormals({0.0, 0.0}, {0.0, 0.0}, {0.2, 0.0}, parameters, kClearance, kNoDetourLimit,
                         slots, normals, offsets);
  const Vector2d first = normals.col(0);
  selector.borderNormals({0.1, 0.0}, {0.1, 0.0}, {0.2, 0.0}, parameters, kClearance, kNoDetourLimit,
                         slots, normals, offsets);
  EXPECT_EQ(normals.col(0), first);  // straight on: kept
  // further on, the CoM has crossed the kept border: given up
  const Vector2d closer(0.6, 0.0);
  ASSERT_LT(first.dot(closer - kCenter) - kRadius, 0.0);
  selector.borderNormals(closer, closer, {0.2, 0.0}, parameters, kClearance, kNoDetourLimit, slots,
                         normals, offsets);
  EXPECT_NE(normals.col(0), first);
  EXPECT_GE(normals.col(0).dot(closer - kCenter) - kRadius, 0.0);
  selector.borderNormals({0.3, 0.6}, {0.3, 0.6}, {0.2, 0.0}, parameters, kClearance, kNoDetourLimit,
                         slots, normals, offsets);
  EXPECT_GT(normals(1, 0), first.y());  // to the left: turned towards +y (border along +x)
  // out of reach: forgotten, chosen afresh
  selector.select({-5.0, 0.0}, 1.5, slots);
  selector.select({0.0, 0.0}, 1.5, slots);
  selector.borderNormals({0.0, 0.0}, {0.0, 0.0}, {0.2, 0.0}, parameters, kClearance, kNoDetourLimit,
                         slots, normals, offsets);
  EXPECT_NEAR((normals.col(0) - first).norm(), 0.0, 1e-12);
}

// Any convex core: for random polygons (as vertex sets) and CoMs, the border keeps every point
// of the grown core on its far side (the row is inside eq. 18's set), passes at least
// `clearance` beside the CoM unless it faces it, and is turned as far towards the command as
// that allows: a little further, some point comes closer than the clearance (or it is at d).
TEST(ObstacleTangent, BorderOfAnyConvexCoreIsASupportingLineTurnedAsFarAsTheComAllows) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int turned = 0, facing_count = 0, at_command = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<Vector2d> core;
    const int points = 1 + trial % 6;
    const Vector2d centre(2.0 + unit(random), 0.5 * unit(random));
    for (int p = 0; p < points; ++p)
      core.push_back(centre + 0.4 * Vector2d(unit(random), unit(random)));
    const double radius = 0.1 + 0.3 * std::abs(unit(random));
    const Vector2d com(2.0 + 2.5 * unit(random), 2.0 * unit(random));
    const Vector2d direction = Vector2d(1.0, 0.3 * unit(random));
    const int side = unit(random) > 0.0 ? 1 : -1;
    // the facing normal of the core's hull: the direction from its nearest point (by sampling
    // the segments between the points, fine enough for this test's tolerance)
    Vector2d nearest = core.front();
    for (const Vector2d& a : core)
      for (const Vector2d& b : core)
        for (int t = 0; t <= 200; ++t) {
          const Vector2d q = a + (b - a) * (t / 200.0);
          if ((com - q).norm() < (com - nearest).norm()) nearest = q;
        }
    if ((com - nearest).norm() < 1e-9) continue;
    const Vector2d facing = (com - nearest).normalized();
    const Vector2d n = wpg::borderNormal(core, radius, com, direction, side, kClearance, facing);
    ASSERT_NEAR(n.norm(), 1.0, 1e-12);
    const double offset = wpg::borderOffset(core, radius, n);
    for (const Vector2d& v : core) EXPECT_LE(n.dot(v) + radius, offset + 1e-12);
    if (n == facing) {
      ++facing_count;
      continue;
    }
    ++turned;
    EXPECT_GE(n.dot(com) - offset, kClearance - 1e-9);
    const double progress = wpg::borderProgress(n, direction, side);
    if (std::abs(progress) < 1e-9) {
      ++at_command;
      continue;
    }
    // turned a little further towards d (clockwise on the left side, unless the CoM is past
    // the obstacle on the other side and the border turns back to d): the CoM loses its
    // clearance
    const double step = (progress < 0.0 ? -side : side) * 1e-6;
    const Vector2d further(std::cos(step) * n.x() - std::sin(step) * n.y(),
                           std::sin(step) * n.x() + std::cos(step) * n.y());
    EXPECT_LT(std::abs(wpg::borderProgress(further, direction, side)), std::abs(progress));
    EXPECT_LT(further.dot(com) - wpg::borderOffset(core, radius, further), kClearance + 1e-9);
  }
  // every case occurs
  EXPECT_GT(turned, 200);
  EXPECT_GT(facing_count, 100);
  EXPECT_GT(at_command, 10);
}

TEST(ObstacleTangent, ProgressGrowsFromSquareInFrontToBehindThroughThePassingSide) {
  const Vector2d d(1.0, 0.0);
  EXPECT_NEAR(wpg::borderProgress({-1.0, 0.0}, d, +1), -M_PI, 1e-12);
  EXPECT_NEAR(wpg::borderProgress({0.0, 1.0}, d, +1), -0.5 * M_PI, 1e-12);
  EXPECT_NEAR(wpg::borderProgress({1.0, 0.0}, d, +1), 0.0, 1e-12);
  EXPECT_NEAR(wpg::borderProgress({0.0, -1.0}, d, -1), -0.5 * M_PI, 1e-12);
  EXPECT_NEAR(wpg::borderProgress({-1.0, 0.0}, d, -1), -M_PI, 1e-12);
  // just short of the cut (the other side's normal) the progress is at its largest
  EXPECT_GT(wpg::borderProgress({0.01, -1.0}, d, +1), 1.5);
  EXPECT_LT(wpg::borderProgress({-0.01, -1.0}, d, +1), -4.0);
}

// A box dead ahead: its border, like a circle's, passes `clearance` beside the CoM and slants
// towards the passing side, and the row keeps every corner grown by the margin behind it.
TEST(ObstacleTangent, BoxAheadGetsABorderTurnedTowardsThePassingSide) {
  wpg::Obstacle box;
  box.type = wpg::ObstacleType::kBox;
  box.center = {2.0, 0.0};
  box.size = {0.4, 0.4};
  box.yaw = 0.3;
  box.margin = 0.2;
  wpg::ObstacleSet set({box});
  const double radius = 0.2 + 0.1287;
  const Vector2d com(0.5, 0.0);
  Vector2d facing;
  set.signedDistance(0, com, &facing);
  for (int side : {+1, -1}) {
    const Vector2d n =
        wpg::borderNormal(set.core(0), radius, com, {1.0, 0.0}, side, kClearance, facing);
    EXPECT_NEAR(n.dot(com) - wpg::borderOffset(set.core(0), radius, n), kClearance, 1e-9);
    EXPECT_LT(n.x(), 0.0);
    EXPECT_GT(side * n.y(), 0.0);
  }
}

// Several obstacles in reach at once (a staggered pair, a box and a circle): each gets its own
// border, none of them zero.
TEST(ObstacleTangent, SelectorGivesEveryObstacleInReachItsBorder) {
  wpg::Obstacle a, b, box;
  a.center = {1.2, 0.25};
  a.radius = 0.15;
  a.margin = 0.2;
  b = a;
  b.center = {2.4, -0.25};
  box.type = wpg::ObstacleType::kBox;
  box.center = {1.8, 1.4};  // 0.25 m from a's grown circle: room for a step between them
  box.size = {0.5, 0.3};
  box.margin = 0.2;
  wpg::ObstacleSelector selector;
  selector.set({a, b, box});
  Eigen::VectorXi slots(4);
  Eigen::Matrix2Xd normals(2, 4);
  Eigen::VectorXd offsets(4);
  selector.select({0.3, -0.1}, 3.0, slots);
  ASSERT_GE(slots(2), 0);
  wpg::WalkingParameters parameters;
  selector.borderNormals({0.4, -0.1}, {0.3, -0.1}, {0.2, 0.0}, parameters, kClearance,
                         kNoDetourLimit, slots, normals, offsets);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(normals.col(k).norm(), 1.0, 1e-12) << k;
  EXPECT_EQ(normals.col(3).norm(), 0.0);
  // the rows keep the steps out: the CoM's own clearance from each border is positive
  for (int k = 0; k < 3; ++k) {
    const int index = slots(k);
    const double radius = selector.distance()->coreRadius(index) +
                          wpg::stepCentreMargin(selector.obstacles()[index], parameters);
    EXPECT_GT(normals.col(k).dot(Vector2d(0.4, -0.1)) -
                  wpg::borderOffset(selector.distance()->core(index), radius, normals.col(k)),
              0.0)
        << k;
    // a lone obstacle's row is its own supporting half-plane
    EXPECT_NEAR(offsets(k),
                wpg::borderOffset(selector.distance()->core(index), radius, normals.col(k)), 1e-12);
  }
}

// Two boxes staggered across the path with a gap no step fits through (0.15 m between their
// grown shapes, the least step width being 0.2 m, the feet side by side): one obstacle for the
// border rule. The slot of the first carries a border that keeps every step out of both; the
// second's slot is emptied; both are passed on the side of the first, here the right (the feet
// right of its centre line). A gap a step fits through (0.25 m) leaves two obstacles.
TEST(ObstacleTangent, SelectorJoinsObstaclesWithNoWayBetween) {
  wpg::WalkingParameters parameters;
  const double grown = 0.2 + parameters.obstacle_foot_radius;  // margin + foot radius
  ASSERT_EQ(parameters.leastStepWidth(), 0.2);  // the feasibility polygon's nearest vertex
  for (const double gap : {0.15, 0.25}) {
    wpg::Obstacle first, second;
    first.type = second.type = wpg::ObstacleType::kBox;
    first.size = second.size = {0.4, 1.0};
    first.margin = second.margin = 0.2;
    first.center = {2.0, 0.45};
    // the boxes' facing corners (2.2, -0.05) and (x, 0.05): 0.1 m apart across
    const double across = 2.0 * grown + gap;
    second.center = {2.2 + std::sqrt(across * across - 0.01) + 0.2, -0.45};
    wpg::ObstacleSelector selector;
    selector.set({first, second});
    Eigen::VectorXi slots(4);
    Eigen::Matrix2Xd normals(2, 4);
    Eigen::VectorXd offsets(4);
    const Vector2d com(0.5, -0.1);
    selector.select(com, 3.0, slots);
    ASSERT_GE(slots(1), 0);
    selector.borderNormals(com, com, {0.2, 0.0}, parameters, kClearance, kNoDetourLimit, slots,
                           normals, offsets);
    const int kept = (slots.array() >= 0).count();
    if (gap < parameters.leastStepWidth()) {
      ASSERT_EQ(kept, 1) << gap;
      const int k = slots(0) >= 0 ? 0 : 1;
      const Vector2d n = normals.col(k);
      for (int index = 0; index < 2; ++index) {
        const double radius = selector.distance()->coreRadius(index) +
                              wpg::stepCentreMargin(selector.obstacles()[index], parameters);
        EXPECT_GE(offsets(k) + 1e-12,
                  wpg::borderOffset(selector.distance()->core(index), radius, n))
            << index;
      }
      EXPECT_GE(n.dot(com) - offsets(k), kClearance - 1e-9);  // the CoM with its clearance
      EXPECT_LT(n.y(), 0.0);  // turned towards the right, the passing side
    } else {
      EXPECT_EQ(kept, 2) << gap;
    }
  }
}

// The distance between convex cores: apart, crossing, one inside the other, point cores.
// A wall 0.3 x 6 m across the path, 1.5 m ahead: its way round on either side lies 3.6 m aside
// of the CoM (3 m + the step-centre margin + the clearance). Within max_detour it gets a border
// turned towards the passing side and a slide; beyond (2.5 m) it is a wall: the border faces
// the CoM (square to the command) and its slide is zero. A box 0.8 m across is no wall.
TEST(ObstacleTangent, SelectorMakesAWallOfAWayRoundBeyondTheDetour) {
  wpg::WalkingParameters parameters;
  for (const double width : {6.0, 0.8}) {
    wpg::Obstacle box;
    box.type = wpg::ObstacleType::kBox;
    box.center = {1.5, 0.0};
    box.size = {0.3, width};
    box.margin = 0.2;
    for (const double detour : {kNoDetourLimit, 2.5}) {
      wpg::ObstacleSelector selector;
      selector.set({box});
      Eigen::VectorXi slots(4);
      Eigen::Matrix2Xd normals(2, 4);
      Eigen::VectorXd offsets(4);
      const Vector2d com(0.3, 0.0);
      selector.select(com, 3.0, slots);
      ASSERT_EQ(slots(0), 0);
      selector.borderNormals(com, com, kForward, parameters, kClearance, detour, slots, normals,
                             offsets);
      const bool wall = width > 2.0 && detour < kNoDetourLimit;
      EXPECT_EQ(selector.slides().col(0).isZero(), wall) << width << " " << detour;
      if (wall) {
        EXPECT_NEAR(normals(0, 0), -1.0, 1e-12);
      } else {
        EXPECT_GT(std::abs(normals(1, 0)), 0.1) << width << " " << detour;  // turned
      }
    }
  }
}

TEST(ObstacleTangent, CoreDistance) {
  const std::vector<Vector2d> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Vector2d> apart{{2, 0.5}, {3, 0.5}, {3, 2}};
  const std::vector<Vector2d> crossing{{0.5, -1}, {0.6, -1}, {0.6, 2}, {0.5, 2}};
  const std::vector<Vector2d> inside{{0.2, 0.2}, {0.4, 0.2}, {0.3, 0.4}};
  EXPECT_NEAR(wpg::coreDistance(square, apart), 1.0, 1e-12);
  EXPECT_NEAR(wpg::coreDistance(apart, square), 1.0, 1e-12);
  EXPECT_EQ(wpg::coreDistance(square, crossing), 0.0);
  EXPECT_EQ(wpg::coreDistance(square, inside), 0.0);
  EXPECT_EQ(wpg::coreDistance(inside, square), 0.0);
  EXPECT_NEAR(wpg::coreDistance({{3, 4}}, {{0, 0}}), 5.0, 1e-12);
  EXPECT_NEAR(wpg::coreDistance({{-1, 0.5}}, square), 1.0, 1e-12);
}

// The facing normal of a hull of discs is the gradient of the distance to it: checked against
// the distance sampled on a fine circle of directions (max over n of n.p - h(n)).
TEST(ObstacleTangent, HullFacingIsTheDistanceGradient) {
  std::mt19937 random(91);
  const auto uniform = [&](double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(random);
  };
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vector2d> points;
    std::vector<double> radii;
    const int count = 1 + trial % 7;
    for (int i = 0; i < count; ++i) {
      points.emplace_back(uniform(-1.0, 1.0), uniform(-1.0, 1.0));
      radii.push_back(uniform(0.05, 0.5));
    }
    const double angle = uniform(-M_PI, M_PI);
    const Vector2d p = 3.0 * Vector2d(std::cos(angle), std::sin(angle));
    const Vector2d n = wpg::hullFacing(points, radii, p);
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    const double found = n.dot(p) - wpg::borderOffset(points, radii, n);
    double sampled = -1e9;
    for (int j = 0; j < 20000; ++j) {
      const double a = 2.0 * M_PI * j / 20000.0;
      const Vector2d m(std::cos(a), std::sin(a));
      sampled = std::max(sampled, m.dot(p) - wpg::borderOffset(points, radii, m));
    }
    EXPECT_GE(found, sampled - 1e-9) << trial;  // no sampled direction does better
    // and no better than the true maximum, which the samples miss by at most half a step
    // times the function's Lipschitz constant in the angle, |p| + max |v| (3 + sqrt 2)
    EXPECT_LE(found, sampled + 0.5 * (2.0 * M_PI / 20000.0) * (3.0 + std::sqrt(2.0))) << trial;
  }
}

}  // namespace

namespace {

// A group joined in two steps (the third obstacle met joins the first, then the second): the
// group keeps the first one met as its leader, so every slot in reach either carries a border
// or is emptied, none is left with neither.
TEST(ObstacleTangent, SelectorGroupKeepsItsFirstMember) {
  wpg::WalkingParameters parameters;
  wpg::Obstacle first, second, third;
  first.type = second.type = third.type = wpg::ObstacleType::kBox;
  first.margin = second.margin = third.margin = 0.2;
  first.size = second.size = {0.4, 0.4};
  first.center = {2.0, 1.0};    // met first along +x
  second.center = {2.3, -1.0};  // then this one, 2 m across from the first: no gap between them
  third.size = {0.4, 1.6};      // last, its ends 0.1 m from each: a wall joining them
  third.center = {2.8, 0.0};
  wpg::ObstacleSelector selector;
  selector.set({first, second, third});
  Eigen::VectorXi slots(4);
  Eigen::Matrix2Xd normals(2, 4);
  Eigen::VectorXd offsets(4);
  const Vector2d com(0.0, 0.0);
  selector.select(com, 5.0, slots);
  ASSERT_EQ((slots.array() >= 0).count(), 3);
  selector.borderNormals(com, com, {0.2, 0.0}, parameters, kClearance, kNoDetourLimit, slots,
                         normals, offsets);
  EXPECT_EQ((slots.array() >= 0).count(), 1);
  for (int k = 0; k < 4; ++k) {
    if (slots(k) < 0) continue;
    EXPECT_EQ(slots(k), 0) << "the first met leads the group";
    EXPECT_NEAR(normals.col(k).norm(), 1.0, 1e-12) << k;
  }
}

// The next landing's row (obstacle_landing_linearization: step): the half-plane of the same
// grown circle that faces the planned landing, the paper's linearization at the step. Pushed
// forward while it walks along a slanted border, the robot must land beyond that border: the
// landing's row allows it where the obstacle is not.
TEST(ObstacleTangent, LandingRowFacesThePlannedLanding) {
  wpg::ObstacleSelector selector;
  selector.set({kCircle()});
  wpg::WalkingParameters parameters;
  parameters.obstacle_foot_radius = kRadius - 0.5;
  Eigen::VectorXi slots(2);
  Eigen::Matrix2Xd normals(2, 2), landing_normals(2, 2);
  Eigen::VectorXd offsets(2), landing_offsets(2);
  selector.select({0.0, 0.0}, 3.0, slots);
  ASSERT_EQ(slots(0), 0);
  selector.borderNormals({0.2, 0.0}, {0.2, 0.0}, kForward, parameters, kClearance, kNoDetourLimit,
                         slots, normals, offsets);
  const Vector2d landing(0.65, -0.06);  // a catching step ahead, right foot
  ASSERT_LT(normals.col(0).dot(landing), offsets(0)) << "the slanted border forbids it";
  selector.landingRows(landing, parameters, slots, landing_normals, landing_offsets);
  const Vector2d facing = (landing - kCenter).normalized();
  EXPECT_NEAR((landing_normals.col(0) - facing).norm(), 0.0, 1e-12);
  // the supporting half-plane of the grown circle: the circle touches it, beyond it
  EXPECT_NEAR(landing_offsets(0), facing.dot(kCenter) + kRadius, 1e-12);
  EXPECT_GT(landing_normals.col(0).dot(landing), landing_offsets(0)) << "allowed";
  EXPECT_EQ(landing_normals.col(1).norm(), 0.0);  // an empty slot has no row
  // no command: the borders face the CoM, and the landing has no row of its own
  selector.borderNormals({0.2, 0.0}, {0.2, 0.0}, {0.0, 0.0}, parameters, kClearance, kNoDetourLimit,
                         slots, normals, offsets);
  selector.landingRows(landing, parameters, slots, landing_normals, landing_offsets);
  EXPECT_EQ(landing_normals.norm(), 0.0);
  EXPECT_EQ(landing_offsets.norm(), 0.0);
}

// A group's landing row is a supporting half-plane of the group's hull: every member's grown
// box lies beyond it (the landing allowed, no member's margin), carried by the leader's slot.
TEST(ObstacleTangent, LandingRowOfAGroupSupportsItsHull) {
  wpg::WalkingParameters parameters;
  wpg::Obstacle first, second;
  first.type = second.type = wpg::ObstacleType::kBox;
  first.margin = second.margin = 0.2;
  first.size = second.size = {0.4, 0.4};
  first.center = {2.0, 0.4};
  second.center = {2.2, -0.3};  // 0.3 m apart: no step between the grown boxes
  wpg::ObstacleSelector selector;
  selector.set({first, second});
  Eigen::VectorXi slots(4);
  Eigen::Matrix2Xd normals(2, 4), landing_normals(2, 4);
  Eigen::VectorXd offsets(4), landing_offsets(4);
  const Vector2d com(0.5, 0.0);
  selector.select(com, 5.0, slots);
  ASSERT_EQ((slots.array() >= 0).count(), 2);
  selector.borderNormals(com, com, kForward, parameters, kClearance, kNoDetourLimit, slots, normals,
                         offsets);
  ASSERT_EQ((slots.array() >= 0).count(), 1) << "one group";
  const double grown = first.margin + parameters.obstacle_foot_radius;
  for (const Vector2d landing : {Vector2d(1.2, 0.0), Vector2d(1.5, -0.9), Vector2d(2.1, 1.2)}) {
    selector.landingRows(landing, parameters, slots, landing_normals, landing_offsets);
    for (int k = 0; k < 4; ++k) {
      if (slots(k) < 0) {
        EXPECT_EQ(landing_normals.col(k).norm(), 0.0) << k;
        continue;
      }
      const Vector2d n = landing_normals.col(k);
      EXPECT_NEAR(n.norm(), 1.0, 1e-12);
      double support = -1e9;  // the hull's support h(n) + radius, over both boxes' corners
      for (const wpg::Obstacle* box : {&first, &second})
        for (const double sx : {-0.2, 0.2})
          for (const double sy : {-0.2, 0.2})
            support = std::max(support, n.dot(box->center + Vector2d(sx, sy)) + grown);
      EXPECT_NEAR(landing_offsets(k), support, 1e-12) << landing.transpose();
      EXPECT_GT(n.dot(landing), landing_offsets(k)) << landing.transpose();
    }
  }
}

}  // namespace
