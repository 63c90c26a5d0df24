// The command_tangent linearization of circle obstacles (wpg/obstacle_tangent.hpp): which
// half-plane, which side, how J1's reference is turned, and that the selector's border only
// turns towards the command.
#include <gtest/gtest.h>

#include <cmath>

#include "wpg/obstacle_selector.hpp"
#include "wpg/obstacle_tangent.hpp"
#include "wpg/walking_parameters.hpp"

namespace {

using Eigen::Vector2d;

const Vector2d kCenter(1.4, 0.0);
const double kRadius = 0.63;      // grown circle [m]
const double kClearance = 0.3;    // CoM from the border [m]

TEST(ObstacleTangent, ObstacleAheadGivesATangentTurnedTowardsThePassingSide) {
  const Vector2d com(0.0, 0.0);
  const Vector2d n = wpg::commandTangentNormal(kCenter, kRadius, com, {0.2, 0.0}, +1, kClearance);
  EXPECT_NEAR(n.norm(), 1.0, 1e-12);
  // the CoM keeps exactly `clearance` from the border, which is turned to the left (n has a
  // positive y: the free side is up-left) and still faces the robot (n.x < 0)
  EXPECT_NEAR(n.dot(com - kCenter) - kRadius, kClearance, 1e-12);
  EXPECT_GT(n.y(), 0.0);
  EXPECT_LT(n.x(), 0.0);
  // the other side is the mirror image
  const Vector2d m = wpg::commandTangentNormal(kCenter, kRadius, com, {0.2, 0.0}, -1, kClearance);
  EXPECT_NEAR(m.x(), n.x(), 1e-12);
  EXPECT_NEAR(m.y(), -n.y(), 1e-12);
}

TEST(ObstacleTangent, CommandLineClearOfTheCircleGivesABorderAlongTheCommand) {
  const Vector2d com(0.5, 1.2);  // abreast-ish, more than r + clearance to the left
  const Vector2d n = wpg::commandTangentNormal(kCenter, kRadius, com, {0.2, 0.0}, +1, kClearance);
  EXPECT_NEAR(n.x(), 0.0, 1e-12);
  EXPECT_NEAR(n.y(), 1.0, 1e-12);
}

TEST(ObstacleTangent, CloseToTheCircleTheBorderFacesTheCom) {
  const Vector2d com(0.6, 0.3);  // 0.85 m from the centre, below r + clearance
  const Vector2d n = wpg::commandTangentNormal(kCenter, kRadius, com, {0.2, 0.0}, +1, kClearance);
  EXPECT_NEAR((n - (com - kCenter).normalized()).norm(), 0.0, 1e-12);
}

TEST(ObstacleTangent, SideIsWhereTheFeetAreTiesToTheLeft) {
  EXPECT_EQ(wpg::obstacleSide(kCenter, {0.0, 0.0}, {1.0, 0.0}), 1);
  EXPECT_EQ(wpg::obstacleSide(kCenter, {0.0, -0.005}, {1.0, 0.0}), 1);  // within the 1 cm tie
  EXPECT_EQ(wpg::obstacleSide(kCenter, {0.0, -0.02}, {1.0, 0.0}), -1);
  EXPECT_EQ(wpg::obstacleSide({1.4, -0.2}, {0.0, 0.0}, {1.0, 0.0}), 1);
  EXPECT_EQ(wpg::obstacleSide({1.4, 0.2}, {0.0, 0.0}, {1.0, 0.0}), -1);
}

TEST(ObstacleTangent, ReferenceIntoABorderSlidesAlongItAtTheCommandedSpeed) {
  Eigen::Matrix2Xd normals = Eigen::Matrix2Xd::Zero(2, 2);
  normals.col(1) = Vector2d(-1.0, 1.0).normalized();
  Eigen::VectorXd vx = Eigen::VectorXd::Constant(3, 0.2), vy = Eigen::VectorXd::Zero(3);
  vx(2) = -0.2;  // moving away from the border: unchanged
  wpg::turnReferenceAlongBorders(normals, 0.0, vx, vy);  // no sideways limit
  EXPECT_NEAR(vx(0), 0.2 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(vy(0), 0.2 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(vx(2), -0.2, 1e-12);
  EXPECT_NEAR(vy(2), 0.0, 1e-12);
}

// Along a border at 45 degrees to a 0.3 m/s command the turned reference would cross the
// command at 0.21 m/s: capped at 0.125 m/s across, it keeps its direction along the border;
// below the cap (0.1 m/s across at 0.2 m/s along a 30-degree border), and away from the border,
// the speed is the command's.
TEST(ObstacleTangent, ReferenceAlongABorderCrossesTheCommandNoFasterThanTheGaitWalksSideways) {
  Eigen::Matrix2Xd normals(2, 1);
  normals.col(0) = Vector2d(-1.0, 1.0).normalized();
  Eigen::VectorXd vx = Eigen::VectorXd::Constant(2, 0.3), vy = Eigen::VectorXd::Zero(2);
  vx(1) = -0.3;
  wpg::turnReferenceAlongBorders(normals, 0.125, vx, vy);
  EXPECT_NEAR(vy(0), 0.125, 1e-12);
  EXPECT_NEAR(vx(0), 0.125, 1e-12);  // along the border
  EXPECT_NEAR(vx(1), -0.3, 1e-12);
  EXPECT_NEAR(vy(1), 0.0, 1e-12);
  normals.col(0) = Vector2d(-0.5, std::sqrt(3.0) / 2.0);  // the border 30 degrees off +x
  vx.setConstant(0.2);
  vy.setZero();
  wpg::turnReferenceAlongBorders(normals, 0.125, vx, vy);
  EXPECT_NEAR(std::hypot(vx(0), vy(0)), 0.2, 1e-12);
  EXPECT_NEAR(vy(0), 0.1, 1e-12);
}

TEST(ObstacleTangent, GaitSidewaysSpeedIsThePolygonsLateralReachPerGaitCycle) {
  wpg::WalkingParameters w;
  // HRP-2: a left step 0.2 to 0.4 m beside the right foot, 0.8 s steps.
  EXPECT_NEAR(w.gaitSidewaysSpeed(), (0.4 - 0.2) / (2.0 * 0.8), 1e-12);
  w.feasibility_y = {0.15, 0.3, 0.45, 0.3, 0.15};
  w.single_support_samples = 5;
  EXPECT_NEAR(w.gaitSidewaysSpeed(), (0.45 - 0.15) / (2.0 * 0.6), 1e-12);
}

// Walking straight on towards the obstacle, the selector keeps the first border (a border
// recomputed beside the advancing CoM would recede in front of it); moving to the passing side,
// the border turns towards the command.
TEST(ObstacleTangent, SelectorBorderOnlyTurnsTowardsTheCommand) {
  wpg::Obstacle obstacle;
  obstacle.center = kCenter;
  obstacle.radius = 0.25;
  obstacle.margin = 0.25;
  wpg::ObstacleSelector selector;
  selector.set({obstacle});
  Eigen::VectorXi slots(1);
  Eigen::Matrix2Xd normals(2, 1);
  const double foot = kRadius - 0.5;
  selector.select({0.0, 0.0}, 1.5, slots);
  ASSERT_EQ(slots(0), 0);
  selector.tangentNormals({0.0, 0.0}, {0.0, 0.0}, {0.2, 0.0}, foot, kClearance, slots, normals);
  const Vector2d first = normals.col(0);
  selector.tangentNormals({0.3, 0.0}, {0.3, 0.0}, {0.2, 0.0}, foot, kClearance, slots, normals);
  EXPECT_EQ(normals.col(0), first);  // straight on: kept
  selector.tangentNormals({0.3, 0.6}, {0.3, 0.6}, {0.2, 0.0}, foot, kClearance, slots, normals);
  EXPECT_GT(normals(1, 0), first.y());  // to the left: turned towards +y (border along +x)
  // out of reach: forgotten, chosen afresh
  selector.select({-5.0, 0.0}, 1.5, slots);
  selector.select({0.0, 0.0}, 1.5, slots);
  selector.tangentNormals({0.0, 0.0}, {0.0, 0.0}, {0.2, 0.0}, foot, kClearance, slots, normals);
  EXPECT_NEAR((normals.col(0) - first).norm(), 0.0, 1e-12);
}

}  // namespace
