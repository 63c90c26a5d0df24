// --set overrides of scenario files: scalars, nested keys and list indices, appended and created
// entries, the order in which they apply, the keys whose non-default values round-trip through
// the resolved YAML, and malformed overrides as one InputError line naming the key and the --set.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scenario_files.hpp"
#include "wpg/datasets/input/scenario.hpp"

using wpg::datasets::Scenario;
using wpg_test::kRobotsDir;
using wpg_test::kValidScenario;
using wpg_test::loadShipped;
using wpg_test::ScenarioFiles;

TEST(Overrides, ScalarsNestedKeysAndListIndices) {
  const Scenario s =
      loadShipped("walk_forward", {"duration=20", "generator.sqp_iterations=3",
                                   "generator.algorithm=lmpc",
                                   "walking.max_step_yaw_change=0.17",
                                   "reference[1].v=[0.3,0,0]", "walking.feasibility_y[2]=0.35"});
  EXPECT_DOUBLE_EQ(s.request.duration, 20.0);
  EXPECT_EQ(s.request.generator.sqp_iterations, 3);
  EXPECT_EQ(s.request.generator.algorithm, wpg::GeneratorAlgorithm::kLmpc);
  EXPECT_DOUBLE_EQ(s.walking.max_step_yaw_change, 0.17);
  EXPECT_EQ(s.request.reference[1].velocity, Eigen::Vector3d(0.3, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(s.walking.feasibility_y[2], 0.35);
  EXPECT_DOUBLE_EQ(s.walking.feasibility_y[1], 0.3);  // the rest of the robot's list stays
  EXPECT_NE(resolvedScenarioText(s).find("duration: 20.0"), std::string::npos)
      << resolvedScenarioText(s);
  EXPECT_NE(resolvedScenarioText(s).find("algorithm: lmpc"), std::string::npos)
      << resolvedScenarioText(s);
  EXPECT_NE(resolvedScenarioText(s).find("{t: 1.0, v: [0.3, 0.0, 0.0]}"), std::string::npos)
      << resolvedScenarioText(s);
}

TEST(Overrides, AppendAndCreate) {
  const Scenario s = loadShipped(
      "walk_forward", {"reference[2]={t: 5, v: [0, 0, 0]}", "pushes[0]={t: 2, force: [10, 0]}",
                       "pushes[0].duration=0.2", "robot_mass=60"});
  ASSERT_EQ(s.request.reference.size(), 3u);
  EXPECT_DOUBLE_EQ(s.request.reference[2].t, 5.0);
  ASSERT_EQ(s.request.pushes.size(), 1u);
  EXPECT_EQ(s.request.pushes[0].force, Eigen::Vector2d(10.0, 0.0));
  EXPECT_DOUBLE_EQ(s.request.pushes[0].duration, 0.2);
  EXPECT_DOUBLE_EQ(s.request.robot_mass, 60.0);
}

TEST(Overrides, LaterOverridesWinAndScenarioBeatsRobot) {
  // turn_on_the_spot sets 0.17 over the robot's 0.05; --set goes last.
  EXPECT_DOUBLE_EQ(loadShipped("turn_on_the_spot").walking.max_step_yaw_change, 0.17);
  const Scenario s = loadShipped("turn_on_the_spot", {"walking.max_step_yaw_change=0.1",
                                                      "walking.max_step_yaw_change=0.12"});
  EXPECT_DOUBLE_EQ(s.walking.max_step_yaw_change, 0.12);
}

TEST_F(ScenarioFiles, BadOverrides) {
  const std::string text = kValidScenario;
  expectError("o1.yaml", text, {"--set 'duration'", "key=value"}, {"duration"});
  expectError("o2.yaml", text, {"'reference[9]'", "out of range"}, {"reference[9].v=[0,0,0]"});
  expectError("o3.yaml", text, {"reference[x].v", "index"}, {"reference[x].v=1"});
  expectError("o4.yaml", text, {"'name.first'", "not a map"}, {"name.first=1"});
  expectError("o5.yaml", text, {"'duration'", "syntax error"}, {"duration=[1"});
  expectError("o6.yaml", text, {"key 'durration'", "unknown key", "--set 'durration=3'"},
              {"durration=3"});
  expectError("o7.yaml", text, {"key 'duration'", "got abc", "--set 'duration=abc'"},
              {"duration=abc"});
  expectError("o8.yaml", text, {"'reference[1].v'", "3 numbers", "--set"},
              {"reference[1].v=[1,2]"});
  expectError("o9.yaml", text, {"'walking.bogus'", "unknown key"}, {"walking.bogus=1"});
  expectError("o10.yaml", text, {"--set '=3'"}, {"=3"});
  expectError("o11.yaml", text, {"key 'robot'", "got nao", "--set 'robot=nao'"}, {"robot=nao"});
  expectError("o12.yaml", text, {"'walking.feasibility_x'", "5 numbers", "--set"},
              {"walking.feasibility_x[5]=1"});
  expectError("o13.yaml", text, {"'walking.feasibility_x[6]'", "out of range"},
              {"walking.feasibility_x[6]=1"});
}

// The non-default value (command is the default): the paper's support_foot.
TEST(Overrides, HeadingReferenceRoundTrips) {
  const Scenario s = loadShipped("walk_forward", {"walking.heading_reference=support_foot"});
  EXPECT_EQ(s.walking.heading_reference, wpg::HeadingReference::kSupportFoot);
  EXPECT_NE(resolvedScenarioText(s).find("heading_reference: support_foot"), std::string::npos);
  const Scenario again =
      wpg::datasets::loadScenarioText(resolvedScenarioText(s), "run.h5:/scenario", {}, kRobotsDir);
  EXPECT_EQ(again.walking.heading_reference, wpg::HeadingReference::kSupportFoot);
}

TEST(Overrides, ObstacleDistanceFormRoundTrips) {
  EXPECT_EQ(loadShipped("walk_forward").walking.obstacle_distance_form,
            wpg::ObstacleDistanceForm::kSoleClearance);
  const Scenario s = loadShipped("walk_forward", {"walking.obstacle_distance_form=paper"});
  EXPECT_EQ(s.walking.obstacle_distance_form, wpg::ObstacleDistanceForm::kPaper);
  EXPECT_NE(resolvedScenarioText(s).find("obstacle_distance_form: paper"), std::string::npos);
  const Scenario again =
      wpg::datasets::loadScenarioText(resolvedScenarioText(s), "run.h5:/scenario", {}, kRobotsDir);
  EXPECT_EQ(again.walking.obstacle_distance_form, wpg::ObstacleDistanceForm::kPaper);
}

TEST(Overrides, ObstacleLinearizationRoundTrips) {
  const Scenario defaults = loadShipped("walk_forward");
  EXPECT_EQ(defaults.walking.obstacle_linearization, wpg::ObstacleLinearization::kCommandTangent);
  const Scenario s = loadShipped("walk_forward", {"walking.obstacle_linearization=step"});
  EXPECT_EQ(s.walking.obstacle_linearization, wpg::ObstacleLinearization::kStep);
  EXPECT_NE(resolvedScenarioText(s).find("obstacle_linearization: step"), std::string::npos);
  const Scenario again =
      wpg::datasets::loadScenarioText(resolvedScenarioText(s), "run.h5:/scenario", {}, kRobotsDir);
  EXPECT_EQ(again.walking.obstacle_linearization, wpg::ObstacleLinearization::kStep);
}

TEST(Overrides, ObstacleLandingLinearizationRoundTrips) {
  const Scenario defaults = loadShipped("walk_forward");
  EXPECT_EQ(defaults.walking.obstacle_landing_linearization, wpg::ObstacleLinearization::kStep);
  const Scenario s =
      loadShipped("walk_forward", {"walking.obstacle_landing_linearization=command_tangent"});
  EXPECT_EQ(s.walking.obstacle_landing_linearization,
            wpg::ObstacleLinearization::kCommandTangent);
  EXPECT_NE(resolvedScenarioText(s).find("obstacle_landing_linearization: command_tangent"),
            std::string::npos);
  const Scenario again =
      wpg::datasets::loadScenarioText(resolvedScenarioText(s), "run.h5:/scenario", {}, kRobotsDir);
  EXPECT_EQ(again.walking.obstacle_landing_linearization,
            wpg::ObstacleLinearization::kCommandTangent);
}
