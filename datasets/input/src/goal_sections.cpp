// The scenario's goal and planner sections (goal_sections.hpp).
#include "goal_sections.hpp"

#include "parameter_fields.hpp"
#include "wpg/datasets/input/input_limits.hpp"
#include "wpg/nearest_name.hpp"

#include <cstdint>
#include <limits>

namespace wpg::datasets::detail {

GoalRequest readGoalRequest(const YAML::Node& goal_node, const YAML::Node& planner_node,
                            const WalkingParameters& walking, const Source& source) {
  GoalRequest request;
  request.enabled = true;
  const Entries goal = readMap(goal_node, "goal", {"position", "yaw", "tolerance", "yaw_tolerance"},
                               "a map {position: [x, y], yaw, tolerance, yaw_tolerance}", source);
  WalkGoal& g = request.goal;
  g.position = readLengthVector<2>(entry(goal, "position"), "goal.position",
                             "[x, y] in m, world frame (2 numbers)", source);
  if (present(goal, "yaw")) {
    g.has_yaw = true;
    g.yaw = readNumber(entry(goal, "yaw"), "goal.yaw", "an angle in rad, world frame", source);
  }
  if (present(goal, "tolerance")) {
    g.tolerance = readPositive(entry(goal, "tolerance"), "goal.tolerance",
                               "a positive distance in m", source);
    checkMagnitude(g.tolerance, kMaxLength, "m", entry(goal, "tolerance"), "goal.tolerance",
                   "a positive distance in m", source);
  }
  if (present(goal, "yaw_tolerance")) {
    g.yaw_tolerance = readPositive(entry(goal, "yaw_tolerance"), "goal.yaw_tolerance",
                                   "a positive angle in rad", source);
  }

  RoutePlannerSettings& p = request.planner;
  if (planner_node.IsDefined()) {
    const Entries planner =
        readMap(planner_node, "planner",
                {"algorithm", "time_limit", "max_iterations", "seed", "robot_radius",
                 "replan_distance", "sensing_range", "lookahead", "bounds"},
                "a map of route planner settings (SCENARIOS.md)", source, /*null_is_empty=*/true);
    if (present(planner, "algorithm")) {
      const YAML::Node algorithm = entry(planner, "algorithm");
      if (!algorithm.IsScalar()) {
        source.fail("planner.algorithm", "the name of a planner such as rrtconnect", algorithm);
      }
      // Planner names are lower case (RRTConnect reads as rrtconnect, the name stored); an
      // unknown one is refused with the nearest known name by the engine's checks, which know
      // the planners of this build (planning/route_planner.hpp).
      p.algorithm = asciiLower(algorithm.Scalar());
    }
    // Signs are checked by GoalRequest::validate (one message per key, with the value).
    if (present(planner, "time_limit")) {
      p.time_limit = readNumber(entry(planner, "time_limit"), "planner.time_limit",
                                "a positive time in s", source);
    }
    if (present(planner, "max_iterations")) {
      p.max_iterations = readInteger(entry(planner, "max_iterations"), "planner.max_iterations", 1,
                                     "a positive number of iterations", source);
    }
    if (present(planner, "seed")) {
      p.seed = static_cast<std::uint32_t>(
          readInteger(entry(planner, "seed"), "planner.seed", 0, "an integer >= 0", source));
    }
    const auto read = [&](const char* name, double* value, const char* expected) {
      if (present(planner, name)) {
        *value = readLength(entry(planner, name), std::string("planner.") + name, expected, source);
      }
    };
    read("robot_radius", &p.robot_radius, "a radius >= 0 in m (0: from the robot)");
    read("replan_distance", &p.replan_distance, "a positive distance in m");
    read("sensing_range", &p.sensing_range, "a distance >= 0 in m");
    read("lookahead", &p.lookahead, "a positive distance in m");
    if (present(planner, "bounds")) {
      p.has_bounds = true;
      p.bounds = readLengthVector<4>(entry(planner, "bounds"), "planner.bounds",
                               "[x_min, x_max, y_min, y_max] in m (4 numbers)", source);
    }
  }
  if (p.robot_radius == 0.0) {
    p.robot_radius = defaultRobotRadius(walking.initial_foot_separation, walking.foot_length,
                                        walking.foot_width);
  }
  return request;
}

void emitGoalRequest(YAML::Emitter& out, const GoalRequest& request) {
  const WalkGoal& g = request.goal;
  out << YAML::Key << "goal" << YAML::Value << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "position" << YAML::Value;
  emitNumbers(out, g.position.data(), 2);
  if (g.has_yaw) out << YAML::Key << "yaw" << YAML::Value << formatNumber(g.yaw);
  out << YAML::Key << "tolerance" << YAML::Value << formatNumber(g.tolerance);
  out << YAML::Key << "yaw_tolerance" << YAML::Value << formatNumber(g.yaw_tolerance);
  out << YAML::EndMap;
  const RoutePlannerSettings& p = request.planner;
  out << YAML::Key << "planner" << YAML::Value << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "algorithm" << YAML::Value << p.algorithm;
  out << YAML::Key << "time_limit" << YAML::Value << formatNumber(p.time_limit);
  out << YAML::Key << "max_iterations" << YAML::Value << p.max_iterations;
  out << YAML::Key << "seed" << YAML::Value << p.seed;
  out << YAML::Key << "robot_radius" << YAML::Value << formatNumber(p.robot_radius);
  out << YAML::Key << "replan_distance" << YAML::Value << formatNumber(p.replan_distance);
  out << YAML::Key << "sensing_range" << YAML::Value << formatNumber(p.sensing_range);
  out << YAML::Key << "lookahead" << YAML::Value << formatNumber(p.lookahead);
  if (p.has_bounds) {
    out << YAML::Key << "bounds" << YAML::Value;
    emitNumbers(out, p.bounds.data(), 4);
  }
  out << YAML::EndMap;
}

}  // namespace wpg::datasets::detail
