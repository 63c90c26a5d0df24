// J1's reference turned along the obstacles' borders (wpg/obstacle_tangent.hpp,
// turnReferenceAlongBorders): into one border it slides along it, square into one towards the
// passing side, between two along the corridor or the strip they leave, never faster across
// the robot's heading than the gait walks sideways, and along a wall only with its own part.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "wpg/obstacle_tangent.hpp"
#include "wpg/walking_parameters.hpp"

namespace {

using Eigen::Vector2d;

// cos and sin of a heading of 0 for `n` samples.
std::pair<Eigen::VectorXd, Eigen::VectorXd> straight(int n) {
  return {Eigen::VectorXd::Ones(n), Eigen::VectorXd::Zero(n)};
}

// The slides of `normals` (zero columns kept zero) towards the left (+1) or right (-1) of +x.
Eigen::Matrix2Xd slidesFor(const Eigen::Matrix2Xd& normals, int side) {
  Eigen::Matrix2Xd slides = Eigen::Matrix2Xd::Zero(2, normals.cols());
  for (int k = 0; k < normals.cols(); ++k)
    if (!normals.col(k).isZero())
      slides.col(k) = wpg::borderSlide(normals.col(k), {1.0, 0.0}, side);
  return slides;
}

// No room inside any border: a direction counts only if it drives into none.
Eigen::VectorXd noRoom(const Eigen::Matrix2Xd& normals) {
  return Eigen::VectorXd::Zero(normals.cols());
}

TEST(ReferenceAlongBorders, ReferenceIntoABorderSlidesAlongItAtTheCommandedSpeed) {
  Eigen::Matrix2Xd normals = Eigen::Matrix2Xd::Zero(2, 2);
  normals.col(1) = Vector2d(-1.0, 1.0).normalized();
  Eigen::VectorXd vx = Eigen::VectorXd::Constant(3, 0.2), vy = Eigen::VectorXd::Zero(3);
  vx(2) = -0.2;  // moving away from the border: unchanged
  const auto heading = straight(3);
  wpg::turnReferenceAlongBorders(normals, slidesFor(normals, +1), heading.first, heading.second,
                                 0.0, noRoom(normals), 1.6, vx, vy);
  EXPECT_NEAR(vx(0), 0.2 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(vy(0), 0.2 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(vx(2), -0.2, 1e-12);
  EXPECT_NEAR(vy(2), 0.0, 1e-12);
}

// The gap between two obstacles crossed at a slant (a slalom's circles 1 m apart, +-0.4 m): the
// borders nearly face each other (normals 177.5 degrees apart) across a strip 0.31 m wide that
// narrows far ahead. The command drives into the near one; along it, the reference drives
// slightly into the far one, so the cone of directions is empty; but walked for the preview
// (0.2 m/s for 1.6 s) the CoM, 0.28 m inside that far border, stays clear of it: the reference
// turns along the strip. With no room inside the far border it stays as it is.
TEST(ReferenceAlongBorders, ReferenceFollowsAStripWhoseBordersMeetBeyondThePreview) {
  Eigen::Matrix2Xd normals(2, 2);
  normals.col(0) = Vector2d(-0.670, 0.742).normalized();           // the near border, driven into
  normals.col(1) = Vector2d(0.649, -0.760).normalized();           // the far one, across the strip
  const Vector2d along = Vector2d(normals(1, 0), -normals(0, 0));  // the near border's tangent
  ASSERT_LT(normals.col(1).dot(along), 0.0);  // along the near border into the far one
  Eigen::VectorXd room(2);
  room << 0.03, 0.28;
  Eigen::VectorXd vx = Eigen::VectorXd::Constant(2, 0.2), vy = Eigen::VectorXd::Zero(2);
  wpg::turnReferenceAlongBorders(normals, slidesFor(normals, +1), straight(2).first,
                                 straight(2).second, 0.0, room, 1.6, vx, vy);
  const Vector2d turned(vx(0), vy(0));
  EXPECT_NEAR(turned.norm(), 0.2, 1e-12);
  EXPECT_NEAR(turned.normalized().dot(along), 1.0, 1e-12);
  vx.setConstant(0.2);
  vy.setZero();
  wpg::turnReferenceAlongBorders(normals, slidesFor(normals, +1), straight(2).first,
                                 straight(2).second, 0.0, noRoom(normals), 1.6, vx, vy);
  EXPECT_EQ(vx(0), 0.2);
  EXPECT_EQ(vy(0), 0.0);
}

// Along a border at 45 degrees to a 0.3 m/s command the turned reference would cross the
// command at 0.21 m/s: capped at 0.125 m/s across, it keeps its direction along the border;
// below the cap (0.1 m/s across at 0.2 m/s along a 30-degree border), and away from the border,
// the speed is the command's.
TEST(ReferenceAlongBorders,
     ReferenceAlongABorderCrossesTheCommandNoFasterThanTheGaitWalksSideways) {
  Eigen::Matrix2Xd normals(2, 1);
  Eigen::VectorXd offsets(1);
  normals.col(0) = Vector2d(-1.0, 1.0).normalized();
  Eigen::VectorXd vx = Eigen::VectorXd::Constant(2, 0.3), vy = Eigen::VectorXd::Zero(2);
  vx(1) = -0.3;
  wpg::turnReferenceAlongBorders(normals, slidesFor(normals, +1), straight(2).first,
                                 straight(2).second, 0.125, noRoom(normals), 1.6, vx, vy);
  EXPECT_NEAR(vy(0), 0.125, 1e-12);
  EXPECT_NEAR(vx(0), 0.125, 1e-12);  // along the border
  EXPECT_NEAR(vx(1), -0.3, 1e-12);
  EXPECT_NEAR(vy(1), 0.0, 1e-12);
  normals.col(0) = Vector2d(-0.5, std::sqrt(3.0) / 2.0);  // the border 30 degrees off +x
  vx.setConstant(0.2);
  vy.setZero();
  wpg::turnReferenceAlongBorders(normals, slidesFor(normals, +1), straight(2).first,
                                 straight(2).second, 0.125, noRoom(normals), 1.6, vx, vy);
  EXPECT_NEAR(std::hypot(vx(0), vy(0)), 0.2, 1e-12);
  EXPECT_NEAR(vy(0), 0.1, 1e-12);
}

TEST(ReferenceAlongBorders, GaitSidewaysSpeedIsThePolygonsLateralReachPerGaitCycle) {
  wpg::WalkingParameters w;
  // HRP-2: a left step 0.2 to 0.4 m beside the right foot, 0.8 s steps.
  EXPECT_NEAR(w.gaitSidewaysSpeed(), (0.4 - 0.2) / (2.0 * 0.8), 1e-12);
  w.feasibility_y = {0.15, 0.3, 0.45, 0.3, 0.15};
  w.single_support_samples = 5;
  EXPECT_NEAR(w.gaitSidewaysSpeed(), (0.45 - 0.15) / (2.0 * 0.6), 1e-12);
}

// Two borders facing each other across a diagonal corridor: the reference slides along the
// corridor (the only directions that drive into neither), at its own speed.
TEST(ReferenceAlongBorders, ReferenceBetweenTwoBordersSlidesAlongTheCorridor) {
  Eigen::Matrix2Xd normals(2, 3);
  const Vector2d along = Vector2d(1.0, 1.0).normalized();
  normals.col(0) = Vector2d(-along.y(), along.x());  // left border, free side to its left
  normals.col(1) = -normals.col(0);
  normals.col(2).setZero();  // an empty slot
  Eigen::VectorXd vx = Eigen::VectorXd::Constant(1, 0.2), vy = Eigen::VectorXd::Zero(1);
  const auto heading = straight(1);
  wpg::turnReferenceAlongBorders(normals, slidesFor(normals, +1), heading.first, heading.second,
                                 0.0, noRoom(normals), 1.6, vx, vy);
  EXPECT_NEAR(vx(0), 0.2 * along.x(), 1e-12);
  EXPECT_NEAR(vy(0), 0.2 * along.y(), 1e-12);
  // a wedge whose every direction is more than a right angle from the reference: unchanged
  normals.col(0) = Vector2d(-1.0, 0.2).normalized();
  normals.col(1) = Vector2d(-1.0, -0.2).normalized();
  vx(0) = 0.2;
  vy(0) = 0.0;
  wpg::turnReferenceAlongBorders(normals, slidesFor(normals, +1), heading.first, heading.second,
                                 0.0, noRoom(normals), 1.6, vx, vy);
  EXPECT_EQ(vx(0), 0.2);
  EXPECT_EQ(vy(0), 0.0);
}

// A box's face met head on: the reference has no projection along the border of its own; it
// slides towards the passing side, no faster sideways than the gait walks.
TEST(ReferenceAlongBorders, ReferenceSquareIntoABorderSlidesTowardsThePassingSide) {
  Eigen::Matrix2Xd normals(2, 1);
  Eigen::VectorXd offsets(1);
  normals.col(0) = Vector2d(-1.0, 0.0);
  const auto heading = straight(1);
  for (int side : {+1, -1}) {
    Eigen::VectorXd vx = Eigen::VectorXd::Constant(1, 0.2), vy = Eigen::VectorXd::Zero(1);
    wpg::turnReferenceAlongBorders(normals, slidesFor(normals, side), heading.first, heading.second,
                                   0.125, noRoom(normals), 1.6, vx, vy);
    EXPECT_NEAR(vx(0), 0.0, 1e-12);
    EXPECT_NEAR(vy(0), side * 0.125, 1e-12);
  }
}

// The sideways limit is in the robot's frame: a robot heading +y, commanded forward (world
// +y), whose reference turns along a border at 45 degrees, is held to 0.125 m/s across its
// heading (world x), not across world y.
TEST(ReferenceAlongBorders, SidewaysLimitIsAcrossTheRobotsHeading) {
  Eigen::Matrix2Xd normals(2, 1);
  Eigen::VectorXd offsets(1);
  normals.col(0) = Vector2d(1.0, -1.0).normalized();  // a border across the way ahead
  Eigen::VectorXd vx = Eigen::VectorXd::Zero(1), vy = Eigen::VectorXd::Constant(1, 0.3);
  const Eigen::VectorXd c = Eigen::VectorXd::Zero(1), s = Eigen::VectorXd::Ones(1);  // h = pi/2
  wpg::turnReferenceAlongBorders(normals, slidesFor(normals, +1), c, s, 0.125, noRoom(normals), 1.6,
                                 vx, vy);
  EXPECT_NEAR(std::abs(vx(0)), 0.125, 1e-12);
  EXPECT_NEAR(vy(0), 0.125, 1e-12);
}

// A wall (a zero slide: no way round within the generator's max_detour) 0.3 rad off square to
// a 0.2 m/s command: the reference keeps only its own part along the wall, 0.2 sin(0.3) m/s,
// not the command's speed; square into it, nothing to keep: left as it is (the QP holds the
// steps and the robot stops). The same border with a slide is followed at 0.2 m/s.
TEST(ReferenceAlongBorders, AlongAWallOnlyTheReferencesOwnPart) {
  Eigen::Matrix2Xd normals(2, 1);
  normals.col(0) = Vector2d(-std::cos(0.3), std::sin(0.3));
  const Eigen::Matrix2Xd wall = Eigen::Matrix2Xd::Zero(2, 1);
  Eigen::VectorXd vx = Eigen::VectorXd::Constant(1, 0.2), vy = Eigen::VectorXd::Zero(1);
  wpg::turnReferenceAlongBorders(normals, wall, straight(1).first, straight(1).second, 0.0,
                                 noRoom(normals), 1.6, vx, vy);
  const Vector2d turned(vx(0), vy(0));
  EXPECT_NEAR(turned.norm(), 0.2 * std::sin(0.3), 1e-12);
  EXPECT_NEAR(turned.dot(normals.col(0)), 0.0, 1e-12);
  vx.setConstant(0.2);
  vy.setZero();
  wpg::turnReferenceAlongBorders(normals, slidesFor(normals, +1), straight(1).first,
                                 straight(1).second, 0.0, noRoom(normals), 1.6, vx, vy);
  EXPECT_NEAR(std::hypot(vx(0), vy(0)), 0.2, 1e-12);
  normals.col(0) = Vector2d(-1.0, 0.0);
  vx.setConstant(0.2);
  vy.setZero();
  wpg::turnReferenceAlongBorders(normals, wall, straight(1).first, straight(1).second, 0.0,
                                 noRoom(normals), 1.6, vx, vy);
  EXPECT_EQ(vx(0), 0.2);
  EXPECT_EQ(vy(0), 0.0);
}

}  // namespace
