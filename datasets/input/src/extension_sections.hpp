#pragma once
// `constraints:` and `costs:` of a scenario (datasets/SCENARIOS.md): registered constraint
// families and cost terms (wpg/nmpc/extension_registry.hpp) by name, each with a map of its
// parameters, checked against the registry with the merged walking parameters.
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "wpg/datasets/input/yaml_input.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::datasets::detail {

enum class ExtensionKind { kConstraint, kCost };

// The section `node` (undefined or null: none) read as a map name -> map of parameters, in
// the order of the names; every name and parameter checked (did-you-mean for unknown ones),
// defaults filled in. Throws InputError naming the key ("constraints.corridor.left").
std::vector<ExtensionUse> readExtensions(const YAML::Node& node, ExtensionKind kind,
                                         const WalkingParameters& walking, const Source& source);

// The section as the resolved scenario writes it (nothing when `uses` is empty).
void emitExtensions(YAML::Emitter& out, ExtensionKind kind, const std::vector<ExtensionUse>& uses);

}  // namespace wpg::datasets::detail
