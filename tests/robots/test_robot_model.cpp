// HRP-2 URDF and RobotModel against values computed independently from the transcribed Klamp't
// model (robots/hrp2/README.md, "Checks").
#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "wpg/robots/robot_model.hpp"
#include "../common/source_dir.hpp"

namespace {

using wpg::robots::Pose;
using wpg::robots::RobotModel;

const std::string kUrdf = std::string(wpg_test::sourceDir()) + "/robots/hrp2/hrp2.urdf";

const RobotModel& hrp2() {
  static const RobotModel model(kUrdf);
  return model;
}

double degrees(double d) { return d * M_PI / 180.0; }

TEST(RobotModel, LoadsTheHrp2Urdf) {
  const RobotModel& model = hrp2();
  EXPECT_EQ(model.name(), "hrp2");
  EXPECT_EQ(model.jointCount(), 30);
  EXPECT_EQ(model.nq(), 37);
  EXPECT_EQ(model.nv(), 36);
  EXPECT_EQ(model.bodies().size(), 31u);  // BODY + 30
  EXPECT_EQ(model.frames().size(), 33u);  // + LLEG_SOLE, RLEG_SOLE
  EXPECT_EQ(model.bodies()[0].name, "BODY");
  // configuration order = the source model's (URDF document) order
  const std::vector<std::string> first = {"RLEG_JOINT0", "RLEG_JOINT1", "RLEG_JOINT2",
                                          "RLEG_JOINT3", "RLEG_JOINT4", "RLEG_JOINT5",
                                          "LLEG_JOINT0"};
  for (std::size_t k = 0; k < first.size(); ++k) EXPECT_EQ(model.jointNames()[k], first[k]);
  EXPECT_EQ(model.jointIndex("CHEST_JOINT0"), 12);
  EXPECT_EQ(model.jointIndex("HEAD_JOINT1"), 15);
  EXPECT_EQ(model.jointIndex("RARM_JOINT0"), 16);
  EXPECT_EQ(model.jointIndex("LARM_JOINT6"), 29);
  // bodies are topologically ordered and each actuated joint moves its own body
  for (std::size_t b = 1; b < model.bodies().size(); ++b) {
    EXPECT_LT(model.bodies()[b].parent, static_cast<int>(b));
    EXPECT_EQ(model.joints()[model.bodies()[b].joint].body, static_cast<int>(b));
  }
  EXPECT_THROW(model.jointIndex("NO_SUCH_JOINT"), std::invalid_argument);
  EXPECT_THROW(model.frameIndex("NO_SUCH_LINK"), std::invalid_argument);
}

TEST(RobotModel, MassAndInertiasAsInTheTable) {
  const RobotModel& model = hrp2();
  // the source model's total mass: 56.03715771 kg (acceptance: 0.1 kg)
  EXPECT_NEAR(model.totalMass(), 56.03715771, 1e-8);
  const auto& body = model.bodies()[0];
  EXPECT_DOUBLE_EQ(body.mass, 15.02949);
  EXPECT_DOUBLE_EQ(body.com.z(), 0.2200769);
  EXPECT_DOUBLE_EQ(body.inertia(0, 2), 0.00070696);
  EXPECT_DOUBLE_EQ(body.inertia(2, 0), 0.00070696);
  const auto& shank = model.bodies()[model.joints()[model.jointIndex("LLEG_JOINT3")].body];
  EXPECT_EQ(shank.name, "LLEG_LINK3");
  EXPECT_DOUBLE_EQ(shank.mass, 1.74762);
  EXPECT_DOUBLE_EQ(shank.com.y(), 0.05791638);
  EXPECT_DOUBLE_EQ(shank.inertia(1, 2), 0.00074527);
  double leg = 0.0;
  for (int k = 0; k < 6; ++k) leg += model.bodies()[model.joints()[k].body].mass;
  EXPECT_NEAR(leg, 8.09051, 1e-9);
}

TEST(RobotModel, JointAxesOriginsAndLimits) {
  const RobotModel& model = hrp2();
  const auto& hip_yaw = model.joints()[model.jointIndex("RLEG_JOINT0")];
  EXPECT_TRUE(hip_yaw.axis.isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(hip_yaw.origin.position.isApprox(Eigen::Vector3d(0, -0.06, 0)));
  EXPECT_NEAR(hip_yaw.lower, degrees(-45), 1e-15);
  EXPECT_NEAR(hip_yaw.upper, degrees(30), 1e-15);
  EXPECT_DOUBLE_EQ(hip_yaw.effort_limit, 100.0);
  EXPECT_DOUBLE_EQ(hip_yaw.velocity_limit, 3.0);
  const auto& ankle = model.joints()[model.jointIndex("LLEG_JOINT4")];
  EXPECT_TRUE(ankle.axis.isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(ankle.origin.position.isApprox(Eigen::Vector3d(0, 0.035, -0.3)));
  const auto& gripper = model.joints()[model.jointIndex("LARM_JOINT6")];
  EXPECT_TRUE(gripper.origin.position.isApprox(Eigen::Vector3d(0.0219, 0, -0.095)));
  EXPECT_NEAR(gripper.lower, degrees(-60), 1e-15);
  EXPECT_NEAR(gripper.upper, degrees(16), 1e-15);
  // the sole frames: 0.105 m below the ankle-roll frames (the sole plane of the foot mesh)
  const auto& sole = model.frames()[model.frameIndex("RLEG_SOLE")];
  EXPECT_EQ(model.bodies()[sole.body].name, "RLEG_LINK5");
  EXPECT_TRUE(sole.placement.position.isApprox(Eigen::Vector3d(0, 0, -0.105)));
}

TEST(RobotModel, HalfSittingMatchesTheFactSheet) {
  const RobotModel& model = hrp2();
  const Eigen::VectorXd q = model.halfSitting();
  // the half-sitting check values: BODY at 0.648702, soles on z = 0
  EXPECT_NEAR(q(2), 0.648702, 1e-6);
  EXPECT_EQ(q.head<2>(), Eigen::Vector2d::Zero());
  EXPECT_NEAR(q(model.nq() - 1), 0.1, 0.0);  // LARM_JOINT6
  EXPECT_TRUE(model.jointLimitViolations(q).empty());

  const Eigen::Vector3d com = model.centerOfMass(q);
  const Eigen::Vector3d expected_com(0.012891, 0.001575, 0.808505);
  const double com_error = (com - expected_com).norm();
  RecordProperty("half_sitting_com_error_m", std::to_string(com_error));
  std::printf("half-sitting CoM (%.6f, %.6f, %.6f), fact sheet error %.2e m\n", com.x(), com.y(),
              com.z(), com_error);
  EXPECT_LT(com_error, 1e-3);  // acceptance: 1 mm
  EXPECT_LT(com_error, 2e-6);  // the check values have 6 decimals

  for (const char* side : {"R", "L"}) {
    const double sign = side[0] == 'R' ? -1.0 : 1.0;
    const Pose ankle = model.framePose(q, std::string(side) + "LEG_LINK5");
    EXPECT_LT((ankle.position - Eigen::Vector3d(0.009490, sign * 0.095, 0.105)).norm(), 1e-6);
    EXPECT_NEAR(ankle.position.z(), 0.105, 1e-12);
    EXPECT_NEAR(ankle.position.y(), sign * 0.095, 1e-12);
    EXPECT_LT((ankle.rotation - Eigen::Matrix3d::Identity()).norm(), 1e-6);
    const Pose sole = model.framePose(q, std::string(side) + "LEG_SOLE");
    EXPECT_NEAR(sole.position.z(), 0.0, 1e-12);
    const Pose knee = model.framePose(q, std::string(side) + "LEG_LINK3");
    EXPECT_LT((knee.position - Eigen::Vector3d(0.131511, sign * 0.06, 0.379064)).norm(), 1e-6);
  }
  // a few frame origins of section 3.4
  EXPECT_LT((model.framePose(q, "CHEST_LINK1").position - Eigen::Vector3d(0.032, 0, 0.996402)).norm(), 1e-6);
  EXPECT_LT((model.framePose(q, "HEAD_LINK1").position - Eigen::Vector3d(0.025, 0, 1.293702)).norm(), 1e-6);
  EXPECT_LT((model.framePose(q, "RARM_LINK3").position - Eigen::Vector3d(-0.023722, -0.293411, 0.939589)).norm(), 1e-6);
  EXPECT_LT((model.framePose(q, "RARM_LINK6").position - Eigen::Vector3d(0.085300, -0.341925, 0.625530)).norm(), 1e-6);
  EXPECT_LT((model.framePose(q, "LARM_LINK6").position - Eigen::Vector3d(0.087857, 0.343391, 0.616236)).norm(), 1e-6);
}

TEST(RobotModel, StraightLegsMatchTheFactSheet) {
  const RobotModel& model = hrp2();
  Eigen::VectorXd q = model.neutralConfiguration();
  q(2) = 0.705;  // the straight-leg check values
  EXPECT_LT((model.centerOfMass(q) - Eigen::Vector3d(0.005912, 0.001578, 0.854178)).norm(), 2e-6);
  EXPECT_NEAR(model.framePose(q, "LLEG_SOLE").position.z(), 0.0, 1e-12);
  EXPECT_LT((model.framePose(q, "RLEG_LINK4").position - Eigen::Vector3d(0, -0.095, 0.105)).norm(), 1e-12);
  EXPECT_LT((model.framePose(q, "LARM_LINK6").position - Eigen::Vector3d(0.0619, 0.25, 0.6387)).norm(), 1e-9);
}

TEST(RobotModel, FreeFlyerMovesTheWholeRobot) {
  const RobotModel& model = hrp2();
  const Eigen::VectorXd q0 = model.halfSitting();
  Eigen::VectorXd q = q0;
  const Eigen::Quaterniond rotation(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, -0.3, 1.0).normalized()));
  const Eigen::Vector3d shift(0.3, -0.2, 0.1);
  RobotModel::setFreeFlyer(q, q0.head<3>() + shift, rotation);
  const Eigen::Vector3d body = q0.head<3>();
  // CoM and frames transform rigidly about the BODY origin
  const Eigen::Vector3d expected = rotation * (model.centerOfMass(q0) - body) + body + shift;
  EXPECT_LT((model.centerOfMass(q) - expected).norm(), 1e-12);
  const Pose hand = model.framePose(q, "RARM_LINK6");
  EXPECT_LT((hand.position - (rotation * (model.framePose(q0, "RARM_LINK6").position - body) + body + shift)).norm(), 1e-12);
}

TEST(RobotModel, ChecksConfigurations) {
  const RobotModel& model = hrp2();
  EXPECT_THROW(model.centerOfMass(Eigen::VectorXd::Zero(36)), std::invalid_argument);
  Eigen::VectorXd q = model.neutralConfiguration();
  q(3) = 2.0;  // not a unit quaternion
  EXPECT_THROW(model.centerOfMass(q), std::invalid_argument);
  q = model.neutralConfiguration();
  q(7) = -1.0;  // RLEG_JOINT0 below -45 deg
  q(9) = 3.0;   // RLEG_JOINT2 above 42 deg
  EXPECT_EQ(model.jointLimitViolations(q), (std::vector<int>{0, 2}));
  EXPECT_THROW(model.referenceConfiguration("no_such_posture"), std::invalid_argument);
  EXPECT_EQ(model.referencePostureNames(), std::vector<std::string>{"half_sitting"});
}

TEST(RobotModel, BadFilesThrow) {
  EXPECT_THROW(RobotModel("/nonexistent/robot.urdf"), std::runtime_error);
  const std::string path = ::testing::TempDir() + "/wpg_bad_robot.urdf";
  {
    std::ofstream out(path);
    out << "<robot name='bad'><link name='a'/><joint name='j' type='floating'>"
           "<parent link='a'/><child link='b'/></joint><link name='b'/></robot>";
  }
  EXPECT_THROW(RobotModel{path}, std::runtime_error);
  {
    std::ofstream out(path);
    out << "<robot name='bad'><link name='a'";
  }
  EXPECT_THROW(RobotModel{path}, std::runtime_error);
}

TEST(RobotModel, FixedJointsAreMergedIntoTheirBody) {
  const std::string path = ::testing::TempDir() + "/wpg_fixed_robot.urdf";
  {
    std::ofstream out(path);
    out << R"(<robot name="two">
  <link name="base"><inertial><origin xyz="0 0 0.1"/><mass value="2"/>
    <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
  <joint name="weld" type="fixed"><parent link="base"/><child link="box"/>
    <origin xyz="0 0 -0.2" rpy="0 0 1.5707963267948966"/></joint>
  <link name="box"><inertial><origin xyz="0.1 0 0"/><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.03"/></inertial></link>
  <joint name="slide" type="prismatic"><parent link="box"/><child link="tip"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
  <link name="tip"><inertial><mass value="0.5"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
</robot>)";
  }
  const RobotModel model(path);
  ASSERT_EQ(model.bodies().size(), 2u);
  ASSERT_EQ(model.jointCount(), 1);
  const auto& base = model.bodies()[0];
  EXPECT_DOUBLE_EQ(base.mass, 3.0);
  // box com: rotated by 90 deg about z, at (0, 0.1, -0.2) in base
  EXPECT_TRUE(base.com.isApprox(Eigen::Vector3d(0, 0.1 / 3.0, (0.2 - 0.2) / 3.0), 1e-12));
  // box inertia rotated: its x and y moments swap in the base frame
  const Eigen::Vector3d c = base.com;
  const Eigen::Vector3d cb(0, 0, 0.1), cx(0, 0.1, -0.2);
  auto steiner = [](double m, const Eigen::Vector3d& r) {
    return Eigen::Matrix3d(m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose()));
  };
  const Eigen::Matrix3d expected = Eigen::Matrix3d::Identity() * 0.1 + steiner(2, cb - c) +
                                   Eigen::Vector3d(0.02, 0.01, 0.03).asDiagonal().toDenseMatrix() +
                                   steiner(1, cx - c);
  EXPECT_LT((base.inertia - expected).norm(), 1e-14);
  Eigen::VectorXd q = model.neutralConfiguration();
  q(7) = 0.3;
  EXPECT_LT((model.framePose(q, "tip").position - Eigen::Vector3d(0, 0, 0.1)).norm(), 1e-15);
  EXPECT_LT((model.framePose(q, "box").position - Eigen::Vector3d(0, 0, -0.2)).norm(), 1e-15);
}

}  // namespace
