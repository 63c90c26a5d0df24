// Unknown keys and enumerated values in scenario files: the error names the nearest known one
// ("did you mean 'algorithm'?"), and planner names and enumerated walking values are read
// case-insensitively and stored by their canonical (lower-case) name.
#include <gtest/gtest.h>

#include <string>

#include "scenario_files.hpp"

namespace {

using wpg::datasets::loadScenario;
using wpg::datasets::loadScenarioText;
using wpg::datasets::Scenario;
using wpg_test::kRobotsDir;
using wpg_test::kValidScenario;
using wpg_test::replaced;
using wpg_test::ScenarioFiles;

TEST_F(ScenarioFiles, UnknownKeysSuggestTheNearestKnownKey) {
  expectError("top.yaml", replaced(kValidScenario, "duration: 5.0", "duraton: 5.0"),
              {"'duraton'", "did you mean 'duration'?"});
  expectError("walking.yaml", kValidScenario,
              {"'walking.com_heigth'", "did you mean 'com_height'?"}, {"walking.com_heigth=0.8"});
  expectError("generator.yaml", replaced(kValidScenario, "sqp_iterations: 1", "sqp_iteration: 1"),
              {"'generator.sqp_iteration'", "did you mean 'sqp_iterations'?"});
  const std::string goal = std::string("name: g\nrobot: hrp2\nduration: 5.0\n") +
                           "goal: {position: [1.0, 0.0]}\nplanner: {algoritm: rrtconnect}\n";
  expectError("planner.yaml", goal, {"'planner.algoritm'", "did you mean 'algorithm'?"});
  // The list of known keys stays in the message.
  expectError("list.yaml", goal, {"known keys of 'planner': algorithm, time_limit"});
}

TEST_F(ScenarioFiles, UnknownKeyFarFromEveryKeySuggestsNothing) {
  const std::string path = write("far.yaml", kValidScenario + std::string("zzzzzz: 1\n"));
  try {
    loadScenario(path, {}, kRobotsDir);
    FAIL() << "no error";
  } catch (const wpg::datasets::InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("did you mean"), std::string::npos) << e.what();
  }
}

TEST_F(ScenarioFiles, PlannerNamesAreCaseInsensitiveAndStoredCanonical) {
  const std::string goal = std::string("name: g\nrobot: hrp2\nduration: 5.0\n") +
                           "goal: {position: [1.0, 0.0]}\nplanner: {algorithm: RRTConnect}\n";
  const Scenario scenario = loadScenario(write("case.yaml", goal), {}, kRobotsDir);
  EXPECT_EQ(scenario.goal.planner.algorithm, "rrtconnect");
  EXPECT_NE(resolvedScenarioText(scenario).find("algorithm: rrtconnect"), std::string::npos);
  const Scenario set =
      loadScenario(write("case_set.yaml", goal), {"planner.algorithm=RRTstar"}, kRobotsDir);
  EXPECT_EQ(set.goal.planner.algorithm, "rrtstar");
}

TEST_F(ScenarioFiles, EnumeratedWalkingValuesAreCaseInsensitiveAndSuggested) {
  const Scenario scenario =
      loadScenario(write("enum.yaml", kValidScenario),
                   {"walking.obstacle_linearization=Command_Tangent"}, kRobotsDir);
  EXPECT_EQ(scenario.walking.obstacle_linearization, wpg::ObstacleLinearization::kCommandTangent);
  EXPECT_NE(resolvedScenarioText(scenario).find("obstacle_linearization: command_tangent"),
            std::string::npos);
  expectError("enum_typo.yaml", kValidScenario,
              {"walking.obstacle_linearization", "step or command_tangent",
               "did you mean 'command_tangent'?"},
              {"walking.obstacle_linearization=comand_tangent"});
  expectError("enum_typo2.yaml", kValidScenario,
              {"walking.velocity_tracking", "did you mean 'with_sway'?"},
              {"walking.velocity_tracking=withsway"});
}

}  // namespace
