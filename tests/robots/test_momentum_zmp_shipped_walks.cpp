// The filter's multibody ZMP (the momentum rate of the kinematics, momentum_zmp.hpp) is
// Simbody's inverse dynamics (multibody_replay.hpp) within 1e-9 m on every sample of every
// shipped walk: each scenario of datasets/scenarios walked as `wpg run` walks it (the goal
// walks through the route planner), the walking IK of its motion, both ZMPs with its pushes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/planning/goal_walk.hpp"
#include "wpg/robots/momentum_zmp.hpp"
#include "wpg/robots/multibody_replay.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"
#include "wpg/walk_generator.hpp"
#include "../common/source_dir.hpp"

namespace {

const std::string kSource = wpg_test::sourceDir();

// Every shipped scenario; in the sanitizer tree one of each kind (WPG_SANITIZER_WALK_KINDS,
// comma-separated, from tests/CMakeLists.txt). The momentum rate and Simbody run the same code
// on every walk, with other numbers: under ASan the 28 took 16 s of CPU, the 7 take 5 s.
std::vector<std::string> shippedScenarios() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/datasets/scenarios"))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
#ifdef WPG_SANITIZER_WALK_KINDS
  std::set<std::string> kinds;
  std::stringstream list(WPG_SANITIZER_WALK_KINDS);
  for (std::string kind; std::getline(list, kind, ',');) kinds.insert(kind);
  names.erase(std::remove_if(names.begin(), names.end(),
                             [&](const std::string& name) { return kinds.count(name) == 0; }),
              names.end());
#endif
  std::sort(names.begin(), names.end());
  return names;
}

class ShippedWalkZmp : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedWalkZmp, MomentumRateIsSimbodysInverseDynamics) {
  const wpg::datasets::Scenario scenario = wpg::datasets::loadScenario(
      kSource + "/datasets/scenarios/" + GetParam() + ".yaml", {}, kSource + "/robots");
  const wpg::WalkTrajectory walk =
      scenario.goal.enabled
          ? wpg::planning::walkToGoal(scenario.walking, scenario.request, scenario.goal).walk.trajectory
          : wpg::generateWalk(scenario.walking, scenario.request).trajectory;
  ASSERT_GE(walk.size(), 3u);
  static const wpg::robots::RobotModel model(kSource + "/robots/hrp2/hrp2.urdf");
  const wpg::robots::WalkingIk ik(model);
  const wpg::robots::WalkingIkTrajectory motion = ik.solveTrajectory(walk);
  const Eigen::Index n = motion.q.rows();
  Eigen::MatrixXd com_force = Eigen::MatrixXd::Zero(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    com_force.row(i).head<2>() = scenario.request.robot_mass *
                                 scenario.request.pushAccelerationAt(walk.time[i]).transpose();
  const double dt = scenario.walking.control_period;
  wpg::robots::MultibodyReplaySettings settings;
  settings.gravity = scenario.walking.gravity;
  settings.joint_torques = false;
  wpg::robots::MultibodyReplay simbody(model, settings);
  wpg::robots::MomentumZmp momentum(model, scenario.walking.gravity);
  const Eigen::MatrixXd& expected = simbody.run(motion.q, dt, com_force).zmp;
  const Eigen::MatrixXd& zmp = momentum.run(motion.q, dt, com_force).zmp;
  double largest = 0.0, largest_offset = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int c = 0; c < 2; ++c) {
      // Both NaN where the ground would pull (f_z <= 0), else both finite.
      ASSERT_EQ(std::isnan(zmp(i, c)), std::isnan(expected(i, c))) << "sample " << i;
      if (std::isnan(zmp(i, c))) continue;
      largest = std::max(largest, std::abs(zmp(i, c) - expected(i, c)));
      largest_offset = std::max(largest_offset, std::abs(expected(i, c) - walk.com[i](c)));
    }
  }
  std::printf("%s: %td samples, |ZMP(momentum rate) - ZMP(Simbody)| max %.2e m\n",
              GetParam().c_str(), n, largest);
  RecordProperty("max_zmp_difference_m", std::to_string(largest));
  EXPECT_LE(largest, 1e-9);
  EXPECT_GT(largest_offset, 1e-3);  // a walk: the ZMP leaves the CoM's projection
}

INSTANTIATE_TEST_SUITE_P(Scenarios, ShippedWalkZmp, ::testing::ValuesIn(shippedScenarios()),
                         [](const auto& info) { return info.param; });

}  // namespace
