#pragma once
// Readers of the scenario's sections (keys: datasets/SCENARIOS.md) and of the robot's
// walking.yaml. Each takes the section's node (undefined when the key is missing) and throws
// InputError naming the file and the key on anything malformed.
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "wpg/dynamic_filter.hpp"
#include "wpg/obstacles.hpp"
#include "wpg/preview_control.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walking_parameters.hpp"
#include "wpg/datasets/input/robot_multibody.hpp"
#include "wpg/datasets/input/yaml_input.hpp"

namespace wpg::datasets::detail {

// The keys a scenario file may hold at its top level.
const std::vector<std::string>& topLevelKeys();

// `generator:` (optional, defaults of GeneratorSettings).
GeneratorSettings readGenerator(const YAML::Node& node, const Source& source);
// `filter_settings:` (optional): the dynamic filter's preview controller, and into `loop` its
// mode (online | offline | both) and whether the online loop re-initialises the WPG.
PreviewControlSettings readFilterSettings(const YAML::Node& node, const Source& source,
                                          DynamicFilterLoopSettings* loop);
// `reference:` (required, may be empty): the velocity command, times strictly ascending.
std::vector<VelocityCommand> readReference(const YAML::Node& node, const Source& source);
// `pushes:` (optional).
std::vector<Push> readPushes(const YAML::Node& node, const Source& source);
// `obstacles:` (optional): circles, boxes, convex polygons (paper Sec. III-D);
// `known_to_planner` (optional, may be null) receives each one's `known_to_planner:` flag.
std::vector<Obstacle> readObstacles(const YAML::Node& node, const Source& source,
                                    std::vector<bool>* known_to_planner = nullptr);

// --- the robot: robots/<robot>/walking.yaml ------------------------------------------------

struct Robot {
  WalkingParameters walking;
  double mass = 0.0;
  RobotMultibody multibody;  // `multibody:` (present false without it)
  Entries nodes;  // the file's walking parameters as YAML, merged under the scenario's
};

// `multibody:` of walking.yaml (robot_multibody.hpp).
RobotMultibody readMultibody(const YAML::Node& node, const Source& source);
// The folders of `robots_dir` that hold a walking.yaml, sorted.
std::vector<std::string> knownRobots(const std::string& robots_dir);
// Reads a robot's walking.yaml: every walking parameter, `mass` and the optional `multibody:`
// map, nothing else.
Robot loadRobot(const std::string& robot_file);

}  // namespace wpg::datasets::detail
