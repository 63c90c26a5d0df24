// The numerical leg IK (damped least squares with joint limits) against the analytic one on
// HRP-2, and both on generated leg geometries, checked by forward kinematics.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "alloc_counter.hpp"
#include "generated_legs.hpp"
#include "hrp2_model.hpp"
#include "wpg/robots/numerical_leg_ik.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"

namespace {

using wpg::robots::NumericalLegIk;
using wpg::robots::Pose;
using wpg::robots::RobotModel;
using wpg::robots::WalkingIk;

using wpg_test::hrp2;

using wpg_test::rpy;

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
  EXPECT_LE(max_position_error, 1e-12);
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
// IK refuses them): from 0.2 rad away from walking-like angles, it reaches the target within
// its 1e-12 tolerances.
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
    const WalkingIk whole_body(model, settings);  // not HRP-2-like: numerical legs
    EXPECT_FALSE(whole_body.analyticLeg(WalkingIk::kLeft));
    EXPECT_FALSE(whole_body.analyticLeg(WalkingIk::kRight));
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
                                      << result.rotation_error << " rad, "
                                      << result.iterations << " iterations";
        worst_iterations = std::max(worst_iterations, result.iterations);
        const Pose reached = ik.forwardKinematics(waist, angles);
        worst_position = std::max(worst_position, (reached.position - sole.position).norm());
        worst_rotation = std::max(worst_rotation, rotationDistance(reached.rotation, sole.rotation));
      }
    }
  }
  std::printf("generated legs, 1000 targets: sole error <= %.3g m, %.3g rad, <= %d iterations\n",
              worst_position, worst_rotation, worst_iterations);
  EXPECT_LE(worst_position, 1e-12);
  EXPECT_LE(worst_rotation, 1e-12);
}

// The whole-body walking IK with numerical legs on HRP-2 (forced) gives the configurations of
// the analytic one within 1e-9, on a walk-like set of targets: feet apart and ahead, the CoM
// between them at heights from 0.70 to 0.82 m, the waist turned.
TEST(NumericalLegIk, WholeBodyIkMatchesTheAnalyticOneOnHrp2) {
  const WalkingIk analytic(hrp2());
  wpg::robots::WalkingIkSettings settings;
  settings.numerical_legs = true;
  const WalkingIk numerical(hrp2(), settings);
  ASSERT_TRUE(analytic.analyticLeg(WalkingIk::kLeft));
  ASSERT_FALSE(numerical.analyticLeg(WalkingIk::kLeft));
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double worst = 0.0;
  Eigen::VectorXd qa(hrp2().nq()), qn(hrp2().nq());
  for (int trial = 0; trial < 100; ++trial) {
    wpg::robots::WalkingIkTarget target;
    const double yaw = 0.3 * u(rng);
    target.left_foot << 0.2 * u(rng), 0.1 + 0.05 * u(rng), 0.03 * (1 + u(rng)), yaw;
    target.right_foot << 0.2 * u(rng), -0.1 + 0.05 * u(rng), 0.0, yaw + 0.1 * u(rng);
    target.com << 0.5 * (target.left_foot(0) + target.right_foot(0)) + 0.02 * u(rng),
        0.5 * (target.left_foot(1) + target.right_foot(1)) + 0.03 * u(rng), 0.76 + 0.06 * u(rng);
    target.waist_yaw = yaw;
    const auto a = analytic.solve(target, qa);
    const auto n = numerical.solve(target, qn);
    ASSERT_EQ(a.status, wpg::robots::WalkingIkStatus::kSolved) << "trial " << trial;
    ASSERT_EQ(n.status, wpg::robots::WalkingIkStatus::kSolved) << "trial " << trial;
    EXPECT_LT(n.foot_position_error, 1e-12);
    worst = std::max(worst, (qa - qn).cwiseAbs().maxCoeff());
  }
  std::printf("HRP-2 whole body, 100 targets: |q numerical - q analytic| <= %.3g\n", worst);
  EXPECT_LT(worst, 1e-9);
}

// A generated robot whose legs the analytic IK cannot solve (tilted, offset axes; 7 joints)
// walks a step: every sample's feet on their targets, CoM within its tolerance.
TEST(NumericalLegIk, WholeBodyIkSolvesGeneratedLegs) {
  std::mt19937 rng(21);
  const std::string path = ::testing::TempDir() + "/wpg_seven_joint_legs.urdf";
  const wpg::test::GeneralLegShape left = wpg::test::generalLeg(rng, 1.0, 7);
  const wpg::test::GeneralLegShape right = wpg::test::generalLeg(rng, -1.0, 7);
  wpg::test::writeTwoLeggedRobot(path, left.leg, right.leg);
  // The standing posture (the IK's start): knees bent 0.6 rad, hip and ankle pitch -0.3.
  {
    std::ofstream srdf(path.substr(0, path.size() - 5) + ".srdf");
    srdf << "<robot name=\"generated\"><group_state name=\"half_sitting\" group=\"all\">";
    for (const auto& [name, shape] : {std::pair{"left", &left}, std::pair{"right", &right}})
      for (std::size_t i = 0; i < shape->kind.size(); ++i)
        srdf << "<joint name=\"" << name << "_joint" << i << "\" value=\""
             << (shape->kind[i] == 'y' ? (i == 3 ? 0.6 : -0.3) : 0.0) << "\"/>";
    srdf << "</group_state></robot>\n";
  }
  const RobotModel model(path);
  wpg::robots::WalkingIkSettings settings;
  settings.left_sole_frame = "LEFT_SOLE";
  settings.right_sole_frame = "RIGHT_SOLE";
  const WalkingIk ik(model, settings);
  // The feet where the standing posture puts them; the CoM 1 cm lower, moving 5 cm forward.
  const Eigen::VectorXd bent = model.referenceConfiguration("half_sitting");
  const Pose l = model.framePose(bent, "LEFT_SOLE"), r = model.framePose(bent, "RIGHT_SOLE");
  Eigen::VectorXd q(model.nq());
  double worst_foot = 0.0, worst_com = 0.0;
  for (int k = 0; k <= 20; ++k) {
    const double s = k / 20.0;  // the left foot steps 0.1 m forward, lifted 3 cm mid-way
    wpg::robots::WalkingIkTarget target;
    target.left_foot << l.position.x() + 0.1 * s, l.position.y(),
        l.position.z() + 0.03 * std::sin(M_PI * s), 0.0;
    target.right_foot << r.position.x(), r.position.y(), r.position.z(), 0.0;
    target.com = model.centerOfMass(bent) + Eigen::Vector3d(0.05 * s, 0.0, -0.01);
    const auto result = ik.solve(target, q);
    ASSERT_EQ(result.status, wpg::robots::WalkingIkStatus::kSolved)
        << "sample " << k << ": CoM error " << result.com_error << " m after " << result.iterations
        << " evaluations";
    worst_foot = std::max(worst_foot, result.foot_position_error);
    worst_com = std::max(worst_com, (model.centerOfMass(q) - target.com).norm());
    for (const auto& [frame, foot] : {std::pair{"LEFT_SOLE", target.left_foot},
                                      std::pair{"RIGHT_SOLE", target.right_foot}}) {
      EXPECT_LT((model.framePose(q, frame).position - foot.head<3>()).norm(), 1e-12);
    }
  }
  EXPECT_LT(worst_foot, 1e-12);
  EXPECT_LT(worst_com, 1e-11);
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
