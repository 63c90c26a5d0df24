// Scenario files: the shipped ones load with the expected values, every malformed input is
// an InputError naming the file and the key, the resolved YAML reproduces the scenario (the
// --set overrides: test_scenario_overrides.cpp).
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "scenario_files.hpp"
#include "test_support.hpp"
#include "wpg/datasets/input/scenario.hpp"

namespace fs = std::filesystem;
using wpg::datasets::InputError;
using wpg::datasets::loadScenario;
using wpg::datasets::Scenario;

namespace {

using wpg_test::kRobotsDir;
using wpg_test::kScenariosDir;
using wpg_test::kValidScenario;
using wpg_test::loadShipped;
using wpg_test::replaced;
using wpg_test::ScenarioFiles;
using wpg_test::shipped;

// ---------------------------------------------------------------------------------------------
// Shipped scenarios
// ---------------------------------------------------------------------------------------------

TEST(ShippedScenarios, EveryFileLoads) {
  int count = 0;
  for (const auto& item : fs::directory_iterator(kScenariosDir)) {
    if (item.path().extension() != ".yaml") continue;
    ++count;
    SCOPED_TRACE(item.path().string());
    Scenario scenario;
    ASSERT_NO_THROW(scenario = loadScenario(item.path().string(), {}, kRobotsDir));
    EXPECT_EQ(scenario.name, item.path().stem().string()) << "name: should match the file name";
    EXPECT_EQ(scenario.robot, "hrp2");
    EXPECT_EQ(scenario.source_path, item.path().string());
    EXPECT_FALSE(resolvedScenarioText(scenario).empty());
    EXPECT_DOUBLE_EQ(scenario.request.robot_mass, 56.037);
    EXPECT_EQ(scenario.request.generator.algorithm, wpg::GeneratorAlgorithm::kNmpc);
    EXPECT_EQ(scenario.request.generator.sqp_iterations, 1);
  }
  EXPECT_GE(count, 6);
}

TEST(ShippedScenarios, RobotFileRestatesTheStructDefaults) {
  const wpg::WalkingParameters defaults;
  const wpg::WalkingParameters loaded = loadShipped("walk_forward").walking;
  EXPECT_EQ(loaded.com_height, defaults.com_height);
  EXPECT_EQ(loaded.gravity, defaults.gravity);
  EXPECT_EQ(loaded.sampling_period, defaults.sampling_period);
  EXPECT_EQ(loaded.horizon_length, defaults.horizon_length);
  EXPECT_EQ(loaded.single_support_samples, defaults.single_support_samples);
  EXPECT_EQ(loaded.double_support_samples, defaults.double_support_samples);
  EXPECT_EQ(loaded.previewed_steps, defaults.previewed_steps);
  EXPECT_EQ(loaded.control_period, defaults.control_period);
  EXPECT_EQ(loaded.foot_length, defaults.foot_length);
  EXPECT_EQ(loaded.foot_width, defaults.foot_width);
  EXPECT_EQ(loaded.ankle_height, defaults.ankle_height);
  EXPECT_EQ(loaded.cop_margin_x, defaults.cop_margin_x);
  EXPECT_EQ(loaded.cop_margin_y, defaults.cop_margin_y);
  EXPECT_EQ(loaded.initial_foot_separation, defaults.initial_foot_separation);
  EXPECT_EQ(loaded.stop_foot_separation, defaults.stop_foot_separation);
  EXPECT_EQ(loaded.obstacle_foot_radius, defaults.obstacle_foot_radius);
  EXPECT_EQ(loaded.feasibility_x, defaults.feasibility_x);
  EXPECT_EQ(loaded.feasibility_y, defaults.feasibility_y);
  EXPECT_EQ(loaded.max_step_yaw_change, defaults.max_step_yaw_change);
  EXPECT_EQ(loaded.weight_velocity, defaults.weight_velocity);
  EXPECT_EQ(loaded.weight_yaw, defaults.weight_yaw);
  EXPECT_EQ(loaded.velocity_window_samples, defaults.velocity_window_samples);
  EXPECT_EQ(loaded.heading_reference, defaults.heading_reference);
  EXPECT_EQ(loaded.start_double_support_samples, defaults.start_double_support_samples);
  EXPECT_EQ(loaded.weight_cop, defaults.weight_cop);
  EXPECT_EQ(loaded.weight_jerk, defaults.weight_jerk);
  EXPECT_EQ(loaded.step_height, defaults.step_height);
  EXPECT_EQ(loaded.max_forward_velocity, defaults.max_forward_velocity);
  EXPECT_EQ(loaded.max_lateral_velocity, defaults.max_lateral_velocity);
  EXPECT_EQ(loaded.max_angular_velocity, defaults.max_angular_velocity);
}

TEST(ShippedScenarios, WalkForward) {
  const Scenario s = loadShipped("walk_forward");
  EXPECT_EQ(s.name, "walk_forward");
  EXPECT_DOUBLE_EQ(s.request.duration, 10.0);
  ASSERT_EQ(s.request.reference.size(), 2u);
  EXPECT_DOUBLE_EQ(s.request.reference[0].t, 0.0);
  EXPECT_EQ(s.request.reference[0].velocity, Eigen::Vector3d::Zero());
  EXPECT_DOUBLE_EQ(s.request.reference[1].t, 1.0);
  EXPECT_EQ(s.request.reference[1].velocity, Eigen::Vector3d(0.2, 0.0, 0.0));
  EXPECT_TRUE(s.request.pushes.empty());
  // The authors' code's bound, which the 0.2 rad/s clamp on omega needs (the paper: 0.05).
  EXPECT_DOUBLE_EQ(s.walking.max_step_yaw_change, 0.17);
  EXPECT_EQ(s.walking.heading_reference, wpg::HeadingReference::kCommand);
  // No multibody replay unless asked; the filter's classic Kajita settings.
  EXPECT_FALSE(s.replay);
  EXPECT_FALSE(s.filter);
  EXPECT_EQ(s.filter_settings.error_weight, 1.0);
  EXPECT_EQ(s.filter_settings.input_weight, 1e-6);
  EXPECT_EQ(s.filter_settings.preview_time, 1.6);
}

TEST(ShippedScenarios, WalkSideways) {
  const Scenario s = loadShipped("walk_sideways");
  ASSERT_EQ(s.request.reference.size(), 2u);
  EXPECT_EQ(s.request.reference[1].velocity, Eigen::Vector3d(0.0, 0.1, 0.0));
  EXPECT_DOUBLE_EQ(s.request.duration, 10.0);
}

TEST(ShippedScenarios, TurnOnTheSpot) {
  const Scenario s = loadShipped("turn_on_the_spot");
  ASSERT_EQ(s.request.reference.size(), 2u);
  EXPECT_EQ(s.request.reference[1].velocity, Eigen::Vector3d(0.0, 0.0, 0.2));
  EXPECT_DOUBLE_EQ(s.walking.max_step_yaw_change, 0.17);
}

TEST(ShippedScenarios, Curve) {
  const Scenario s = loadShipped("curve");
  ASSERT_EQ(s.request.reference.size(), 2u);
  EXPECT_EQ(s.request.reference[1].velocity, Eigen::Vector3d(0.2, 0.0, 0.2));
  EXPECT_DOUBLE_EQ(s.walking.max_step_yaw_change, 0.17);
  EXPECT_DOUBLE_EQ(s.request.duration, 15.0);
}

TEST(ShippedScenarios, StartWalkStop) {
  const Scenario s = loadShipped("start_walk_stop");
  ASSERT_EQ(s.request.reference.size(), 3u);
  EXPECT_DOUBLE_EQ(s.request.reference[1].t, 1.0);
  EXPECT_EQ(s.request.reference[1].velocity, Eigen::Vector3d(0.2, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(s.request.reference[2].t, 6.0);
  EXPECT_EQ(s.request.reference[2].velocity, Eigen::Vector3d::Zero());
  EXPECT_DOUBLE_EQ(s.request.duration, 10.0);
}

TEST(ShippedScenarios, Push) {
  const Scenario s = loadShipped("push");
  ASSERT_EQ(s.request.pushes.size(), 1u);
  EXPECT_DOUBLE_EQ(s.request.pushes[0].t, 3.8);
  EXPECT_EQ(s.request.pushes[0].force, Eigen::Vector2d(0.0, 90.0));
  EXPECT_DOUBLE_EQ(s.request.pushes[0].duration, 0.1);
  ASSERT_FALSE(s.request.reference.empty());
  EXPECT_EQ(s.request.reference.back().velocity, Eigen::Vector3d(0.2, 0.0, 0.0));
}

// The resolved YAML is itself a scenario that gives the same Scenario back.
TEST(ShippedScenarios, ResolvedYamlRoundTrips) {
  const std::string path = (fs::temp_directory_path() /
                            ("wpg_test_resolved_" + std::to_string(::getpid()) + ".yaml"))
                               .string();
  for (const char* name : {"walk_forward", "walk_sideways", "turn_on_the_spot", "curve",
                           "start_walk_stop", "push", "paper_experiment_a",
                           "paper_experiment_b"}) {
    SCOPED_TRACE(name);
    const Scenario first = loadShipped(name, {"generator.sqp_tolerance=1e-9"});
    std::ofstream(path) << resolvedScenarioText(first);
    const Scenario second = loadScenario(path, {}, kRobotsDir);
    EXPECT_EQ(resolvedScenarioText(second), resolvedScenarioText(first));
    EXPECT_EQ(second.name, first.name);
    EXPECT_EQ(second.walking.max_step_yaw_change, first.walking.max_step_yaw_change);
    EXPECT_EQ(second.walking.feasibility_y, first.walking.feasibility_y);
    EXPECT_EQ(second.walking.weight_jerk, first.walking.weight_jerk);
    EXPECT_EQ(second.request.duration, first.request.duration);
    EXPECT_EQ(second.request.robot_mass, first.request.robot_mass);
    EXPECT_EQ(second.request.generator.sqp_tolerance, 1e-9);
    EXPECT_EQ(second.replay, first.replay);
    EXPECT_EQ(second.filter, first.filter);
    EXPECT_EQ(second.filter_settings.input_weight, first.filter_settings.input_weight);
    ASSERT_EQ(second.request.reference.size(), first.request.reference.size());
    for (std::size_t i = 0; i < first.request.reference.size(); ++i) {
      EXPECT_EQ(second.request.reference[i].t, first.request.reference[i].t);
      EXPECT_EQ(second.request.reference[i].velocity, first.request.reference[i].velocity);
    }
    ASSERT_EQ(second.request.pushes.size(), first.request.pushes.size());
    for (std::size_t i = 0; i < first.request.pushes.size(); ++i) {
      EXPECT_EQ(second.request.pushes[i].force, first.request.pushes[i].force);
      EXPECT_EQ(second.request.pushes[i].duration, first.request.pushes[i].duration);
    }
  }
  fs::remove(path);
}

TEST(ShippedScenarios, ResolvedYamlListsEveryKey) {
  const std::string yaml = resolvedScenarioText(loadShipped("turn_on_the_spot"));
  for (const char* key :
       {"name: turn_on_the_spot", "robot: hrp2", "duration: 10.0", "robot_mass: 56.037",
        "algorithm: nmpc", "sqp_iterations: 1", "max_sqp_iterations:", "sqp_tolerance:",
        "max_qp_iterations:", "slack_weight:", "reference:", "pushes: []", "walking:",
        "com_height: 0.814", "horizon_length: 16", "max_step_yaw_change: 0.17",
        "feasibility_x: [-0.28, -0.2, 0.0, 0.2, 0.28]", "weight_jerk: 1.0e-05",
        "replay: false", "filter: false",
        "filter_settings: {error_weight: 1.0, input_weight: 1.0e-06, preview_time: 1.6, mode: "
        "offline, reinitialize_wpg: false, online_input_weight: 0.001}"}) {
    EXPECT_NE(yaml.find(key), std::string::npos) << "'" << key << "' missing in:\n" << yaml;
  }
}

// The multibody keys: filter implies replay; the settings read back through the resolved YAML;
// the scenario text loads like a file (wpg replay reads it from a dataset).
TEST(ShippedScenarios, ReplayAndFilterKeys) {
  const Scenario replay_only = loadShipped("walk_forward", {"replay=true"});
  EXPECT_TRUE(replay_only.replay);
  EXPECT_FALSE(replay_only.filter);
  const Scenario filtered =
      loadShipped("walk_forward", {"filter=true", "replay=false",
                                   "filter_settings={input_weight: 1e-5, preview_time: 0.665}"});
  EXPECT_TRUE(filtered.filter);
  EXPECT_TRUE(filtered.replay);  // the filter replays the walk
  EXPECT_EQ(filtered.filter_settings.error_weight, 1.0);
  EXPECT_EQ(filtered.filter_settings.input_weight, 1e-5);
  EXPECT_EQ(filtered.filter_settings.preview_time, 0.665);
  EXPECT_NE(resolvedScenarioText(filtered).find("replay: true"), std::string::npos)
      << resolvedScenarioText(filtered);
  const Scenario again = wpg::datasets::loadScenarioText(resolvedScenarioText(filtered),
                                                         "run.h5:/scenario", {}, kRobotsDir);
  EXPECT_EQ(resolvedScenarioText(again), resolvedScenarioText(filtered));
  EXPECT_EQ(again.source_path, "run.h5:/scenario");
  EXPECT_TRUE(again.filter);
  EXPECT_EQ(again.filter_settings.preview_time, 0.665);
  try {
    wpg::datasets::loadScenarioText("name: a\nrobot: hrp2\nduration: x\nreference: []\n",
                                    "run.h5:/scenario", {}, kRobotsDir);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("run.h5:/scenario: key 'duration'", 0), 0u) << message;
  }
}

// filter_settings.mode and .reinitialize_wpg (the online loop of Fig. 3): offline and no
// re-initialisation by default, read, echoed in the resolved YAML and read back; a bad mode is
// one InputError naming the key.
TEST(ShippedScenarios, FilterModeKeys) {
  const Scenario defaults = loadShipped("walk_forward", {"filter=true"});
  EXPECT_EQ(defaults.filter_loop.mode, wpg::DynamicFilterMode::kOffline);
  EXPECT_FALSE(defaults.filter_loop.reinitialize_wpg);
  const Scenario online = loadShipped(
      "walk_forward", {"filter=true", "filter_settings={mode: both, reinitialize_wpg: true}"});
  EXPECT_EQ(online.filter_loop.mode, wpg::DynamicFilterMode::kBoth);
  EXPECT_TRUE(online.filter_loop.reinitialize_wpg);
  EXPECT_EQ(online.filter_settings.preview_time, 1.6);  // the other keys keep their defaults
  const Scenario again = wpg::datasets::loadScenarioText(resolvedScenarioText(online),
                                                         "run.h5:/scenario", {}, kRobotsDir);
  EXPECT_EQ(again.filter_loop.mode, wpg::DynamicFilterMode::kBoth);
  EXPECT_TRUE(again.filter_loop.reinitialize_wpg);
  // closed_loop and its own online weight, read back through the resolved YAML.
  const Scenario closed =
      loadShipped("walk_forward", {"filter=true", "filter_settings={mode: closed_loop, "
                                                  "online_input_weight: 2e-4}"});
  EXPECT_EQ(closed.filter_loop.mode, wpg::DynamicFilterMode::kClosedLoop);
  EXPECT_EQ(closed.filter_loop.online_input_weight, 2e-4);
  EXPECT_EQ(closed.filter_settings.input_weight, 1e-6);  // the offline pass's R is its own key
  EXPECT_EQ(defaults.filter_loop.online_input_weight, 1e-3);
  const Scenario closed_again = wpg::datasets::loadScenarioText(resolvedScenarioText(closed),
                                                                "run.h5:/scenario", {}, kRobotsDir);
  EXPECT_EQ(closed_again.filter_loop.mode, wpg::DynamicFilterMode::kClosedLoop);
  EXPECT_EQ(closed_again.filter_loop.online_input_weight, 2e-4);
  for (const char* bad : {"filter_settings.mode=closed", "filter_settings.mode=[online]",
                          "filter_settings.reinitialize_wpg=maybe",
                          "filter_settings.online_input_weight=0",
                          "filter_settings={mode: closed_loop, reinitialize_wpg: true}"}) {
    try {
      loadShipped("walk_forward", {bad});
      ADD_FAILURE() << bad << ": no InputError";
    } catch (const InputError& error) {
      const std::string message = error.what();
      const std::string text(bad);
      const std::string key = text.find('{') == std::string::npos
                                  ? text.substr(0, text.find('='))
                                  : "filter_settings.reinitialize_wpg";
      EXPECT_NE(message.find(key), std::string::npos) << message;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Malformed input: one InputError line naming the file and the key
// ---------------------------------------------------------------------------------------------

TEST_F(ScenarioFiles, UnknownObstacleLinearizationIsAnError) {
  expectError("bad_linearization.yaml", kValidScenario,
              {"walking.obstacle_linearization", "step or command_tangent"},
              {"walking.obstacle_linearization=tangent"});
}

TEST_F(ScenarioFiles, UnknownObstacleLandingLinearizationIsAnError) {
  expectError("bad_landing_linearization.yaml", kValidScenario,
              {"walking.obstacle_landing_linearization", "step or command_tangent"},
              {"walking.obstacle_landing_linearization=border"});
}

TEST_F(ScenarioFiles, ValidBaseLoads) {
  const Scenario s = loadScenario(write("valid.yaml", kValidScenario), {}, kRobotsDir);
  EXPECT_EQ(s.name, "test_case");
  EXPECT_DOUBLE_EQ(s.walking.max_step_yaw_change, 0.17);
  ASSERT_EQ(s.request.pushes.size(), 1u);
}

TEST_F(ScenarioFiles, MissingKeys) {
  expectError("no_duration.yaml", replaced(kValidScenario, "duration: 5.0\n", ""),
              {"'duration'", "missing"});
  expectError("no_name.yaml", replaced(kValidScenario, "name: test_case\n", ""),
              {"'name'", "missing"});
  expectError("no_robot.yaml", replaced(kValidScenario, "robot: hrp2\n", ""),
              {"'robot'", "missing"});
  expectError("no_reference.yaml",
              replaced(kValidScenario,
                       "reference:\n  - {t: 0.0, v: [0.0, 0.0, 0.0]}\n  - {t: 1.0, v: [0.2, "
                       "0.0, 0.0]}\n",
                       ""),
              {"'reference'", "missing"});
  expectError("no_v.yaml", replaced(kValidScenario, ", v: [0.2, 0.0, 0.0]}", "}"),
              {"'reference[1].v'", "missing"});
  expectError("no_force.yaml", replaced(kValidScenario, " force: [0.0, 90.0],", ""),
              {"'pushes[0].force'", "missing"});
}

TEST_F(ScenarioFiles, WrongTypes) {
  expectError("duration_text.yaml", replaced(kValidScenario, "duration: 5.0", "duration: ten"),
              {"'duration'", "expected a positive number of seconds", "got ten"});
  expectError("duration_quoted.yaml",
              replaced(kValidScenario, "duration: 5.0", "duration: \"5.0\""),
              {"'duration'", "string"});
  expectError("duration_list.yaml", replaced(kValidScenario, "duration: 5.0", "duration: [5]"),
              {"'duration'", "list"});
  expectError("reference_map.yaml",
              "name: a\nrobot: hrp2\nduration: 1.0\nreference: {t: 0, v: [0, 0, 0]}\n",
              {"'reference'", "expected a list"});
  expectError("sqp_float.yaml",
              replaced(kValidScenario, "sqp_iterations: 1", "sqp_iterations: 1.5"),
              {"'generator.sqp_iterations'", "integer"});
  expectError("sqp_negative.yaml",
              replaced(kValidScenario, "sqp_iterations: 1", "sqp_iterations: -1"),
              {"'generator.sqp_iterations'", "got -1"});
  expectError("algorithm.yaml",
              replaced(kValidScenario, "algorithm: nmpc", "algorithm: ilqr"),
              {"'generator.algorithm'", "nmpc or lmpc", "got ilqr"});
  expectError("walking_int.yaml",
              replaced(kValidScenario, "max_step_yaw_change: 0.17", "horizon_length: 16.5"),
              {"'walking.horizon_length'", "integer"});
  expectError("walking_heading.yaml",
              replaced(kValidScenario, "max_step_yaw_change: 0.17", "heading_reference: world"),
              {"'walking.heading_reference'", "support_foot or command", "got world"});
  expectError("walking_obstacle_form.yaml",
              replaced(kValidScenario, "max_step_yaw_change: 0.17",
                       "obstacle_distance_form: points"),
              {"'walking.obstacle_distance_form'", "sole_clearance or paper", "got points"});
  expectError("name_slash.yaml", replaced(kValidScenario, "name: test_case", "name: a/b"),
              {"'name'", "got a/b"});
  expectError("not_a_map.yaml", "- just\n- a list\n", {"expected a map"});
  expectError("empty.yaml", "", {"empty"});
}

TEST_F(ScenarioFiles, BadDurations) {
  expectError("negative.yaml", replaced(kValidScenario, "duration: 5.0", "duration: -1"),
              {"key 'duration': expected a positive number of seconds, got -1"});
  expectError("zero.yaml", replaced(kValidScenario, "duration: 5.0", "duration: 0"),
              {"'duration'", "got 0"});
  expectError("inf.yaml", replaced(kValidScenario, "duration: 5.0", "duration: .inf"),
              {"'duration'", "finite", ".inf"});
}

TEST_F(ScenarioFiles, NonFiniteNumbers) {
  expectError("nan_command.yaml",
              replaced(kValidScenario, "v: [0.2, 0.0, 0.0]", "v: [.nan, 0.0, 0.0]"),
              {"'reference[1].v[0]'", "finite", ".nan"});
  expectError("nan_force.yaml", replaced(kValidScenario, "[0.0, 90.0]", "[0.0, .NaN]"),
              {"'pushes[0].force[1]'", "finite"});
  expectError("inf_time.yaml", replaced(kValidScenario, "t: 1.0", "t: -.inf"),
              {"'reference[1].t'", "finite"});
  expectError("nan_walking.yaml",
              replaced(kValidScenario, "max_step_yaw_change: 0.17", "com_height: .nan"),
              {"'walking.com_height'", "finite"});
}

TEST_F(ScenarioFiles, WrongVectorLengths) {
  expectError("v2.yaml", replaced(kValidScenario, "v: [0.2, 0.0, 0.0]", "v: [0.2, 0.0]"),
              {"'reference[1].v'", "3 numbers", "a list of 2 entries"});
  expectError("force3.yaml", replaced(kValidScenario, "[0.0, 90.0]", "[0.0, 90.0, 1.0]"),
              {"'pushes[0].force'", "2 numbers"});
  expectError("polygon.yaml",
              replaced(kValidScenario, "max_step_yaw_change: 0.17", "feasibility_x: [1, 2]"),
              {"'walking.feasibility_x'", "5 numbers"});
}

TEST_F(ScenarioFiles, TimesMustAscend) {
  expectError("descending.yaml", replaced(kValidScenario, "t: 1.0", "t: 0.0"),
              {"'reference[1].t'", "ascending"});
  expectError("negative_time.yaml", replaced(kValidScenario, "{t: 0.0, v: [0.0, 0.0, 0.0]}",
                                             "{t: -1.0, v: [0.0, 0.0, 0.0]}"),
              {"'reference[0].t'", ">= 0"});
  expectError("push_duration.yaml", replaced(kValidScenario, "duration: 0.1}", "duration: 0}"),
              {"'pushes[0].duration'", "positive"});
}

TEST_F(ScenarioFiles, UnknownRobot) {
  expectError("nao.yaml", replaced(kValidScenario, "robot: hrp2", "robot: nao"),
              {"key 'robot'", "hrp2", "got nao"});
  expectError("traversal.yaml", replaced(kValidScenario, "robot: hrp2", "robot: ../robots/hrp2"),
              {"key 'robot'"});
}

TEST_F(ScenarioFiles, UnreadableFile) {
  const std::string missing = (directory_ / "does_not_exist.yaml").string();
  try {
    loadScenario(missing, {}, kRobotsDir);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(missing), std::string::npos) << error.what();
  }
  try {
    loadScenario(directory_.string(), {}, kRobotsDir);
    ADD_FAILURE() << "no InputError for a directory";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("directory"), std::string::npos) << error.what();
  }
}

TEST_F(ScenarioFiles, YamlSyntaxErrorGivesTheLine) {
  expectError("syntax.yaml", "name: a\nrobot: hrp2\nduration: [1.0, 2.0\nreference: []\n",
              {"syntax error", "line "});
  expectError("syntax2.yaml", "name: a\n  robot: hrp2\n", {"syntax error", "line 2"});
}

// Texts on which yaml-cpp 0.7's LoadAll never returns (empty documents forever, memory growing
// until bad_alloc; found by tests/fuzz/fuzz_scenario_loader): one error, at once.
TEST_F(ScenarioFiles, EndlessDocumentsAreAnError) {
  expectError("comma.yaml", ",\n", {"comma.yaml", "one YAML document"});
  expectError("comma_after_comment.yaml", "# a scenario\n, size: [0.6, 0.4]\n",
              {"one YAML document"});
  expectError("two.yaml", replaced(kValidScenario, "duration: 5.0", "duration: 5.0\n---\na: 1"),
              {"two.yaml", "one YAML document"});
}

TEST_F(ScenarioFiles, UnknownKeysAreErrors) {
  expectError("typo.yaml", replaced(kValidScenario, "duration: 5.0", "duration: 5.0\ndurration: 6"),
              {"key 'durration'", "unknown key", "known keys", "duration"});
  expectError("walking_typo.yaml",
              replaced(kValidScenario, "max_step_yaw_change: 0.17", "max_step_yaw: 0.17"),
              {"key 'walking.max_step_yaw'", "unknown key", "max_step_yaw_change"});
  expectError("generator_typo.yaml",
              replaced(kValidScenario, "sqp_iterations: 1", "sqp_iteration: 1"),
              {"key 'generator.sqp_iteration'", "unknown key"});
  expectError("reference_typo.yaml", replaced(kValidScenario, "{t: 1.0, v:", "{t: 1.0, vel:"),
              {"key 'reference[1].vel'", "unknown key"});
  expectError("push_typo.yaml", replaced(kValidScenario, "force: [0.0, 90.0]", "f: [0.0, 90.0]"),
              {"key 'pushes[0].f'", "unknown key"});
  expectError("robot_typo.yaml", replaced(kValidScenario, "robot: hrp2", "robto: hrp2"),
              {"key 'robto'", "unknown key"});
  expectError("duplicate.yaml", replaced(kValidScenario, "duration: 5.0", "duration: 5.0\nduration: 6.0"),
              {"key 'duration'", "twice"});
}

TEST_F(ScenarioFiles, BadReplayKeys) {
  expectError("replay_yes.yaml", std::string(kValidScenario) + "replay: yes\n",
              {"key 'replay'", "expected true or false", "got yes"});
  expectError("filter_quoted.yaml", std::string(kValidScenario) + "filter: \"true\"\n",
              {"key 'filter'", "expected true or false", "string"});
  expectError("filter_settings_typo.yaml",
              std::string(kValidScenario) + "filter_settings: {preview: 1.0}\n",
              {"key 'filter_settings.preview'", "unknown key", "preview_time"});
  expectError("filter_settings_negative.yaml",
              std::string(kValidScenario) + "filter_settings: {input_weight: -1e-6}\n",
              {"key 'filter_settings.input_weight'", "positive"});
  expectError("filter_settings_zero.yaml",
              std::string(kValidScenario) + "filter_settings: {preview_time: 0}\n",
              {"key 'filter_settings.preview_time'", "positive duration"});
  expectError("filter_settings_list.yaml",
              std::string(kValidScenario) + "filter_settings: [1, 1e-6, 1.6]\n",
              {"key 'filter_settings'", "expected a map"});
}

TEST_F(ScenarioFiles, WalkingParametersAreValidated) {
  // Values of the right type but physically wrong: rejected by WalkingParameters::validate().
  expectError("negative_height.yaml",
              replaced(kValidScenario, "max_step_yaw_change: 0.17", "com_height: -0.8"),
              {"com_height"});
}

TEST_F(ScenarioFiles, BadRobotFiles) {
  const std::string robots = (directory_ / "robots").string();
  write("robots/partial/walking.yaml", "com_height: 0.8\nmass: 30\n");
  const std::string scenario_path =
      write("partial.yaml", replaced(kValidScenario, "robot: hrp2", "robot: partial"));
  const std::string robot_file = robots + "/partial/walking.yaml";
  try {
    loadScenario(scenario_path, {}, robots);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(robot_file), std::string::npos) << message;
    EXPECT_NE(message.find("'gravity'"), std::string::npos) << message;
  }
  std::ifstream hrp2(kRobotsDir + "/hrp2/walking.yaml");
  std::string text((std::istreambuf_iterator<char>(hrp2)), std::istreambuf_iterator<char>());
  write("robots/partial/walking.yaml", text + "\nknee_count: 2\n");
  try {
    loadScenario(scenario_path, {}, robots);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(robot_file), std::string::npos) << message;
    EXPECT_NE(message.find("'knee_count'"), std::string::npos) << message;
  }
  // A complete copy of hrp2 is a valid robot.
  write("robots/partial/walking.yaml", text);
  EXPECT_EQ(loadScenario(scenario_path, {}, robots).robot, "partial");
}

// walking.yaml's `multibody:` reaches the scenario; without it the robot walks without a model;
// a bad map is one line naming the robot file and the key.
TEST_F(ScenarioFiles, RobotMultibodyMap) {
  const std::string robots = (directory_ / "robots").string();
  const std::string scenario_path =
      write("mapped.yaml", replaced(kValidScenario, "robot: hrp2", "robot: mapped"));
  const std::string robot_file = robots + "/mapped/walking.yaml";
  std::ifstream hrp2(kRobotsDir + "/hrp2/walking.yaml");
  const std::string text((std::istreambuf_iterator<char>(hrp2)), std::istreambuf_iterator<char>());
  write("robots/mapped/walking.yaml", text);
  const wpg::datasets::RobotMultibody shipped = loadScenario(scenario_path, {}, robots).multibody;
  EXPECT_TRUE(shipped.present);
  EXPECT_EQ(shipped.urdf, "hrp2.urdf");
  EXPECT_EQ(shipped.left_sole_frame, "LLEG_SOLE");
  EXPECT_EQ(shipped.right_sole_frame, "RLEG_SOLE");
  EXPECT_EQ(shipped.standing_posture, "half_sitting");

  const std::string block =
      "multibody:\n  urdf: hrp2.urdf                  # robots/hrp2/README.md, \"The multibody model\"\n";
  ASSERT_NE(text.find(block), std::string::npos) << "test bug: the shipped map changed";
  const auto with_map = [&](const std::string& map) {
    std::string edited = text;
    const std::size_t start = edited.find("multibody:\n");
    const std::size_t end = edited.find("\n\n", start);
    edited.replace(start, end - start, map);
    return edited;
  };
  write("robots/mapped/walking.yaml", with_map("multibody:\n  urdf: a.urdf\n  left_sole_frame: L\n  "
                                               "right_sole_frame: R"));
  const wpg::datasets::RobotMultibody own = loadScenario(scenario_path, {}, robots).multibody;
  EXPECT_EQ(own.urdf, "a.urdf");
  EXPECT_EQ(own.left_sole_frame, "L");
  EXPECT_EQ(own.standing_posture, "half_sitting");  // the default
  write("robots/mapped/walking.yaml", with_map(""));
  EXPECT_FALSE(loadScenario(scenario_path, {}, robots).multibody.present);

  const std::pair<std::string, std::string> bad[] = {
      {"multibody:\n  urdf: a.urdf\n  left_sole_frame: L", "'multibody.right_sole_frame'"},
      {"multibody:\n  urdf: a.urdf\n  left_sole_frame: L\n  right_sole_frame: L",
       "'multibody.right_sole_frame'"},
      {"multibody:\n  urdf: a.urdf\n  left_sole_frame: L\n  right_sole_frame: R\n  knee: K",
       "'multibody.knee'"},
      {"multibody:\n  urdf: ../a.urdf\n  left_sole_frame: L\n  right_sole_frame: R",
       "'multibody.urdf'"},
      {"multibody: hrp2.urdf", "'multibody'"}};
  for (const auto& [map, key] : bad) {
    write("robots/mapped/walking.yaml", with_map(map));
    try {
      loadScenario(scenario_path, {}, robots);
      ADD_FAILURE() << "no InputError for " << map;
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(robot_file), std::string::npos) << message;
      EXPECT_NE(message.find(key), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

}  // namespace
