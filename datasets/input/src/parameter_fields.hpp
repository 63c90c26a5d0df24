#pragma once
// Parameter reflection: the tables that bind scenario keys to struct fields, so that the
// reader (scenario_sections.cpp, the robot file) and the emitter of the resolved scenario
// (resolved_scenario.cpp) walk the same list and cannot disagree on a key, its order or its
// type. A new parameter is one row here.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "wpg/preview_control.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walking_parameters.hpp"
#include "wpg/datasets/input/yaml_input.hpp"
#include "plain_scalar.hpp"

namespace wpg::datasets::detail {

// A flow list of numbers in the canonical form (formatNumber), as the resolved YAML writes.
void emitNumbers(YAML::Emitter& out, const double* values, int count);

// --- walking parameters: one YAML key per WalkingParameters field, same name ---------------

// A field that takes one of a few names (an enum of WalkingParameters).
struct WalkingChoice {
  const char* expected;  // the accepted names, for messages ("stop or step_in_place")
  bool (*parse)(const std::string& name, WalkingParameters* parameters);  // false: not a name
  const char* (*name)(const WalkingParameters& parameters);
};

// Exactly one member pointer (or `choice`) is set.
struct WalkingField {
  const char* name;
  double WalkingParameters::*number;
  int WalkingParameters::*integer;
  std::array<double, 5> WalkingParameters::*polygon;
  const WalkingChoice* choice;
};

// In the struct's order (walking_parameters.hpp); the resolved YAML keeps it.
const std::vector<WalkingField>& walkingFields();
std::vector<std::string> walkingFieldNames();

// Sets the fields present in `entries` (keys `prefix.<name>` in messages); `require_all` for a
// robot file, which must state every parameter (a new robot silently inheriting HRP-2's feet
// would be a bad surprise). Ranges are WalkingParameters::validate()'s job.
void readWalkingFields(const Entries& entries, const std::string& prefix, bool require_all,
                       const Source& source, WalkingParameters* parameters);
// Every field as key: value into a map the caller has begun.
void emitWalkingFields(YAML::Emitter& out, const WalkingParameters& parameters);

// --- numeric settings with a range (generator, dynamic filter) -----------------------------

// Exactly one of `positive` and `integer` is set.
template <typename Settings>
struct SettingField {
  const char* name;
  const char* expected;        // what a value must be, for messages
  double Settings::*positive;  // a number > 0
  int Settings::*integer;      // an integer in [minimum, maximum]
  int minimum;
  int maximum;
  double positive_maximum;  // a positive number is at most this
};

template <typename Settings>
SettingField<Settings> positiveSetting(const char* name, double Settings::*member,
                                       const char* expected,
                                       double maximum = std::numeric_limits<double>::infinity()) {
  return {name, expected, member, nullptr, 0, 0, maximum};
}
template <typename Settings>
SettingField<Settings> integerSetting(const char* name, int Settings::*member, int minimum,
                                      const char* expected,
                                      int maximum = std::numeric_limits<int>::max()) {
  return {name, expected, nullptr, member, minimum, maximum, 0.0};
}

// `generator:` without `algorithm` (an enum, read and emitted by name before these).
const std::vector<SettingField<GeneratorSettings>>& generatorSettingFields();
// `filter_settings:` (Kajita et al. 2003 preview control, wpg/preview_control.hpp).
const std::vector<SettingField<PreviewControlSettings>>& filterSettingFields();

template <typename Settings>
std::vector<std::string> settingNames(const std::vector<SettingField<Settings>>& fields) {
  std::vector<std::string> names;
  for (const SettingField<Settings>& field : fields) names.push_back(field.name);
  return names;
}

// Sets the fields given with a value in `entries`; keys `section.<name>` in messages.
template <typename Settings>
void readSettingFields(const Entries& entries, const std::string& section,
                       const std::vector<SettingField<Settings>>& fields, const Source& source,
                       Settings* settings) {
  for (const SettingField<Settings>& field : fields) {
    if (!present(entries, field.name)) continue;
    const YAML::Node node = entry(entries, field.name);
    const std::string key = childKey(section, field.name);
    if (field.positive) {
      const double value = readPositive(node, key, field.expected, source);
      if (value > field.positive_maximum) source.fail(key, field.expected, node);
      settings->*field.positive = value;
    } else {
      const int value = readInteger(node, key, field.minimum, field.expected, source);
      if (value > field.maximum) source.fail(key, field.expected, node);
      settings->*field.integer = value;
    }
  }
}

// Every field as key: value into a map the caller has begun.
template <typename Settings>
void emitSettingFields(YAML::Emitter& out, const std::vector<SettingField<Settings>>& fields,
                       const Settings& settings) {
  for (const SettingField<Settings>& field : fields) {
    emitKey(out, field.name);
    if (field.positive) {
      emitScalar(out, formatNumber(settings.*field.positive));
    } else {
      out << settings.*field.integer;
    }
  }
}

}  // namespace wpg::datasets::detail
