// The multibody ZMP from the momentum rate (momentum_zmp.hpp) against Simbody's inverse
// dynamics (multibody_replay.hpp) on motions where every joint, the base position and its
// orientation move; the welding of constant joints; no allocation on a second run of a window.
// The agreement on every sample of the shipped walks: test_momentum_zmp_shipped_walks.cpp.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "alloc_counter.hpp"
#include "hrp2_model.hpp"
#include "wpg/robots/momentum_zmp.hpp"
#include "wpg/robots/multibody_replay.hpp"
#include "wpg/robots/robot_model.hpp"

namespace {

using wpg::robots::MomentumZmp;
using wpg::robots::MultibodyReplay;
using wpg::robots::RobotModel;

constexpr double kGravity = 9.81;
constexpr double kDt = 0.005;

using wpg_test::hrp2;

// 0.4 s of a motion far from walking: the base translates, turns about a tilted axis and
// accelerates; every joint swings (amplitude 0.3 rad, its own frequency and phase), or only
// the legs when `legs_only` (the upper body then held at `arm_offset` from half-sitting).
Eigen::MatrixXd wildMotion(const RobotModel& model, bool legs_only, double arm_offset = 0.0) {
  const int n = 81;
  const Eigen::VectorXd q0 = model.halfSitting();
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, -0.4, 1.0).normalized();
  Eigen::MatrixXd q(n, model.nq());
  for (int k = 0; k < n; ++k) {
    const double t = kDt * k;
    Eigen::VectorXd qk = q0;
    RobotModel::setFreeFlyer(
        qk, q0.head<3>() + Eigen::Vector3d(0.3 * t + 0.5 * t * t, 0.05 * std::sin(7.0 * t), 0.02 * t),
        Eigen::Quaterniond(Eigen::AngleAxisd(0.8 * t + 1.5 * t * t, axis)));
    for (int j = 0; j < model.jointCount(); ++j) {
      if (!legs_only || j < 12) {
        qk(7 + j) += 0.3 * std::sin((2.0 + 0.37 * j) * t + 0.5 * j);
      } else {
        qk(7 + j) += arm_offset;
      }
    }
    q.row(k) = qk.transpose();
  }
  return q;
}

// Every joint moves: nothing welded, 31 bodies; the wrench, ZMP and CoM are Simbody's (full
// system, joint torques on) to round-off.
TEST(MomentumZmp, AgreesWithSimbodyWhenEveryJointMoves) {
  const RobotModel& model = hrp2();
  MultibodyReplay simbody(model);
  MomentumZmp momentum(model, kGravity);
  const Eigen::MatrixXd q = wildMotion(model, false);
  const auto expected = simbody.run(q, kDt);
  const auto& result = momentum.run(q, kDt);
  EXPECT_EQ(momentum.bodyCount(), static_cast<int>(model.bodies().size()));
  const double wrench = (result.base_wrench - expected.base_wrench).cwiseAbs().maxCoeff();
  const double zmp = (result.zmp - expected.zmp).cwiseAbs().maxCoeff();
  const double com = (result.com - expected.com).cwiseAbs().maxCoeff();
  std::printf("every joint moving, momentum rate vs Simbody: wrench %.2e, ZMP %.2e m, CoM %.2e m "
              "(wrench up to %.0f)\n", wrench, zmp, com, expected.base_wrench.cwiseAbs().maxCoeff());
  EXPECT_EQ(result.velocity, expected.velocity);
  EXPECT_EQ(result.acceleration, expected.acceleration);
  EXPECT_EQ(result.joint_torques.rows(), 0);
  EXPECT_LT(wrench, 1e-9);
  EXPECT_LT(zmp, 1e-12);
  EXPECT_LT(com, 1e-14);
  // far from static: the motion's own terms move the ZMP by centimetres
  EXPECT_GT((expected.zmp - expected.com.leftCols<2>()).cwiseAbs().maxCoeff(), 0.05);
}

// An external force at the CoM: the ground's share, as MultibodyReplay's.
TEST(MomentumZmp, SubtractsAForceAtTheComAsSimbody) {
  const RobotModel& model = hrp2();
  MultibodyReplay simbody(model);
  MomentumZmp momentum(model, kGravity);
  const Eigen::MatrixXd q = wildMotion(model, true, 0.2);
  Eigen::MatrixXd force(q.rows(), 3);
  for (Eigen::Index k = 0; k < q.rows(); ++k) force.row(k) << 40.0 * std::sin(0.1 * k), -25.0, 10.0;
  const auto expected = simbody.run(q, kDt, force);
  const auto result = momentum.run(q, kDt, force);  // a copy: run() below overwrites it
  EXPECT_LT((result.zmp - expected.zmp).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((result.base_wrench - expected.base_wrench).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT((result.zmp - momentum.run(q, kDt).zmp).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_THROW(momentum.run(q, kDt, force.topRows(3)), std::invalid_argument);
}

// The upper body held: 13 bodies (the root with the upper body, 6 per leg); another held
// posture (an arm offset) or a moving chest rebuilds the welded tree, each time equal to
// Simbody's full system.
TEST(MomentumZmp, WeldsTheJointsConstantOverARun) {
  const RobotModel& model = hrp2();
  MultibodyReplay simbody(model);
  MomentumZmp momentum(model, kGravity);
  double zmp = 0.0;
  for (double arm_offset : {0.0, 0.4}) {
    const Eigen::MatrixXd q = wildMotion(model, true, arm_offset);
    const auto expected = simbody.run(q, kDt);
    const auto& result = momentum.run(q, kDt);
    EXPECT_EQ(momentum.bodyCount(), 13);
    zmp = std::max(zmp, (result.zmp - expected.zmp).cwiseAbs().maxCoeff());
    EXPECT_LT((result.com - expected.com).cwiseAbs().maxCoeff(), 1e-14);
  }
  Eigen::MatrixXd q = wildMotion(model, true, 0.4);
  const int chest = 7 + model.jointIndex("CHEST_JOINT0");
  for (Eigen::Index k = 0; k < q.rows(); ++k) q(k, chest) += 0.5 * (kDt * k) * (kDt * k);
  const auto expected = simbody.run(q, kDt);
  const auto& result = momentum.run(q, kDt);
  EXPECT_EQ(momentum.bodyCount(), 14);
  zmp = std::max(zmp, (result.zmp - expected.zmp).cwiseAbs().maxCoeff());
  EXPECT_LT(zmp, 1e-12);
}

// Joints that are not a turn about a coordinate axis of their parent's frame (rotated joint
// frames, a tilted axis, a slider on a rotated frame): the general path, against Simbody.
TEST(MomentumZmp, AgreesWithSimbodyOnRotatedJointFramesAndSliders) {
  const std::string path = ::testing::TempDir() + "/wpg_momentum_zmp_robot.urdf";
  {
    std::ofstream out(path);
    const char* inertia = "<inertia ixx='0.02' ixy='0.001' ixz='0' iyy='0.03' iyz='0.002' izz='0.04'/>";
    out << "<robot name='arms'>"
           "<link name='base'><inertial><origin xyz='0 0 0.1'/><mass value='5'/>" << inertia
        << "</inertial></link>"
           "<joint name='tilted' type='revolute'><parent link='base'/><child link='a'/>"
           "<origin xyz='0.1 0 0.2' rpy='0.3 -0.2 0.5'/><axis xyz='0.6 0 0.8'/>"
           "<limit lower='-2' upper='2' effort='10' velocity='5'/></joint>"
           "<link name='a'><inertial><origin xyz='0.05 0.02 0'/><mass value='1.5'/>" << inertia
        << "</inertial></link>"
           "<joint name='pitch' type='continuous'><parent link='a'/><child link='b'/>"
           "<origin xyz='0 0.1 0' rpy='0 0 0'/><axis xyz='0 1 0'/></joint>"
           "<link name='b'><inertial><origin xyz='0 0 -0.1'/><mass value='1'/>" << inertia
        << "</inertial></link>"
           "<joint name='slide' type='prismatic'><parent link='b'/><child link='c'/>"
           "<origin xyz='0 0 -0.2' rpy='0 0.4 0'/><axis xyz='1 0 0'/>"
           "<limit lower='-1' upper='1' effort='10' velocity='1'/></joint>"
           "<link name='c'><inertial><origin xyz='0.02 0 0'/><mass value='0.7'/>" << inertia
        << "</inertial></link>"
           "<joint name='roll' type='revolute'><parent link='base'/><child link='d'/>"
           "<origin xyz='0 -0.1 0' rpy='0.7 0 0'/><axis xyz='1 0 0'/>"
           "<limit lower='-2' upper='2' effort='10' velocity='5'/></joint>"
           "<link name='d'><inertial><origin xyz='0 0 -0.05'/><mass value='0.8'/>" << inertia
        << "</inertial></link></robot>";
  }
  const RobotModel model(path);
  ASSERT_EQ(model.jointCount(), 4);
  const int n = 61;
  Eigen::MatrixXd q(n, model.nq());
  for (int k = 0; k < n; ++k) {
    const double t = kDt * k;
    Eigen::VectorXd qk = model.neutralConfiguration();
    RobotModel::setFreeFlyer(qk, Eigen::Vector3d(0.2 * t, 0.1 * t * t, 0.8 + 0.05 * std::sin(4 * t)),
                             Eigen::Quaterniond(Eigen::AngleAxisd(
                                 0.5 + 2.0 * t, Eigen::Vector3d(0.3, 0.5, 0.8).normalized())));
    for (int j = 0; j < 4; ++j) qk(7 + j) = 0.4 * std::sin((3.0 + j) * t + j);
    q.row(k) = qk.transpose();
  }
  MultibodyReplay simbody(model);
  MomentumZmp momentum(model, kGravity);
  const auto expected = simbody.run(q, kDt);
  const auto& result = momentum.run(q, kDt);
  EXPECT_EQ(momentum.bodyCount(), 5);
  EXPECT_LT((result.base_wrench - expected.base_wrench).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_LT((result.zmp - expected.zmp).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((result.com - expected.com).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_GT((expected.zmp - expected.com.leftCols<2>()).cwiseAbs().maxCoeff(), 0.01);
}

// Standing still: the ZMP is the CoM's projection, the force the weight.
TEST(MomentumZmp, StaticPoseZmpIsTheComProjection) {
  const RobotModel& model = hrp2();
  MomentumZmp momentum(model, kGravity);
  const Eigen::VectorXd q0 = model.halfSitting();
  const auto& result = momentum.run(q0.transpose().replicate(5, 1), kDt);
  const Eigen::Vector3d com = model.centerOfMass(q0);
  for (int k = 0; k < 5; ++k) {
    EXPECT_LT((result.zmp.row(k).transpose() - com.head<2>()).norm(), 1e-12);
    EXPECT_LT((result.com.row(k).transpose() - com).norm(), 1e-14);
    EXPECT_NEAR(result.base_wrench(k, 5), model.totalMass() * kGravity, 1e-9);
  }
}

// The filter's window at every NMPC iteration: a second run of the same size and welded set
// does not allocate.
TEST(MomentumZmp, SecondRunOfAWindowDoesNotAllocate) {
  const RobotModel& model = hrp2();
  MomentumZmp momentum(model, kGravity);
  const Eigen::MatrixXd first = wildMotion(model, true, 0.1);
  Eigen::MatrixXd second = first;
  second.col(0).array() += 0.01;  // another window: the base elsewhere, the same held joints
  momentum.run(first, kDt);
  const long before = wpg_test::allocationCount();
  momentum.run(second, kDt);
  EXPECT_EQ(wpg_test::allocationCount() - before, 0);
}

TEST(MomentumZmp, RejectsBadTrajectories) {
  const RobotModel& model = hrp2();
  MomentumZmp momentum(model, kGravity);
  const Eigen::MatrixXd q = wildMotion(model, true);
  EXPECT_THROW(momentum.run(q.topRows(2), kDt), std::invalid_argument);
  EXPECT_THROW(momentum.run(q.leftCols(10), kDt), std::invalid_argument);
  EXPECT_THROW(momentum.run(q, 0.0), std::invalid_argument);
  Eigen::MatrixXd bad = q;
  bad(4, 3) = 2.0;  // not a unit quaternion
  EXPECT_THROW(momentum.run(bad, kDt), std::invalid_argument);
  bad = q;
  bad(4, 9) = std::nan("");
  EXPECT_THROW(momentum.run(bad, kDt), std::invalid_argument);
  EXPECT_THROW(MomentumZmp(model, -1.0), std::invalid_argument);
}

}  // namespace
