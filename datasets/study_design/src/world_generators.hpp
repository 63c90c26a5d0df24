#pragma once
// The generated worlds of comparison studies (comparison_study.hpp; parameters and defaults:
// datasets/SCENARIOS.md, "Comparison studies"): obstacles and a default goal, from the
// generator's parameters and the run's seed only, so that the same study gives the same
// worlds on any machine and thread count.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "wpg/datasets/input/yaml_input.hpp"

namespace wpg::datasets::detail {

struct GeneratedWorld {
  YAML::Node obstacles;  // a YAML list in the scenario's `obstacles:` format
  Eigen::Vector2d goal;  // the generator's default goal position, m, world
};

// The generators' names, for `worlds[i]` keys and messages.
const std::vector<std::string>& worldGeneratorNames();

// Builds world `generator` from `parameters` (a map, possibly empty; reported under `key`),
// drawing random worlds from their own seed and `run_seed`. Throws InputError through
// `source` on unknown or out-of-range parameters.
GeneratedWorld generateWorld(const std::string& generator, const YAML::Node& parameters,
                             const std::string& key, int run_seed, const Source& source);

}  // namespace wpg::datasets::detail
