// Analytic leg IK and whole-body walking IK, checked with the model's own forward kinematics.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "alloc_counter.hpp"
#include "hrp2_model.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"

namespace {

using wpg::robots::Pose;
using wpg::robots::RobotModel;
using wpg::robots::WalkingIk;
using wpg::robots::WalkingIkStatus;
using wpg::robots::WalkingIkTarget;

using wpg_test::hrp2;

using wpg_test::rpy;

TEST(WalkingIk, LegGeometryIsHrp2s) {
  const WalkingIk ik(hrp2());
  const auto& left = ik.legConfigurationIndices(WalkingIk::kLeft);
  const auto& right = ik.legConfigurationIndices(WalkingIk::kRight);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(right[i], 7 + i);
    EXPECT_EQ(left[i], 13 + i);
  }
  wpg::robots::WalkingIkSettings arm;
  arm.left_sole_frame = "LARM_LINK6";  // nine joints from the root
  EXPECT_THROW(WalkingIk(hrp2(), arm), std::invalid_argument);
  wpg::robots::WalkingIkSettings unknown;
  unknown.right_sole_frame = "NO_SUCH_FRAME";
  EXPECT_THROW(WalkingIk(hrp2(), unknown), std::invalid_argument);
}

// Random leg angles -> forward kinematics -> IK -> forward kinematics: same sole pose, and the
// same angles (the IK picks the knee-forward branch, knee > 0).
TEST(WalkingIk, LegIkRoundTrip) {
  const RobotModel& model = hrp2();
  const WalkingIk ik(model);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double max_position_error = 0.0, max_rotation_error = 0.0, max_angle_error = 0.0;
  for (int trial = 0; trial < 2000; ++trial) {
    const WalkingIk::Side side = trial % 2 == 0 ? WalkingIk::kLeft : WalkingIk::kRight;
    Pose waist;
    waist.rotation = rpy(0.3 * u(rng), 0.3 * u(rng), M_PI * u(rng));
    waist.position = Eigen::Vector3d(u(rng), u(rng), 0.6 + 0.1 * u(rng));
    WalkingIk::LegAngles angles;
    angles << 0.6 * u(rng), 0.4 * u(rng), -0.7 + 0.8 * u(rng), 1.1 + 1.0 * u(rng),
        -0.3 + 0.6 * u(rng), 0.4 * u(rng);
    const Pose sole = ik.legForwardKinematics(side, waist, angles);
    WalkingIk::LegAngles solved;
    ASSERT_TRUE(ik.solveLeg(side, waist, sole, solved)) << "trial " << trial;
    const Pose back = ik.legForwardKinematics(side, waist, solved);
    max_position_error = std::max(max_position_error, (back.position - sole.position).norm());
    max_rotation_error = std::max(max_rotation_error, (back.rotation - sole.rotation).norm());
    max_angle_error = std::max(max_angle_error, (solved - angles).cwiseAbs().maxCoeff());
  }
  std::printf("leg IK round trip (2000 poses): position %.2e m, rotation %.2e, angles %.2e rad\n",
              max_position_error, max_rotation_error, max_angle_error);
  RecordProperty("leg_ik_max_position_error_m", std::to_string(max_position_error));
  EXPECT_LT(max_position_error, 1e-9);
  EXPECT_LT(max_rotation_error, 1e-9);
  EXPECT_LT(max_angle_error, 1e-7);
}

TEST(WalkingIk, LegIkAgreesWithTheModelKinematics) {
  // legForwardKinematics and RobotModel::framePose are the same chain
  const RobotModel& model = hrp2();
  const WalkingIk ik(model);
  Eigen::VectorXd q = model.halfSitting();
  q.segment<6>(7) << 0.1, -0.2, -0.5, 1.0, -0.4, 0.1;
  RobotModel::setFreeFlyer(q, Eigen::Vector3d(0.1, 0.2, 0.6), Eigen::Quaterniond(rpy(0.1, -0.2, 0.5)));
  const Pose waist{RobotModel::freeFlyerOrientation(q).toRotationMatrix(), q.head<3>()};
  const Pose a = ik.legForwardKinematics(WalkingIk::kRight, waist, q.segment<6>(7));
  const Pose b = model.framePose(q, "RLEG_SOLE");
  EXPECT_LT((a.position - b.position).norm(), 1e-14);
  EXPECT_LT((a.rotation - b.rotation).norm(), 1e-14);
}

TEST(WalkingIk, HalfSittingIsAFixedPoint) {
  const RobotModel& model = hrp2();
  const WalkingIk ik(model);
  const Eigen::VectorXd half_sitting = model.halfSitting();
  WalkingIkTarget target;
  target.left_foot << 0.009490, 0.095, 0.0, 0.0;
  target.right_foot << 0.009490, -0.095, 0.0, 0.0;
  // exact feet of the half-sitting posture (the check values are rounded to 6 decimals)
  target.left_foot.head<3>() = model.framePose(half_sitting, "LLEG_SOLE").position;
  target.right_foot.head<3>() = model.framePose(half_sitting, "RLEG_SOLE").position;
  target.com = model.centerOfMass(half_sitting);
  Eigen::VectorXd q(model.nq());
  const auto result = ik.solve(target, q);
  EXPECT_EQ(result.status, WalkingIkStatus::kSolved);
  EXPECT_EQ(result.limit_violations, 0u);
  EXPECT_LT((q - half_sitting).cwiseAbs().maxCoeff(), 1e-9);
}

// Walking-like targets: feet apart, yawed, one lifted; CoM at the LIPM height between them.
TEST(WalkingIk, WholeBodyIkReachesFeetAndCom) {
  const RobotModel& model = hrp2();
  const WalkingIk ik(model);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd q(model.nq());
  double max_foot = 0.0, max_com = 0.0, max_foot_reported = 0.0;
  int max_iterations = 0;
  const int trials = 500;
  for (int trial = 0; trial < trials; ++trial) {
    const double yaw = M_PI * u(rng);
    const Eigen::Matrix3d r = rpy(0, 0, yaw);
    const Eigen::Vector3d centre(2.0 * u(rng), 2.0 * u(rng), 0.0);
    WalkingIkTarget target;
    const double step = 0.14 * u(rng);  // feet up to 0.28 m apart (feasibility polygon)
    target.left_foot.head<3>() = centre + r * Eigen::Vector3d(step, 0.095 + 0.03 * u(rng), 0.0);
    target.right_foot.head<3>() = centre + r * Eigen::Vector3d(-step, -0.095 - 0.03 * u(rng), 0.0);
    (trial % 2 == 0 ? target.left_foot : target.right_foot)(2) = 0.025 + 0.025 * u(rng);
    target.left_foot(3) = yaw + 0.1 * u(rng);
    target.right_foot(3) = yaw + 0.1 * u(rng);
    target.waist_yaw = 0.5 * (target.left_foot(3) + target.right_foot(3));
    target.com = centre + r * Eigen::Vector3d(0.02 * u(rng), 0.08 * u(rng), 0.0);
    target.com.z() = 0.814;
    const auto result = ik.solve(target, q);
    ASSERT_EQ(result.status, WalkingIkStatus::kSolved)
        << "trial " << trial << " step " << step << " foot error " << result.foot_position_error
        << " knees " << q(10) << " " << q(16) << " com error " << result.com_error;
    // independent check with the model's forward kinematics
    const double com_error = (model.centerOfMass(q) - target.com).norm();
    double foot_error = 0.0;
    for (const auto& [frame, foot] : {std::pair{"LLEG_SOLE", target.left_foot},
                                      std::pair{"RLEG_SOLE", target.right_foot}}) {
      const Pose sole = model.framePose(q, frame);
      foot_error = std::max(foot_error, (sole.position - foot.head<3>()).norm());
      foot_error = std::max(foot_error, (sole.rotation - rpy(0, 0, foot(3))).norm());
    }
    // waist: requested yaw, level
    const Eigen::Matrix3d waist = RobotModel::freeFlyerOrientation(q).toRotationMatrix();
    EXPECT_LT((waist - rpy(0, 0, target.waist_yaw)).norm(), 1e-12);
    max_com = std::max(max_com, com_error);
    max_foot = std::max(max_foot, foot_error);
    max_foot_reported = std::max(max_foot_reported, result.foot_position_error);
    max_iterations = std::max(max_iterations, result.iterations);
  }
  std::printf("whole-body IK (%d targets): feet %.2e m, CoM %.2e m, max %d CoM evaluations\n",
              trials, max_foot, max_com, max_iterations);
  RecordProperty("whole_body_ik_max_com_error_m", std::to_string(max_com));
  RecordProperty("whole_body_ik_max_foot_error_m", std::to_string(max_foot));
  EXPECT_LT(max_foot, 1e-8);
  EXPECT_LT(max_com, 1e-8);
  EXPECT_LT(max_com, 1e-10);
  EXPECT_LT(max_foot_reported, 1e-9);
}

TEST(WalkingIk, ReportsUnreachableTargetsAndJointLimits) {
  const RobotModel& model = hrp2();
  const WalkingIk ik(model);
  Eigen::VectorXd q(model.nq());
  WalkingIkTarget target;
  target.left_foot << 0.0, 0.095, 0.0, 0.0;
  target.right_foot << 0.0, -0.095, 0.0, 0.0;
  target.com << 0.0, 0.0, 1.1;  // above what straight legs reach (0.857)
  auto result = ik.solve(target, q);
  EXPECT_NE(result.status, WalkingIkStatus::kSolved);
  EXPECT_GT(result.foot_position_error, 0.1);
  EXPECT_STRNE(wpg::robots::walkingIkStatusName(result.status), "solved");

  // right foot yawed by -1 rad: the right hip yaw (joint 0) goes below -45 deg; not clamped
  target.com << 0.0, 0.0, 0.8;
  target.right_foot(3) = -1.0;
  result = ik.solve(target, q);
  EXPECT_EQ(result.status, WalkingIkStatus::kSolved);
  EXPECT_TRUE(result.limit_violations & 1u);
  EXPECT_NEAR(result.max_limit_violation, -(q(7) - model.jointLowerLimits()(0)), 1e-12);
  EXPECT_LT(q(7), -0.9);
  EXPECT_LT(result.foot_position_error, 1e-9);

  Eigen::VectorXd too_short(10);
  EXPECT_THROW(ik.solve(target, too_short), std::invalid_argument);
  target.com.x() = std::nan("");
  EXPECT_THROW(ik.solve(target, q), std::invalid_argument);
}

TEST(WalkingIk, SolveDoesNotAllocate) {
  const RobotModel& model = hrp2();
  const WalkingIk ik(model);
  Eigen::VectorXd q(model.nq());
  WalkingIkTarget target;
  target.left_foot << 0.1, 0.1, 0.03, 0.1;
  target.right_foot << -0.1, -0.09, 0.0, 0.05;
  target.com << 0.0, 0.02, 0.814;
  target.waist_yaw = 0.075;
  ik.solve(target, q);  // warm-up
  const long before = wpg_test::allocationCount();
  const auto result = ik.solve(target, q);
  EXPECT_EQ(wpg_test::allocationCount() - before, 0);
  EXPECT_EQ(result.status, WalkingIkStatus::kSolved);
}

TEST(WalkingIk, SolvesAWalkTrajectory) {
  const RobotModel& model = hrp2();
  const WalkingIk ik(model);
  wpg::WalkTrajectory walk;
  const int n = 200;
  for (int i = 0; i < n; ++i) {
    const double t = 0.005 * i;
    walk.time.push_back(t);
    walk.com.emplace_back(0.1 * t, 0.05 * std::sin(2 * M_PI * t), 0.814);
    walk.left_foot.emplace_back(0.0, 0.095, 0.0, 0.0);
    walk.right_foot.emplace_back(0.1 * t, -0.095, 0.04 * std::sin(M_PI * t), 0.0);
    walk.free_flyer_yaw.push_back(0.0);
  }
  const auto out = ik.solveTrajectory(walk);
  EXPECT_EQ(out.q.rows(), n);
  EXPECT_EQ(out.q.cols(), model.nq());
  EXPECT_EQ(out.failures, 0);
  EXPECT_LT(out.max_com_error, 1e-10);
  EXPECT_LT(out.max_foot_position_error, 1e-9);
  EXPECT_LT((model.centerOfMass(out.q.row(n - 1).transpose()) - walk.com.back()).norm(), 1e-10);
  // a corrected CoM (dynamic filter) replaces walk.com
  Eigen::MatrixXd com(n, 3);
  for (int i = 0; i < n; ++i) com.row(i) = (walk.com[i] + Eigen::Vector3d(0.01, 0, 0)).transpose();
  const auto shifted = ik.solveTrajectory(walk, com);
  EXPECT_LT((model.centerOfMass(shifted.q.row(7).transpose()) - com.row(7).transpose()).norm(), 1e-10);
  EXPECT_THROW(ik.solveTrajectory(walk, com.topRows(3)), std::invalid_argument);
  // Into a trajectory of the walk's size (the online filter's window): the same
  // configurations, no allocation.
  wpg::robots::WalkingIkTrajectory reused = out;
  const long before = wpg_test::allocationCount();
  ik.solveTrajectory(walk, com, reused);
  EXPECT_EQ(wpg_test::allocationCount() - before, 0);
  EXPECT_EQ(reused.q, shifted.q);
  EXPECT_EQ(reused.failures, 0);
}

}  // namespace

namespace {

// Walking-like random targets (as in WholeBodyIkReachesFeetAndCom), and a waist position near
// the solution.
WalkingIkTarget randomWalkingTarget(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double yaw = M_PI * u(rng);
  const Eigen::Matrix3d r = rpy(0, 0, yaw);
  const Eigen::Vector3d centre(u(rng), u(rng), 0.0);
  WalkingIkTarget target;
  const double step = 0.12 * u(rng);
  target.left_foot.head<3>() = centre + r * Eigen::Vector3d(step, 0.095 + 0.02 * u(rng), 0.0);
  target.right_foot.head<3>() = centre + r * Eigen::Vector3d(-step, -0.095 - 0.02 * u(rng), 0.0);
  target.left_foot(2) = 0.025 + 0.025 * u(rng);
  target.left_foot(3) = yaw + 0.1 * u(rng);
  target.right_foot(3) = yaw + 0.1 * u(rng);
  target.waist_yaw = 0.5 * (target.left_foot(3) + target.right_foot(3));
  target.com = centre + r * Eigen::Vector3d(0.02 * u(rng), 0.06 * u(rng), 0.0);
  target.com.z() = 0.814;
  return target;
}

// The analytic d CoM / d waist position (the Newton Jacobian of solve()) against central
// differences of the same CoM function.
TEST(WalkingIk, AnalyticComJacobianMatchesFiniteDifferences) {
  const RobotModel& model = hrp2();
  const WalkingIk ik(model);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd q(model.nq());
  double max_error = 0.0, max_off_identity = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const WalkingIkTarget target = randomWalkingTarget(rng);
    ASSERT_EQ(ik.solve(target, q).status, WalkingIkStatus::kSolved) << "trial " << trial;
    const Eigen::Vector3d waist =
        q.head<3>() + 0.01 * Eigen::Vector3d(u(rng), u(rng), u(rng));  // off the solution
    Eigen::Matrix3d analytic;
    const Eigen::Vector3d com = ik.comAtWaist(target, waist, &analytic);
    EXPECT_EQ(com, ik.comAtWaist(target, waist));  // the Jacobian does not change the CoM
    const double h = 1e-6;
    Eigen::Matrix3d numeric;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(i);
      numeric.col(i) = (ik.comAtWaist(target, waist + step) - ik.comAtWaist(target, waist - step)) /
                       (2.0 * h);
    }
    max_error = std::max(max_error, (analytic - numeric).cwiseAbs().maxCoeff());
    max_off_identity =
        std::max(max_off_identity, (analytic - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
  }
  std::printf("CoM / waist Jacobian: analytic - central differences max %.2e (entries differ from "
              "the identity by up to %.2f)\n", max_error, max_off_identity);
  EXPECT_LT(max_error, 1e-8);
  EXPECT_GT(max_off_identity, 0.05);  // the legs' share: not a trivial identity
}

// The warm start of solveTrajectory (extrapolated from the previous samples) converges to the
// same configurations as independent solves, in fewer CoM evaluations.
TEST(WalkingIk, WarmStartedTrajectoryMatchesIndependentSolves) {
  const RobotModel& model = hrp2();
  const WalkingIk ik(model);
  wpg::WalkTrajectory walk;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const double t = 0.005 * i;
    walk.time.push_back(t);
    walk.com.emplace_back(0.1 * t, 0.05 * std::sin(2 * M_PI * t), 0.814);
    walk.left_foot.emplace_back(0.0, 0.095, 0.0, 0.1 * t);
    walk.right_foot.emplace_back(0.1 * t, -0.095, 0.04 * std::sin(M_PI * t), 0.0);
    walk.free_flyer_yaw.push_back(0.05 * t);
  }
  const auto out = ik.solveTrajectory(walk);
  ASSERT_EQ(out.failures, 0);
  Eigen::VectorXd q(model.nq());
  double max_difference = 0.0;
  int warm_evaluations = 0, cold_evaluations = 0;
  for (int i = 0; i < n; ++i) {
    WalkingIkTarget target;
    target.left_foot = walk.left_foot[i];
    target.right_foot = walk.right_foot[i];
    target.com = walk.com[i];
    target.waist_yaw = walk.free_flyer_yaw[i];
    cold_evaluations += ik.solve(target, q).iterations;
    warm_evaluations += out.samples[i].iterations;
    max_difference = std::max(max_difference, (out.q.row(i).transpose() - q).cwiseAbs().maxCoeff());
  }
  std::printf("warm-started IK: max |q - q(independent)| %.2e, %d vs %d CoM evaluations\n",
              max_difference, warm_evaluations, cold_evaluations);
  EXPECT_LT(max_difference, 1e-10);
  EXPECT_LT(2 * warm_evaluations, cold_evaluations);
}

}  // namespace
