// Scenario files: YAML in, a validated Scenario out (every key: datasets/SCENARIOS.md). This
// file holds the order of the steps: the robot, the merge of its walking parameters with the
// scenario's, the --set overrides, the sections, libwpg's cross-field checks, the resolved
// YAML. The pieces, each in its own file of datasets/input/ (yaml_input.hpp is public: the
// study files are read with it too):
//   yaml_input          typed YAML readers whose errors name the file and the key
//   scenario_overrides  the --set grammar (dotted paths, [index]) and its assignment
//   parameter_fields    the tables binding walking/generator/filter keys to struct fields
//   scenario_sections   the section readers (reference, pushes, obstacles, ...) and the robot
//   extension_sections  `constraints:` and `costs:`: the NMPC's registered extensions
//   resolved_scenario   the emitter of the resolved YAML
#include "wpg/datasets/input/scenario.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "extension_sections.hpp"
#include "goal_sections.hpp"
#include "parameter_fields.hpp"
#include "resolved_scenario.hpp"
#include "scenario_overrides.hpp"
#include "scenario_sections.hpp"
#include "scenario_warnings.hpp"
#include "wpg/datasets/input/scenario_field.hpp"
#include "wpg/datasets/input/yaml_input.hpp"
#include "wpg/walk_generator.hpp"

namespace wpg::datasets {
namespace {

namespace fs = std::filesystem;
using namespace detail;  // NOLINT: the private pieces of this reader

}  // namespace

void checkScenario(Scenario* scenario_ptr, const Source& source) {
  const Scenario& scenario = *scenario_ptr;
  // Cross-field checks owned by libwpg (ranges, consistency of timings, ...).
  try {
    scenario.walking.validate();
  } catch (const std::invalid_argument& error) {
    source.failChecked(std::string("invalid walking parameters (robot '") + scenario.robot +
                           "' merged with 'walking:' of the scenario): " + error.what(),
                       "walking.");
  }
  try {
    scenario.request.validate();
  } catch (const std::invalid_argument& error) {
    std::string message = error.what();
    // libwpg's request calls the robot's mass 'mass'; the scenario's key is robot_mass.
    if (message.rfind("'mass'", 0) == 0) message.replace(0, 6, "'robot_mass'");
    source.failChecked("invalid walk request: " + message);
  }
  try {
    scenario.goal.validate();
  } catch (const std::invalid_argument& error) {
    source.failChecked(error.what());
  }
  // Bounded work and a walk of at least one NMPC iteration (libwpg's limits), checked here so
  // that every command (run, batch, compare, replay) refuses it before anything runs.
  try {
    checkWalkSize(scenario.walking, scenario.request);
  } catch (const std::invalid_argument& error) {
    source.failChecked(error.what());
  }
  if (scenario.replay) {
    // The multibody replay differentiates the motion: it needs 3 samples (2 control periods).
    const double T = scenario.walking.sampling_period;
    const long periods = std::lround(scenario.request.duration / T) *
                         std::lround(T / scenario.walking.control_period);
    if (periods < 2) {
      source.failWith("duration",
                      "expected a walk of at least 2 control periods for the "
                      "multibody replay (replay or filter is on), got " +
                          std::to_string(periods));
    }
  }

  scenario_ptr->warnings = scenarioWarnings(scenario, scenario.robot_com_height, source);
}

namespace {

// `root` is the parsed scenario of `path` (a file, or the origin of a text).
Scenario loadScenarioTree(YAML::Node root, const std::string& path,
                          const std::vector<std::string>& overrides,
                          const std::string& robots_dir) {
  Source source(path);
  Scenario scenario;
  scenario.source_path = path;
  double robot_com_height = 0.0;  // the robot's own, for the plausible range of the scenario's
  try {
    if (root.IsNull() && !overrides.empty()) root = YAML::Node(YAML::NodeType::Map);
    if (!root.IsMap()) {
      source.failFile("expected a map of scenario keys (" + joinNames(topLevelKeys()) +
                      "), got " + describeDocument(root));
    }
    std::vector<ParsedOverride> parsed_overrides;
    for (const std::string& text : overrides) {
      parsed_overrides.push_back(parseOverride(text, &source));
    }

    // The robot first (a --set robot=... included): its walking parameters are the base that
    // the scenario's `walking:` map and then the overrides modify, so that an override such
    // as walking.feasibility_y[2]=0.35 changes one entry of the robot's list.
    // Reads through a const handle: yaml-cpp's non-const operator[] inserts keys, and
    // assigning to a Node that refers into the tree overwrites the tree.
    const YAML::Node& const_root = root;
    // Unknown keys first: a misspelt `robot:` should be reported as the typo it is.
    readMap(const_root, "", topLevelKeys(), "a map of scenario keys", source);
    const ParsedOverride* robot_override = nullptr;
    for (const ParsedOverride& parsed : parsed_overrides) {
      if (parsed.path.size() == 1 && parsed.path[0].key == "robot") robot_override = &parsed;
    }
    const YAML::Node robot_node = robot_override ? robot_override->value : const_root["robot"];
    const std::vector<std::string> robots = knownRobots(robots_dir);
    const std::string robot_expected =
        "the name of a folder of " + robots_dir + " holding walking.yaml (known robots: " +
        (robots.empty() ? std::string("none") : joinNames(robots)) + ")";
    scenario.robot = readName(robot_node, "robot", robot_expected, source);
    const fs::path robot_file = fs::path(robots_dir) / scenario.robot / "walking.yaml";
    std::error_code ec;
    if (!fs::is_regular_file(robot_file, ec)) source.fail("robot", robot_expected, robot_node);
    const Robot robot = loadRobot(robot_file.string());
    scenario.request.robot_mass = robot.mass;
    scenario.multibody = robot.multibody;
    robot_com_height = robot.walking.com_height;

    // walking := robot's parameters, then the scenario's (checked: known keys, given once).
    {
      Entries scenario_walking;
      const YAML::Node own_walking = const_root["walking"];
      if (own_walking.IsDefined() && !own_walking.IsNull()) {
        scenario_walking = readMap(own_walking, "walking", walkingFieldNames(),
                                   "a map of walking parameters", source);
      }
      YAML::Node merged(YAML::NodeType::Map);
      for (const WalkingField& field : walkingFields()) {
        const auto own = scenario_walking.find(field.name);
        merged[field.name] = YAML::Clone(own != scenario_walking.end()
                                             ? own->second
                                             : robot.nodes.at(field.name));
      }
      root["walking"] = merged;
    }
    for (const ParsedOverride& parsed : parsed_overrides) {
      assignPath(root, parsed.path, 0, parsed.value, parsed.text, source);
    }

    const Entries entries = readMap(root, "", topLevelKeys(), "a map of scenario keys", source);

    scenario.name = readName(entry(entries, "name"), "name",
                             "a name of at most 128 letters, digits, '_', '-', '.' (the HDF5 group "
                             "and default file name)",
                             source);
    if (readName(entry(entries, "robot"), "robot", robot_expected, source) != scenario.robot) {
      throw std::logic_error("loadScenario: the robot changed while merging");
    }
    scenario.walking = robot.walking;
    const Entries walking = readMap(entry(entries, "walking"), "walking", walkingFieldNames(),
                                    "a map of walking parameters", source);
    readWalkingFields(walking, "walking", /*require_all=*/false, source, &scenario.walking);

    scenario.request.duration = readPositive(entry(entries, "duration"), "duration",
                                             "a positive number of seconds", source);
    if (present(entries, "robot_mass")) {
      scenario.request.robot_mass = readPositive(entry(entries, "robot_mass"), "robot_mass",
                                                 "a positive mass in kg", source);
    }
    scenario.request.generator = readGenerator(entry(entries, "generator"), source);
    // Registered extensions, checked against the merged walking parameters.
    scenario.request.generator.constraints = readExtensions(
        entry(entries, "constraints"), ExtensionKind::kConstraint, scenario.walking, source);
    scenario.request.generator.costs = readExtensions(entry(entries, "costs"),
                                                      ExtensionKind::kCost, scenario.walking, source);
    if (scenario.request.generator.algorithm == GeneratorAlgorithm::kLmpc &&
        !scenario.request.generator.costs.empty()) {
      source.failWith("costs", "expected no cost terms with generator.algorithm lmpc: that "
                               "baseline fixes the step yaws in its own QP first, so a cost "
                               "would move the steps, not turn them (use algorithm nmpc)");
    }
    // A goal replaces the velocity command: the path follower gives it.
    const bool has_goal = present(entries, "goal");
    if (has_goal && entry(entries, "reference").IsDefined()) {
      source.failWith("reference", "expected either 'goal' or 'reference', not both (the path "
                                   "follower gives a goal walk's velocity command)");
    }
    if (!has_goal && entry(entries, "planner").IsDefined()) {
      source.failWith("planner", "expected only with a 'goal' (the route planner serves walks "
                                 "to a goal)");
    }
    if (!has_goal) {
      scenario.request.reference = readReference(entry(entries, "reference"), source);
    }
    scenario.request.pushes = readPushes(entry(entries, "pushes"), source);
    std::vector<bool> known_to_planner;
    scenario.request.obstacles =
        readObstacles(entry(entries, "obstacles"), source, &known_to_planner);
    if (has_goal) {
      scenario.goal = readGoalRequest(entry(entries, "goal"), entry(entries, "planner"),
                                      scenario.walking, source);
      scenario.goal.known_to_planner = known_to_planner;
    }
    if (present(entries, "filter")) {
      scenario.filter = readBoolean(entry(entries, "filter"), "filter", "true or false", source);
    }
    // The filter replays the walk (before and after its correction): filter implies replay.
    scenario.replay = scenario.filter;
    if (present(entries, "replay") &&
        readBoolean(entry(entries, "replay"), "replay", "true or false", source)) {
      scenario.replay = true;
    }
    scenario.filter_settings =
        readFilterSettings(entry(entries, "filter_settings"), source, &scenario.filter_loop);
  } catch (const YAML::Exception& error) {
    // Not expected (types are checked before conversion); still one line naming the file.
    throw InputError(oneLine(path + ": " + error.what()));
  }

  scenario.robot_com_height = robot_com_height;
  checkScenario(&scenario, source);
  return scenario;
}

}  // namespace

Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides,
                      const std::string& robots_dir) {
  return loadScenarioTree(readYamlFile(path, "scenario file"), path, overrides, robots_dir);
}

std::string resolvedScenarioText(const Scenario& scenario) {
  return detail::emitResolved(scenario);
}

Scenario loadScenarioText(const std::string& text, const std::string& origin,
                          const std::vector<std::string>& overrides,
                          const std::string& robots_dir) {
  return loadScenarioTree(parseYamlText(text, origin), origin, overrides, robots_dir);
}

}  // namespace wpg::datasets
