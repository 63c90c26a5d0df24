#pragma once
// The part of a run dataset that a walk to a goal adds (datasets/SCHEMA.md, "Walks to a
// goal"): the goal's attributes on the run group, the plans table with the routes, and the
// obstacles' known_to_planner column.
#include <H5Cpp.h>

#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/input/scenario.hpp"

namespace wpg::datasets::detail {

// `run` is /runs/<name>, its obstacles group already written.
void writeGoal(H5::Group& run, const Scenario& scenario, const GoalOutcome& goal);

}  // namespace wpg::datasets::detail
