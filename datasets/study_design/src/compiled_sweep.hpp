#pragma once
// A study's sweep compiled once against its base scenario, so that run i's scenario is made
// in microseconds instead of loaded from YAML (a few hundred): at study load run 0's scenario
// is loaded once (the base), each swept key is resolved to the Scenario field it sets
// (scenario_field.hpp), and each listed value is loaded once, run 0 with that value (the runs
// loadStudy checks, checkedRuns), through the loader (whose readers check it and word the
// errors). A run is then a copy of the base with
// its values' fields copied in (numbers, random or listed, set directly: the loader accepted
// the smallest and the largest, and every check a reader makes of one number is an interval),
// then the loader's checks over several keys and its warnings (checkScenario). The load costs
// a loaded scenario per key of numbers (2) or per other listed value (names, vectors).
//
// A run that cannot be made so returns false, and the study loads it from YAML as before: a
// structural key (scenario_field.hpp lists them), a value the loader refused alone (the run
// then fails with the loader's own message), a run that checkScenario refuses (same).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/input/scenario_field.hpp"
#include "wpg/datasets/study_design/study_runs.hpp"

namespace wpg::datasets {

// One swept key: its listed values (grid, zip), or the range of its random draws.
struct SweptKey {
  std::string key;
  std::string first;               // run 0's value, as text
  std::vector<SweptValue> values;  // empty for a random key
  double low = 0.0, high = 0.0;    // a random key's range
};

class CompiledSweep {
 public:
  CompiledSweep() = default;
  // `constants` are the study's set: overrides (before the swept values, as the runs apply
  // them); run 0 is named `first_name`.
  CompiledSweep(const std::string& base_text, const std::string& base_origin,
                const std::string& robots_dir, const std::vector<std::string>& constants,
                const std::string& first_name, const std::vector<SweptKey>& keys);

  // The scenario of the run named `name` whose key k takes `swept[k]` (value number
  // `positions[k]` of a listed key), into `scenario`; false when it must be loaded from YAML.
  bool make(const std::vector<SweptValue>& swept, const std::vector<std::size_t>& positions,
            const std::string& name, Scenario* scenario) const;

 private:
  struct CompiledKey {
    std::optional<ScenarioField> field;           // nothing: structural
    std::vector<std::optional<Scenario>> loaded;  // per listed value; nothing: refused
    bool by_number = false;       // its values are numbers set as they are (random, or listed)
    bool range_accepted = false;  // by_number: its smallest and largest values load
  };

  std::optional<Scenario> base_;  // run 0; nothing: it does not load (every run is loaded)
  std::string base_origin_;
  std::vector<detail::AppliedOverride> constants_;  // as a Source notes them
  std::vector<CompiledKey> keys_;
};

}  // namespace wpg::datasets
