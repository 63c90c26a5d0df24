// Warnings of the scenario loader (Scenario::warnings, datasets/SCENARIOS.md, "Warnings"): a
// commanded velocity beyond the robot's clamp, a CoM height outside the robot's plausible range,
// a goal yaw beyond a turn. One line each naming the file, the key, the value given and what
// happens; the scenario itself (what walks) is unchanged; no shipped scenario or study warns.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scenario_files.hpp"
#include "wpg/datasets/study_design/comparison_study.hpp"
#include "wpg/datasets/study_design/study.hpp"

namespace {

namespace fs = std::filesystem;
using wpg::datasets::Scenario;
using wpg_test::kRobotsDir;
using wpg_test::loadShipped;
using wpg_test::shipped;

// The one warning of `scenario`, which must hold every one of `parts`.
void expectOneWarning(const Scenario& scenario, std::initializer_list<std::string> parts) {
  ASSERT_EQ(scenario.warnings.size(), 1u);
  const std::string& line = scenario.warnings.front();
  EXPECT_EQ(line.find('\n'), std::string::npos) << line;
  for (const std::string& part : parts) {
    EXPECT_NE(line.find(part), std::string::npos) << "'" << part << "' not in: " << line;
  }
}

TEST(ScenarioWarnings, CommandBeyondTheClampWarnsAndIsKept) {
  const Scenario s = loadShipped("walk_forward", {"reference[1].v=[2.0, 0.0, 0.0]"});
  expectOneWarning(
      s, {"walk_forward.yaml", "key 'reference[1].v[0]'", "2.0 m/s", "walking.max_forward_velocity",
          "0.4 m/s", "clamped", "set by --set 'reference[1].v=[2.0, 0.0, 0.0]'"});
  // The scenario says what was asked; the generator clamps (the walk is that of 0.4 m/s).
  EXPECT_DOUBLE_EQ(s.request.reference[1].velocity.x(), 2.0);
  const Scenario lateral = loadShipped("walk_forward", {"reference[1].v=[0.05, -0.5, 0.0]"});
  // Clamped to -0.3 m/s, which the gait does not reach either: a second line says so.
  ASSERT_EQ(lateral.warnings.size(), 2u);
  EXPECT_NE(lateral.warnings[0].find("key 'reference[1].v[1]': -0.5 m/s is beyond walking."
                                     "max_lateral_velocity"), std::string::npos)
      << lateral.warnings[0];
  EXPECT_NE(lateral.warnings[1].find("key 'reference[1].v': [0.05, -0.5, 0.0] is beyond the "
                                     "reach of the gait"), std::string::npos)
      << lateral.warnings[1];
  const Scenario turn = loadShipped("walk_forward", {"reference[1].v=[0.1, 0.0, 1.0]"});
  expectOneWarning(turn, {"key 'reference[1].v[2]'", "1.0 rad/s", "max_angular_velocity"});
  // At the clamp exactly: nothing is clamped (0.4 m/s forward, which the gait reaches).
  EXPECT_TRUE(loadShipped("walk_forward", {"reference[1].v=[0.4, 0.0, 0.0]"}).warnings.empty());
}

TEST(ScenarioWarnings, CommandBeyondTheGaitsReachWarns) {
  // 0.3 m/s sideways is at the clamp, but HRP-2's shortest steps (0.5 s) reach 0.2 m/s.
  const Scenario s = loadShipped("walk_forward", {"reference[1].v=[0.0, 0.3, 0.0]"});
  expectOneWarning(s, {"key 'reference[1].v'", "beyond the reach of the gait", "steps of 0.5 s",
                       "66% of it", "falls behind the command and may fall",
                       "set by --set 'reference[1].v=[0.0, 0.3, 0.0]'"});
  EXPECT_TRUE(loadShipped("walk_forward", {"reference[1].v=[0.0, 0.15, 0.0]"}).warnings.empty());
  // The paper's fixed timing keeps its 0.8 s steps: 0.15 m/s sideways is beyond them.
  expectOneWarning(loadShipped("walk_forward", {"reference[1].v=[0.0, 0.15, 0.0]",
                                                "walking.step_timing=fixed"}),
                   {"steps of 0.8 s"});
}

TEST(ScenarioWarnings, TurnBeyondTheStepYawBoundWarns) {
  // 0.2 rad/s x 0.8 s per step = 0.16 rad a step, beyond a yaw bound of 0.05 rad.
  const Scenario s = loadShipped(
      "walk_forward", {"reference[1].v=[0.1, 0.0, 0.2]", "walking.max_step_yaw_change=0.05"});
  expectOneWarning(
      s, {"key 'reference[1].v[2]'", "0.2 rad/s", "walking.max_step_yaw_change", "0.05 rad"});
}

TEST(ScenarioWarnings, ImplausibleComHeightWarns) {
  const Scenario cm = loadShipped("walk_forward", {"walking.com_height=81.4"});
  expectOneWarning(cm, {"key 'walking.com_height'", "81.4 m", "hrp2", "plausible"});
  EXPECT_DOUBLE_EQ(cm.walking.com_height, 81.4);  // warned, not changed
  const Scenario low = loadShipped("walk_forward", {"walking.com_height=0.2"});
  expectOneWarning(low, {"key 'walking.com_height'", "0.2 m"});
  // The range of the shipped study (0.78 to 0.84 m) is plausible.
  EXPECT_TRUE(loadShipped("walk_forward", {"walking.com_height=0.78"}).warnings.empty());
  EXPECT_TRUE(loadShipped("walk_forward", {"walking.com_height=0.84"}).warnings.empty());
}

TEST(ScenarioWarnings, GoalYawBeyondATurnWarns) {
  const Scenario s = loadShipped("goal_with_yaw", {"goal.yaw=90"});
  expectOneWarning(s, {"goal_with_yaw.yaml", "key 'goal.yaw'", "90", "rad", "degrees"});
  EXPECT_DOUBLE_EQ(s.goal.goal.yaw, 90.0);
  EXPECT_TRUE(loadShipped("goal_with_yaw", {"goal.yaw=-3.1"}).warnings.empty());
  const Scenario box = loadShipped("goal_cluttered", {"obstacles[1].yaw=30"});
  expectOneWarning(box, {"goal_cluttered.yaml", "key 'obstacles[1].yaw'", "30.0 rad", "degrees"});
}

TEST(ScenarioWarnings, ResolvedScenarioWarnsAgain) {
  const Scenario s = loadShipped("walk_forward", {"reference[1].v=[2.0, 0.0, 0.0]"});
  const Scenario again =
      wpg::datasets::loadScenarioText(resolvedScenarioText(s), "stored", {}, kRobotsDir);
  ASSERT_EQ(again.warnings.size(), 1u);
  EXPECT_NE(again.warnings.front().find("stored: key 'reference[1].v[0]'"), std::string::npos);
}

TEST(ScenarioWarnings, NoShippedScenarioWarns) {
  for (const fs::directory_entry& file : fs::directory_iterator(wpg_test::kScenariosDir)) {
    if (file.path().extension() != ".yaml") continue;
    const Scenario s = wpg::datasets::loadScenario(file.path().string(), {}, kRobotsDir);
    EXPECT_TRUE(s.warnings.empty())
        << file.path() << ": " << (s.warnings.empty() ? "" : s.warnings[0]);
  }
}

TEST(ScenarioWarnings, NoRunOfAShippedStudyWarns) {
  const auto resolve = [](const std::string& base) {
    return wpg_test::kScenariosDir + "/" + base + ".yaml";
  };
  int studies = 0;
  for (const fs::directory_entry& file :
       fs::directory_iterator(wpg_test::kSourceDir + "/datasets/studies")) {
    if (file.path().extension() != ".yaml") continue;
    std::stringstream text;
    text << std::ifstream(file.path()).rdbuf();
    const bool comparison = text.str().find("\nworlds:") != std::string::npos;
    const wpg::datasets::Study study =
        comparison
            ? wpg::datasets::loadComparisonStudy(file.path().string(), resolve, kRobotsDir, 2).study
            : wpg::datasets::loadStudy(file.path().string(), resolve, kRobotsDir, 2);
    ++studies;
    for (const wpg::datasets::StudyRun& run : study.runs) {
      EXPECT_TRUE(run.scenario.warnings.empty())
          << file.path() << " " << run.name << ": "
          << (run.scenario.warnings.empty() ? "" : run.scenario.warnings[0]);
    }
  }
  EXPECT_GE(studies, 6);
}

TEST(ScenarioWarnings, StudyRunsNameTheSweep) {
  const fs::path path = fs::temp_directory_path() / "wpg_test_warning_study.yaml";
  std::ofstream(path) << "name: fast\nbase: walk_forward\nsweep:\n  grid:\n"
                         "    \"reference[1].v\": [[0.2, 0, 0], [1.0, 0, 0]]\n";
  const wpg::datasets::Study study = wpg::datasets::loadStudy(
      path.string(),
      [](const std::string& base) { return wpg_test::kScenariosDir + "/" + base + ".yaml"; },
      kRobotsDir, 1);
  fs::remove(path);
  ASSERT_EQ(study.runs.size(), 2u);
  EXPECT_TRUE(study.runs[0].scenario.warnings.empty());
  expectOneWarning(study.runs[1].scenario,
                   {"wpg_test_warning_study.yaml: run 1", "key 'reference[1].v[0]'", "1.0 m/s",
                    "sweep 'reference[1].v="});
}

}  // namespace
