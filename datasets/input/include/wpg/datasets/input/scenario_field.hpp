#pragma once
// A `--set` key compiled to the Scenario field it sets, so that a study can make its runs'
// scenarios without reading YAML again: the study loads its base scenario once, loads each
// swept value once (the loader's own readers check it and say what is wrong), and a run is then
// the base with the fields of its values copied in, checked by checkScenario. Only the keys
// whose change stays inside one field compile; the others ("structural") return nothing and a
// study loads those runs from YAML as `wpg run --set` would:
//   - robot (another robot file), generator.algorithm (the cost terms depend on it), filter
//     (it turns replay on), and every enum other than walking's;
//   - an entry of a list or its length (reference[1], obstacles[2] past the end: whole lists
//     compile), and the times reference[i].t and pushes[i].t (the reader checks them against
//     their neighbours);
//   - any key of goal:, planner:, constraints:, costs:, filter_settings' mode and loop;
//   - walking keys when the base has a goal or cost or constraint terms (those readers check
//     themselves against the walking parameters);
//   - (for a study) two swept keys of which one holds the other (obstacles, obstacles[0].yaw).
#include <functional>
#include <optional>
#include <string>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/input/yaml_input.hpp"

namespace wpg::datasets {

struct ScenarioField {
  std::string key;  // the key in its canonical form ("reference[1].v"), as messages name it
  // Copies the field from a scenario that has the wanted value into another.
  std::function<void(const Scenario& from, Scenario* to)> copy;
  // Where the field is when it is one number (a random sweep sets it); empty otherwise.
  std::function<double*(Scenario* scenario)> number;
};

// The field of `key` (as `wpg run --set` takes it) in scenarios shaped as `base` (same
// lists, same obstacle types), or nothing when the key is structural (above) or not a key.
std::optional<ScenarioField> compileScenarioField(const std::string& key, const Scenario& base);

// The `--set` override "key=value" as a Source notes it (its canonical key, its text), so
// that messages about the key say that it was set. Throws InputError on a malformed key.
detail::AppliedOverride appliedOverride(const std::string& text);

// What the loader checks once every key is read, on a scenario whose fields were changed since
// (walking.validate(), request.validate(), the goal, the walk's size, the replay's length),
// then its warnings (Scenario::warnings), named after `source`. Throws InputError as
// loadScenario does.
void checkScenario(Scenario* scenario, const detail::Source& source);

}  // namespace wpg::datasets
