#pragma once
// `wpg run --set key=value`: the key is a dotted path into the scenario tree with list
// indices, the value is parsed as YAML (grammar: wpg/datasets/input/scenario.hpp, loadScenario).
#include <cstddef>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "wpg/datasets/input/yaml_input.hpp"

namespace wpg::datasets::detail {

// One step of an override's path: a map key, or a list index.
struct PathStep {
  std::string key;        // map key, or empty for a list index
  std::size_t index = 0;  // list index when key is empty
};

struct ParsedOverride {
  std::vector<PathStep> path;
  YAML::Node value;
  std::string text;  // as given, key=value
};

// The first `count` steps of `path` as a key ("reference[1].v").
std::string pathText(const std::vector<PathStep>& path, std::size_t count);

// Parses "key=value" and registers it with `source`, so that later messages about this key
// say that the value came from --set. Throws InputError on a malformed key or value.
ParsedOverride parseOverride(const std::string& text, Source* source);

// Sets path[step..] below `node` (a handle sharing the tree's data) to `value`: missing maps
// on the way are created; an index may be one past the end of a list to append an entry.
void assignPath(YAML::Node node, const std::vector<PathStep>& path, std::size_t step,
                const YAML::Node& value, const std::string& text, const Source& source);

}  // namespace wpg::datasets::detail
