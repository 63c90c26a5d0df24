// --set keys compiled to Scenario fields (wpg/datasets/input/scenario_field.hpp). A key is
// resolved with the --set grammar (scenario_overrides.hpp) and the parameter tables
// (parameter_fields.hpp), the same the loader reads with, so that a field is found under the
// name the reader gives it. The checks of a value are not here: a study loads each value once
// through the loader, whose readers check it.
#include "wpg/datasets/input/scenario_field.hpp"

#include <type_traits>
#include <utility>

#include "parameter_fields.hpp"
#include "scenario_overrides.hpp"

namespace wpg::datasets {
namespace {

using detail::PathStep;

// The field `get(scenario)` refers to (`get` takes a Scenario or a const Scenario): copied by
// value; a number when it is a double.
template <typename Get>
ScenarioField referenceField(std::string key, Get get) {
  ScenarioField field;
  field.key = std::move(key);
  field.copy = [get](const Scenario& from, Scenario* to) { get(*to) = get(from); };
  using Value = std::decay_t<decltype(get(std::declval<Scenario&>()))>;
  if constexpr (std::is_same_v<Value, double>) {
    field.number = [get](Scenario* scenario) { return &get(*scenario); };
  }
  return field;
}

// `walking.<name>`: a row of the walking table (every kind: number, integer, polygon, choice).
std::optional<ScenarioField> walkingField(const std::string& key, const std::string& name) {
  for (const detail::WalkingField& row : detail::walkingFields()) {
    if (name != row.name) continue;
    if (row.number) {
      const auto member = row.number;
      return referenceField(
          key, [member](auto& s) -> auto& { return s.walking.*member; });
    }
    if (row.integer) {
      const auto member = row.integer;
      return referenceField(
          key, [member](auto& s) -> auto& { return s.walking.*member; });
    }
    if (row.polygon) {
      const auto member = row.polygon;
      return referenceField(
          key, [member](auto& s) -> auto& { return s.walking.*member; });
    }
    const detail::WalkingChoice* choice = row.choice;
    ScenarioField field;
    field.key = key;
    field.copy = [choice](const Scenario& from, Scenario* to) {
      choice->parse(choice->name(from.walking), &to->walking);
    };
    return field;
  }
  return std::nullopt;
}

// `<section>.<name>` of a table of numeric settings (generator, filter_settings).
template <typename Settings, typename GetSettings>
std::optional<ScenarioField> settingField(const std::string& key, const std::string& name,
                                          const std::vector<detail::SettingField<Settings>>& rows,
                                          GetSettings settings) {
  for (const detail::SettingField<Settings>& row : rows) {
    if (name != row.name) continue;
    if (row.positive) {
      const auto member = row.positive;
      return referenceField(
          key, [member, settings](auto& s) -> auto& { return settings(s).*member; });
    }
    const auto member = row.integer;
    return referenceField(
        key, [member, settings](auto& s) -> auto& { return settings(s).*member; });
  }
  return std::nullopt;
}

// `vector` or, with one more index step, its entry `[c]` (c < size).
template <typename Get>
std::optional<ScenarioField> vectorField(const std::string& key, const std::vector<PathStep>& rest,
                                         int size, Get get) {
  if (rest.empty()) return referenceField(key, get);
  if (rest.size() != 1 || !rest[0].key.empty() || rest[0].index >= static_cast<std::size_t>(size))
    return std::nullopt;
  const Eigen::Index c = static_cast<Eigen::Index>(rest[0].index);
  return referenceField(
      key, [get, c](auto& s) -> auto& { return get(s)[c]; });
}

// `<list>[i].<name>...` of the entries of the request's lists.
std::optional<ScenarioField> listEntryField(const std::string& key,
                                            const std::vector<PathStep>& path,
                                            const Scenario& base) {
  if (path.size() < 3 || !path[1].key.empty() || path[2].key.empty()) return std::nullopt;
  const std::size_t i = path[1].index;
  const std::string& list = path[0].key;
  const std::string& name = path[2].key;
  const std::vector<PathStep> rest(path.begin() + 3, path.end());
  const WalkRequest& request = base.request;
  if (list == "reference" && i < request.reference.size() && !base.goal.enabled && name == "v") {
    return vectorField(
        key, rest, 3, [i](auto& s) -> auto& { return s.request.reference[i].velocity; });
  }
  if (list == "pushes" && i < request.pushes.size()) {
    if (name == "force") {
      return vectorField(
          key, rest, 2, [i](auto& s) -> auto& { return s.request.pushes[i].force; });
    }
    if (name == "duration" && rest.empty()) {
      return referenceField(
          key, [i](auto& s) -> auto& { return s.request.pushes[i].duration; });
    }
  }
  if (list == "obstacles" && i < request.obstacles.size()) {
    const ObstacleType type = request.obstacles[i].type;
    const bool circle = type == ObstacleType::kCircle, box = type == ObstacleType::kBox;
    if (name == "center" && (circle || box)) {
      return vectorField(
          key, rest, 2, [i](auto& s) -> auto& { return s.request.obstacles[i].center; });
    }
    if (name == "size" && box) {
      return vectorField(
          key, rest, 2, [i](auto& s) -> auto& { return s.request.obstacles[i].size; });
    }
    if (!rest.empty()) return std::nullopt;
    if (name == "radius" && circle) {
      return referenceField(
          key, [i](auto& s) -> auto& { return s.request.obstacles[i].radius; });
    }
    if (name == "yaw" && box) {
      return referenceField(
          key, [i](auto& s) -> auto& { return s.request.obstacles[i].yaw; });
    }
    if (name == "margin") {
      return referenceField(
          key, [i](auto& s) -> auto& { return s.request.obstacles[i].margin; });
    }
  }
  return std::nullopt;
}

}  // namespace

detail::AppliedOverride appliedOverride(const std::string& text) {
  detail::Source source("");
  const detail::ParsedOverride parsed = detail::parseOverride(text, &source);
  return {detail::pathText(parsed.path, parsed.path.size()), text};
}

std::optional<ScenarioField> compileScenarioField(const std::string& key, const Scenario& base) {
  std::vector<PathStep> path;
  try {
    detail::Source source("");
    path = detail::parseOverride(key + "=0", &source).path;
  } catch (const InputError&) {
    return std::nullopt;  // not a key: the loader says why
  }
  const std::string canonical = detail::pathText(path, path.size());
  if (path.empty() || path[0].key.empty()) return std::nullopt;
  const std::string& top = path[0].key;
  const bool extensions =
      !base.request.generator.constraints.empty() || !base.request.generator.costs.empty();
  if (path.size() == 1) {
    // The run's own name replaces a swept `name` (StudyRun::name): nothing to copy.
    if (top == "name") return ScenarioField{canonical, [](const Scenario&, Scenario*) {}, {}};
    if (top == "duration") {
      return referenceField(
          canonical, [](auto& s) -> auto& { return s.request.duration; });
    }
    if (top == "robot_mass") {
      return referenceField(
          canonical, [](auto& s) -> auto& { return s.request.robot_mass; });
    }
    // A whole list: its reader checks the entries against each other within the value. The
    // obstacles' known_to_planner flags and the reference matter only without a goal.
    if (top == "reference" && !base.goal.enabled) {
      return referenceField(
          canonical, [](auto& s) -> auto& { return s.request.reference; });
    }
    if (top == "pushes") {
      return referenceField(
          canonical, [](auto& s) -> auto& { return s.request.pushes; });
    }
    if (top == "obstacles" && !base.goal.enabled) {
      return referenceField(
          canonical, [](auto& s) -> auto& { return s.request.obstacles; });
    }
    if (top == "replay" && !base.filter) {
      return referenceField(
          canonical, [](auto& s) -> auto& { return s.replay; });
    }
    return std::nullopt;
  }
  if (path.size() == 2 && !path[1].key.empty()) {
    const std::string& name = path[1].key;
    if (top == "walking" && !base.goal.enabled && !extensions) return walkingField(canonical, name);
    if (top == "generator") {
      if (name == "stop_when_blocked") {
        return referenceField(
            canonical, [](auto& s) -> auto& { return s.request.generator.stop_when_blocked; });
      }
      if (name == "record_plan") {
        return referenceField(
            canonical, [](auto& s) -> auto& { return s.request.generator.record_plan; });
      }
      return settingField(
          canonical, name, detail::generatorSettingFields(),
          [](auto& s) -> auto& { return s.request.generator; });
    }
    if (top == "filter_settings") {
      return settingField(
          canonical, name, detail::filterSettingFields(),
          [](auto& s) -> auto& { return s.filter_settings; });
    }
    return std::nullopt;
  }
  return listEntryField(canonical, path, base);
}

}  // namespace wpg::datasets
