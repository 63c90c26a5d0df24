// The resolved scenario, emitted with yaml-cpp (resolved_scenario.hpp). Keys in the order of
// SCENARIOS.md; the parameter tables (parameter_fields.hpp) give the generator, filter and
// walking keys, the same tables the readers use. Keys, numbers and names go through
// emitKey and emitScalar (plain_scalar.hpp): the same bytes without yaml-cpp's character test.
#include "resolved_scenario.hpp"

#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "extension_sections.hpp"
#include "goal_sections.hpp"
#include "parameter_fields.hpp"
#include "plain_scalar.hpp"
#include "wpg/datasets/input/yaml_input.hpp"

namespace wpg::datasets::detail {
namespace {

// `key:` and the list `items`, one flow map per item (written by emit_item), so that each entry
// stays on one line; an empty list is written `[]`.
template <typename Item, typename EmitItem>
void emitList(YAML::Emitter& out, const char* key, const std::vector<Item>& items,
              EmitItem emit_item) {
  emitKey(out, key);
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
  emitKey(out, "name");
  emitScalar(out, scenario.name);
  emitKey(out, "robot");
  emitScalar(out, scenario.robot);
  emitKey(out, "duration");
  emitScalar(out, formatNumber(request.duration));
  emitKey(out, "robot_mass");
  emitScalar(out, formatNumber(request.robot_mass));

  emitKey(out, "generator");
  out << YAML::BeginMap;
  emitKey(out, "algorithm");
  emitScalar(out, generatorAlgorithmName(generator.algorithm));
  emitSettingFields(out, generatorSettingFields(), generator);
  emitKey(out, "stop_when_blocked");
  out << generator.stop_when_blocked;
  emitKey(out, "record_plan");
  out << generator.record_plan;
  out << YAML::EndMap;

  if (scenario.goal.enabled) {
    emitGoalRequest(out, scenario.goal);  // instead of the velocity command
  } else {
    emitList(out, "reference", request.reference, [&out](const VelocityCommand& command) {
      emitKey(out, "t");
      emitScalar(out, formatNumber(command.t));
      emitKey(out, "v");
      emitNumbers(out, command.velocity.data(), 3);
    });
  }
  emitList(out, "pushes", request.pushes, [&out](const Push& push) {
    emitKey(out, "t");
    emitScalar(out, formatNumber(push.t));
    emitKey(out, "force");
    emitNumbers(out, push.force.data(), 2);
    emitKey(out, "duration");
    emitScalar(out, formatNumber(push.duration));
  });
  std::size_t obstacle_index = 0;
  emitList(out, "obstacles", request.obstacles, [&](const Obstacle& obstacle) {
    emitKey(out, "type");
    emitScalar(out, obstacleTypeName(obstacle.type));
    if (obstacle.type == ObstacleType::kPolygon) {
      emitKey(out, "vertices");
      out << YAML::Flow << YAML::BeginSeq;
      for (const Eigen::Vector2d& vertex : obstacle.vertices) emitNumbers(out, vertex.data(), 2);
      out << YAML::EndSeq;
    } else {
      emitKey(out, "center");
      emitNumbers(out, obstacle.center.data(), 2);
    }
    if (obstacle.type == ObstacleType::kCircle) {
      emitKey(out, "radius");
      emitScalar(out, formatNumber(obstacle.radius));
    }
    if (obstacle.type == ObstacleType::kBox) {
      emitKey(out, "size");
      emitNumbers(out, obstacle.size.data(), 2);
      emitKey(out, "yaw");
      emitScalar(out, formatNumber(obstacle.yaw));
    }
    emitKey(out, "margin");
    emitScalar(out, formatNumber(obstacle.margin));
    // Written only where false, so that scenarios without goals read as before.
    if (!scenario.goal.knownToPlanner(obstacle_index++)) {
      emitKey(out, "known_to_planner");
      out << false;
    }
  });

  // Only when given: the resolved scenarios without extensions read as before.
  emitExtensions(out, ExtensionKind::kConstraint, generator.constraints);
  emitExtensions(out, ExtensionKind::kCost, generator.costs);

  emitKey(out, "replay");
  out << scenario.replay;
  emitKey(out, "filter");
  out << scenario.filter;
  emitKey(out, "filter_settings");
  out << YAML::Flow << YAML::BeginMap;
  emitSettingFields(out, filterSettingFields(), scenario.filter_settings);
  emitKey(out, "mode");
  emitScalar(out, dynamicFilterModeName(scenario.filter_loop.mode));
  emitKey(out, "reinitialize_wpg");
  out << scenario.filter_loop.reinitialize_wpg;
  emitKey(out, "online_input_weight");
  out << scenario.filter_loop.online_input_weight;
  out << YAML::EndMap;

  emitKey(out, "walking");
  out << YAML::BeginMap;
  emitWalkingFields(out, scenario.walking);
  out << YAML::EndMap;
  out << YAML::EndMap;
  if (!out.good()) throw std::logic_error("emitting the resolved scenario: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

}  // namespace wpg::datasets::detail
