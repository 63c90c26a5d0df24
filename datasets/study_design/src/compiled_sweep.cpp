// A study's sweep compiled against its base scenario (compiled_sweep.hpp).
#include "compiled_sweep.hpp"

#include <algorithm>
#include <exception>

#include <yaml-cpp/yaml.h>

#include "wpg/datasets/input/yaml_input.hpp"

namespace wpg::datasets {
namespace {

// The base with one more override, as the loader reads it; nothing when it refuses it.
std::optional<Scenario> loadWith(const std::string& base_text, const std::string& base_origin,
                                 const std::string& robots_dir, std::vector<std::string> overrides,
                                 const std::string& name) {
  overrides.push_back("name=" + name);
  try {
    return loadScenarioText(base_text, base_origin, overrides, robots_dir);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

// The loader reads `value` (a --set value's text) as value.number, bit for bit: its number
// reader (from_chars) and the study's (yaml-cpp's as<double>) agree on it.
bool readsAsItsNumber(const SweptValue& value) {
  if (!value.numeric) return false;
  try {
    const detail::Source source("");
    return detail::readNumber(YAML::Load(value.value), value.key, "a number", source) ==
           value.number;
  } catch (const std::exception&) {  // InputError, YAML::Exception
    return false;
  }
}

// True when one of the keys holds the other: "obstacles" and "obstacles[0].yaw".
bool nested(const std::string& outer, const std::string& inner) {
  return inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 &&
         (inner[outer.size()] == '.' || inner[outer.size()] == '[');
}

}  // namespace

CompiledSweep::CompiledSweep(const std::string& base_text, const std::string& base_origin,
                             const std::string& robots_dir,
                             const std::vector<std::string>& constants,
                             const std::string& first_name, const std::vector<SweptKey>& keys)
    : base_origin_(base_origin) {
  // Run 0's overrides; a value of key k is loaded as run 0 with k's value replaced.
  std::vector<std::string> first = constants;
  for (const SweptKey& swept : keys) first.push_back(swept.key + "=" + swept.first);
  base_ = loadWith(base_text, base_origin, robots_dir, first, first_name);
  if (!base_) return;
  for (const std::string& constant : constants) constants_.push_back(appliedOverride(constant));
  std::vector<std::optional<ScenarioField>> fields;
  for (const SweptKey& swept : keys) fields.push_back(compileScenarioField(swept.key, *base_));
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const SweptKey& swept = keys[k];
    CompiledKey compiled;
    compiled.field = fields[k];
    for (const std::optional<ScenarioField>& other : fields) {
      // Nested keys (in their canonical form): the outer one may change the inner one's list.
      if (compiled.field && other &&
          (nested(compiled.field->key, other->key) || nested(other->key, compiled.field->key)))
        compiled.field.reset();
    }
    // A key of plain numbers into a number field takes them as they are (a random key's draws,
    // or listed numbers): the loader accepted the smallest and the largest, and what a reader
    // checks of one number is an interval. Other values are each loaded.
    double low = swept.low, high = swept.high;
    bool numbers = compiled.field && compiled.field->number;
    for (std::size_t v = 0; v < swept.values.size() && numbers; ++v) {
      numbers = readsAsItsNumber(swept.values[v]);
      low = v == 0 ? swept.values[v].number : std::min(low, swept.values[v].number);
      high = v == 0 ? swept.values[v].number : std::max(high, swept.values[v].number);
    }
    const auto load = [&](const std::string& value) {
      std::vector<std::string> overrides = first;
      overrides[constants.size() + k] = swept.key + "=" + value;
      return loadWith(base_text, base_origin, robots_dir, overrides, first_name);
    };
    compiled.by_number = swept.values.empty() || numbers;
    if (compiled.field && compiled.by_number) {
      compiled.range_accepted = compiled.field->number &&
                                load(detail::formatNumber(low)).has_value() &&
                                load(detail::formatNumber(high)).has_value();
    } else if (compiled.field) {
      for (const SweptValue& value : swept.values) compiled.loaded.push_back(load(value.value));
    }
    keys_.push_back(std::move(compiled));
  }
}

bool CompiledSweep::make(const std::vector<SweptValue>& swept,
                         const std::vector<std::size_t>& positions, const std::string& name,
                         Scenario* scenario) const {
  if (!base_) return false;
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    const CompiledKey& key = keys_[k];
    if (!key.field) return false;
    if (key.by_number ? !key.range_accepted : !key.loaded[positions[k]]) return false;
  }
  Scenario made = *base_;
  for (std::size_t k = 0; k < keys_.size(); ++k) {
    const CompiledKey& key = keys_[k];
    if (key.by_number) {
      *key.field->number(&made) = swept[k].number;
    } else {
      key.field->copy(*key.loaded[positions[k]], &made);
    }
  }
  made.name = name;
  // The overrides in the loader's order (set:, the sweep, the name), so that a warning names
  // the value that caused it as it would after loading.
  detail::Source source(base_origin_);
  for (const detail::AppliedOverride& constant : constants_) source.addOverride(constant);
  for (std::size_t k = 0; k < keys_.size(); ++k)
    source.addOverride({keys_[k].field->key, swept[k].key + "=" + swept[k].value});
  source.addOverride({"name", "name=" + name});
  try {
    checkScenario(&made, source);
  } catch (const InputError&) {
    return false;  // refused: loaded from YAML, whose message is the reference
  }
  *scenario = std::move(made);
  return true;
}

}  // namespace wpg::datasets
