// The numerical leg IK (damped least squares with joint limits) against the analytic one on
// HRP-2, and both on generated leg geometries, checked by forward kinematics.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "alloc_counter.hpp"
#include "generated_legs.hpp"
#include "wpg/robots/numerical_leg_ik.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"

namespace {

using wpg::robots::NumericalLegIk;
using wpg::robots::Pose;
using wpg::robots::RobotModel;
using wpg::robots::WalkingIk;

const RobotModel& hrp2() {
  static const RobotModel model(std::string(WPG_SOURCE_DIR) + "/robots/hrp2/hrp2.urdf");
  return model;
}

Eigen::Matrix3d rpy(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

double rotationDistance(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a * b.transpose()).angle();
}

// Walking-like leg angles of HRP-2: small hip and ankle angles, the knee bent.
WalkingIk::LegAngles walkingAngles(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  WalkingIk::LegAngles q;
  q << 0.3 * u(rng), 0.25 * u(rng), -0.4 + 0.4 * u(rng), 1.0 + 0.8 * u(rng), -0.4 + 0.4 * u(rng),
      0.25 * u(rng);
  return q;
}

// On HRP-2 both IKs solve the same sole targets, and the numerical one, started 0.2 rad away
// from the solution (a walk's previous sample is closer), lands on the analytic angles.
TEST(NumericalLegIk, MatchesTheAnalyticIkOnHrp2) {
  const WalkingIk analytic(hrp2());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double max_angle_difference = 0.0, max_position_error = 0.0;
  int max_iterations = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const WalkingIk::Side side = trial % 2 == 0 ? WalkingIk::kLeft : WalkingIk::kRight;
    const NumericalLegIk numerical(hrp2(), side == WalkingIk::kLeft ? "LLEG_SOLE" : "RLEG_SOLE");
    ASSERT_EQ(numerical.jointCount(), 6);
    Pose waist;
    waist.rotation = rpy(0.1 * u(rng), 0.1 * u(rng), M_PI * u(rng));
    waist.position = Eigen::Vector3d(u(rng), u(rng), 0.6);
    const WalkingIk::LegAngles truth = walkingAngles(rng);
    const Pose sole = analytic.legForwardKinematics(side, waist, truth);
    WalkingIk::LegAngles closed_form;
    ASSERT_TRUE(analytic.solveLeg(side, waist, sole, closed_form));
    Eigen::VectorXd angles = truth;
    for (int i = 0; i < 6; ++i) angles(i) += 0.2 * u(rng);
    const auto result = numerical.solve(waist, sole, angles);
    ASSERT_TRUE(result.converged) << "trial " << trial << ": errors " << result.position_error
                                  << " m, " << result.rotation_error << " rad";
    max_iterations = std::max(max_iterations, result.iterations);
    max_angle_difference =
        std::max(max_angle_difference, (angles - closed_form).cwiseAbs().maxCoeff());
    const Pose reached = numerical.forwardKinematics(waist, angles);
    max_position_error = std::max(max_position_error, (reached.position - sole.position).norm());
    // The chain's own forward kinematics is the analytic IK's.
    const Pose analytic_reached = analytic.legForwardKinematics(side, waist, closed_form);
    EXPECT_LT((analytic_reached.position - numerical.forwardKinematics(waist, closed_form).position)
                  .norm(), 1e-14);
  }
  std::printf("HRP-2, 500 targets: |numerical - analytic| <= %.3g rad, sole error <= %.3g m, "
              "<= %d iterations\n", max_angle_difference, max_position_error, max_iterations);
  EXPECT_LT(max_angle_difference, 1e-9);
  EXPECT_LT(max_position_error, 1e-12);
}

// A target that needs the knee beyond its limit: the numerical IK stays within the limits
// (the knee held at it) and says it did not converge.
TEST(NumericalLegIk, HoldsTheJointLimits) {
  const WalkingIk analytic(hrp2());
  const NumericalLegIk numerical(hrp2(), "RLEG_SOLE");
  const int knee = numerical.joints()[3];
  const double upper = hrp2().jointUpperLimits()(knee);
  WalkingIk::LegAngles truth;
  truth << 0.0, 0.0, -1.4, upper + 0.3, -1.4, 0.0;
  Pose waist;
  waist.position.z() = 0.6;
  const Pose sole = analytic.legForwardKinematics(WalkingIk::kRight, waist, truth);
  Eigen::VectorXd angles = truth;  // the knee starts clamped to its limit
  const auto result = numerical.solve(waist, sole, angles);
  EXPECT_FALSE(result.converged);
  EXPECT_GT(result.position_error, 1e-3);
  for (int i = 0; i < 6; ++i) {
    const int k = numerical.joints()[i];
    EXPECT_GE(angles(i), hrp2().jointLowerLimits()(k));
    EXPECT_LE(angles(i), hrp2().jointUpperLimits()(k));
  }
  EXPECT_DOUBLE_EQ(angles(3), upper);
}

// The analytic IK on generated HRP-2-like legs (random thigh, shank, hip, knee and ankle
// offsets): forward kinematics of its angles is the target.
TEST(NumericalLegIk, AnalyticIkHoldsOnGeneratedHrp2LikeLegs) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  for (int robot = 0; robot < 20; ++robot) {
    const std::string path =
        ::testing::TempDir() + "/wpg_hrp2_like_" + std::to_string(robot) + ".urdf";
    wpg::test::writeTwoLeggedRobot(path, wpg::test::hrp2LikeLeg(rng, 1.0),
                                   wpg::test::hrp2LikeLeg(rng, -1.0));
    const RobotModel model(path);
    wpg::robots::WalkingIkSettings settings;
    settings.left_sole_frame = "LEFT_SOLE";
    settings.right_sole_frame = "RIGHT_SOLE";
    const WalkingIk ik(model, settings);
    for (int trial = 0; trial < 50; ++trial) {
      const WalkingIk::Side side = trial % 2 == 0 ? WalkingIk::kLeft : WalkingIk::kRight;
      Pose waist;
      waist.rotation = rpy(0.1 * u(rng), 0.1 * u(rng), M_PI * u(rng));
      const WalkingIk::LegAngles truth = walkingAngles(rng);
      const Pose sole = ik.legForwardKinematics(side, waist, truth);
      WalkingIk::LegAngles angles;
      ASSERT_TRUE(ik.solveLeg(side, waist, sole, angles));
      const Pose reached = ik.legForwardKinematics(side, waist, angles);
      worst = std::max({worst, (reached.position - sole.position).norm(),
                        rotationDistance(reached.rotation, sole.rotation)});
    }
  }
  EXPECT_LT(worst, 1e-12);
}

// Walking-like angles of a generated leg: the knee (the first pitch joint right after another)
// bent 0.3 to 1.7 rad, the other pitch joints about -0.4, the rest within 0.3 rad.
Eigen::VectorXd walkingAngles(std::mt19937& rng, const std::vector<char>& kind) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd q(static_cast<Eigen::Index>(kind.size()));
  bool knee_seen = false;
  for (std::size_t i = 0; i < kind.size(); ++i) {
    const bool knee = !knee_seen && kind[i] == 'y' && i > 0 && kind[i - 1] == 'y';
    knee_seen = knee_seen || knee;
    q(static_cast<Eigen::Index>(i)) = knee             ? 1.0 + 0.7 * u(rng)
                                      : kind[i] == 'y' ? -0.4 + 0.3 * u(rng)
                                                       : 0.3 * u(rng);
  }
  return q;
}

// The numerical IK on generated legs of 6 and 7 joints whose axes do not meet (the analytic
// IK refuses them): from 0.2 rad away from walking-like angles, it reaches the target to 1e-12.
TEST(NumericalLegIk, HoldsOnGeneratedLegsWithoutIntersectingAxes) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst_position = 0.0, worst_rotation = 0.0;
  int worst_iterations = 0;
  for (int robot = 0; robot < 20; ++robot) {
    const int joints = robot % 2 == 0 ? 6 : 7;
    const std::string path =
        ::testing::TempDir() + "/wpg_general_leg_" + std::to_string(robot) + ".urdf";
    const wpg::test::GeneralLegShape left = wpg::test::generalLeg(rng, 1.0, joints);
    const wpg::test::GeneralLegShape right = wpg::test::generalLeg(rng, -1.0, joints);
    wpg::test::writeTwoLeggedRobot(path, left.leg, right.leg);
    const RobotModel model(path);
    wpg::robots::WalkingIkSettings settings;
    settings.left_sole_frame = "LEFT_SOLE";
    settings.right_sole_frame = "RIGHT_SOLE";
    EXPECT_THROW(WalkingIk(model, settings), std::invalid_argument);  // not HRP-2-like
    for (const auto& [frame, shape] : {std::pair{"LEFT_SOLE", &left}, std::pair{"RIGHT_SOLE", &right}}) {
      const NumericalLegIk ik(model, frame);
      ASSERT_EQ(ik.jointCount(), joints);
      for (int trial = 0; trial < 25; ++trial) {
        Pose waist;
        waist.rotation = rpy(0.1 * u(rng), 0.1 * u(rng), M_PI * u(rng));
        waist.position = Eigen::Vector3d(u(rng), u(rng), 0.7);
        const Eigen::VectorXd truth = walkingAngles(rng, shape->kind);
        Eigen::VectorXd angles = truth;
        for (int i = 0; i < joints; ++i) angles(i) += 0.2 * u(rng);
        const Pose sole = ik.forwardKinematics(waist, truth);
        const auto result = ik.solve(waist, sole, angles);
        ASSERT_TRUE(result.converged) << "robot " << robot << " " << frame << " trial " << trial
                                      << ": errors " << result.position_error << " m, "
                                      << result.rotation_error << " rad";
        worst_iterations = std::max(worst_iterations, result.iterations);
        const Pose reached = ik.forwardKinematics(waist, angles);
        worst_position = std::max(worst_position, (reached.position - sole.position).norm());
        worst_rotation = std::max(worst_rotation, rotationDistance(reached.rotation, sole.rotation));
      }
    }
  }
  std::printf("generated legs, 1000 targets: sole error <= %.3g m, %.3g rad, <= %d iterations\n",
              worst_position, worst_rotation, worst_iterations);
  EXPECT_LT(worst_position, 1e-12);
  EXPECT_LT(worst_rotation, 1e-12);
}

TEST(NumericalLegIk, SolveDoesNotAllocate) {
  const WalkingIk analytic(hrp2());
  const NumericalLegIk numerical(hrp2(), "LLEG_SOLE");
  WalkingIk::LegAngles truth;
  truth << 0.1, 0.05, -0.5, 1.0, -0.5, -0.05;
  Pose waist;
  const Pose sole = analytic.legForwardKinematics(WalkingIk::kLeft, waist, truth);
  Eigen::VectorXd angles = Eigen::VectorXd::Zero(6);
  angles(3) = 0.5;
  const long before = wpg_test::allocationCount();
  const auto result = numerical.solve(waist, sole, angles);
  EXPECT_EQ(wpg_test::allocationCount() - before, 0);
  EXPECT_TRUE(result.converged);
}

TEST(NumericalLegIk, RefusesLegsOfFewerThanSixJoints) {
  std::mt19937 rng(3);
  const std::string path = ::testing::TempDir() + "/wpg_five_joint_leg.urdf";
  wpg::test::writeTwoLeggedRobot(path, wpg::test::generalLeg(rng, 1.0, 5).leg,
                                 wpg::test::generalLeg(rng, -1.0, 6).leg);
  const RobotModel model(path);
  EXPECT_THROW(NumericalLegIk(model, "LEFT_SOLE"), std::invalid_argument);
  EXPECT_EQ(NumericalLegIk(model, "RIGHT_SOLE").jointCount(), 6);
}

}  // namespace
