#pragma once
// The part of a run dataset that a walk to a goal adds (datasets/SCHEMA.md, "Walks to a
// goal"): the goal's attributes on the run group, the plans table with the routes, the
// obstacles' known_to_planner column and the path follower's commands.
#include "hdf5_image.hpp"

#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/study_design/run_fields.hpp"

namespace wpg::datasets::detail {

// `run` is /runs/<name>, its obstacles group already written when `fields` has obstacles; the
// attributes always, known_to_planner with the field obstacles, plans/ with goal.
void writeGoal(GroupImage& run, const Scenario& scenario, const GoalOutcome& goal,
               RunFields fields = RunFields::all());

// mpc/command of a walk to a goal: the path follower's command of each NMPC iteration (what its
// velocity metrics are measured against, datasets/METRICS.md); written also when the walk is
// replayed from its file (no GoalOutcome then), left out when the commands are not known (a
// file written before they were stored). `run` is /runs/<name>, its mpc group already written.
void writeGoalCommands(GroupImage& run, const wpg::WalkTrajectory& trajectory);

}  // namespace wpg::datasets::detail
