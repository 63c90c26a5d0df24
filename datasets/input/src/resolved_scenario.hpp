#pragma once
// The resolved scenario: every key explicit (all walking parameters, all generator settings),
// numbers in a canonical form. Loading it as a scenario file gives the same Scenario again
// (resolvedScenarioText, stored in every dataset).
#include <string>

#include "wpg/datasets/input/scenario.hpp"

namespace wpg::datasets::detail {

std::string emitResolved(const Scenario& scenario);

}  // namespace wpg::datasets::detail
