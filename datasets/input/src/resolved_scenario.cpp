// The resolved scenario, emitted with yaml-cpp (resolved_scenario.hpp). Keys in the order of
// SCENARIOS.md; the parameter tables (parameter_fields.hpp) give the generator, filter and
// walking keys, the same tables the readers use.
#include "resolved_scenario.hpp"

#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "goal_sections.hpp"
#include "parameter_fields.hpp"
#include "wpg/datasets/input/yaml_input.hpp"

namespace wpg::datasets::detail {
namespace {

// `key:` and the list `items`, one flow map per item (written by emit_item), so that each entry
// stays on one line; an empty list is written `[]`.
template <typename Item, typename EmitItem>
void emitList(YAML::Emitter& out, const char* key, const std::vector<Item>& items,
              EmitItem emit_item) {
  out << YAML::Key << key << YAML::Value;
  if (items.empty()) out << YAML::Flow;
  out << YAML::BeginSeq;
  for (const Item& item : items) {
    out << YAML::Flow << YAML::BeginMap;
    emit_item(item);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
}

}  // namespace

std::string emitResolved(const Scenario& scenario) {
  const WalkRequest& request = scenario.request;
  const GeneratorSettings& generator = request.generator;
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << scenario.name;
  out << YAML::Key << "robot" << YAML::Value << scenario.robot;
  out << YAML::Key << "duration" << YAML::Value << formatNumber(request.duration);
  out << YAML::Key << "robot_mass" << YAML::Value << formatNumber(request.robot_mass);

  out << YAML::Key << "generator" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "algorithm" << YAML::Value << generatorAlgorithmName(generator.algorithm);
  emitSettingFields(out, generatorSettingFields(), generator);
  out << YAML::EndMap;

  if (scenario.goal.enabled) {
    emitGoalRequest(out, scenario.goal);  // instead of the velocity command
  } else {
    emitList(out, "reference", request.reference, [&out](const VelocityCommand& command) {
      out << YAML::Key << "t" << YAML::Value << formatNumber(command.t);
      out << YAML::Key << "v" << YAML::Value;
      emitNumbers(out, command.velocity.data(), 3);
    });
  }
  emitList(out, "pushes", request.pushes, [&out](const Push& push) {
    out << YAML::Key << "t" << YAML::Value << formatNumber(push.t);
    out << YAML::Key << "force" << YAML::Value;
    emitNumbers(out, push.force.data(), 2);
    out << YAML::Key << "duration" << YAML::Value << formatNumber(push.duration);
  });
  std::size_t obstacle_index = 0;
  emitList(out, "obstacles", request.obstacles, [&](const Obstacle& obstacle) {
    out << YAML::Key << "type" << YAML::Value << obstacleTypeName(obstacle.type);
    if (obstacle.type == ObstacleType::kPolygon) {
      out << YAML::Key << "vertices" << YAML::Value << YAML::Flow << YAML::BeginSeq;
      for (const Eigen::Vector2d& vertex : obstacle.vertices) emitNumbers(out, vertex.data(), 2);
      out << YAML::EndSeq;
    } else {
      out << YAML::Key << "center" << YAML::Value;
      emitNumbers(out, obstacle.center.data(), 2);
    }
    if (obstacle.type == ObstacleType::kCircle) {
      out << YAML::Key << "radius" << YAML::Value << formatNumber(obstacle.radius);
    }
    if (obstacle.type == ObstacleType::kBox) {
      out << YAML::Key << "size" << YAML::Value;
      emitNumbers(out, obstacle.size.data(), 2);
      out << YAML::Key << "yaw" << YAML::Value << formatNumber(obstacle.yaw);
    }
    out << YAML::Key << "margin" << YAML::Value << formatNumber(obstacle.margin);
    // Written only where false, so that scenarios without goals read as before.
    if (!scenario.goal.knownToPlanner(obstacle_index++)) {
      out << YAML::Key << "known_to_planner" << YAML::Value << false;
    }
  });

  out << YAML::Key << "replay" << YAML::Value << scenario.replay;
  out << YAML::Key << "filter" << YAML::Value << scenario.filter;
  out << YAML::Key << "filter_settings" << YAML::Value << YAML::Flow << YAML::BeginMap;
  emitSettingFields(out, filterSettingFields(), scenario.filter_settings);
  out << YAML::Key << "mode" << YAML::Value << dynamicFilterModeName(scenario.filter_loop.mode);
  out << YAML::Key << "reinitialize_wpg" << YAML::Value << scenario.filter_loop.reinitialize_wpg;
  out << YAML::Key << "online_input_weight" << YAML::Value
      << scenario.filter_loop.online_input_weight;
  out << YAML::EndMap;

  out << YAML::Key << "walking" << YAML::Value << YAML::BeginMap;
  emitWalkingFields(out, scenario.walking);
  out << YAML::EndMap;
  out << YAML::EndMap;
  if (!out.good()) throw std::logic_error("emitting the resolved scenario: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

}  // namespace wpg::datasets::detail
