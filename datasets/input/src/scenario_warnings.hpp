#pragma once
// The loader's warnings (Scenario::warnings; datasets/SCENARIOS.md, "Warnings"): values that
// are accepted but are either clamped before they reach the generator or outside what the robot
// can plausibly do, most often a unit mistake (a CoM height in cm, a yaw in degrees).
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/input/yaml_input.hpp"

namespace wpg::datasets::detail {

// The CoM heights (walking.com_height) taken as plausible for a robot whose own walking.yaml
// says `nominal`: from kLowestComHeightRatio to kHighestComHeightRatio times it (the reasons
// and the measurements on HRP-2 are in SCENARIOS.md, "Warnings").
constexpr double kLowestComHeightRatio = 0.75;
constexpr double kHighestComHeightRatio = 1.05;

// The warnings of a loaded `scenario` (its walking parameters, command and goal final), for a
// robot whose walking.yaml gives `robot_com_height`; `source` names the file and the --set.
std::vector<std::string> scenarioWarnings(const Scenario& scenario, double robot_com_height,
                                          const Source& source);

}  // namespace wpg::datasets::detail
