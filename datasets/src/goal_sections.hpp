#pragma once
// The scenario's `goal:` and `planner:` sections (keys: datasets/SCENARIOS.md, "Walks
// to a goal"): read into libwpg's plain GoalRequest, and emitted back into the resolved
// scenario. planning/ checks what needs the world (a goal inside an obstacle, the planner's
// name against OMPL's planners).
#include <yaml-cpp/yaml.h>

#include "wpg/walk_goal.hpp"
#include "wpg/walking_parameters.hpp"
#include "yaml_input.hpp"

namespace wpg::datasets::detail {

// `goal` (a map) and `planner` (optional map); a robot_radius of 0 or missing becomes the
// robot's default (defaultRobotRadius of `walking`), so that the resolved scenario states it.
// known_to_planner is left to the caller (it comes with the obstacles).
GoalRequest readGoalRequest(const YAML::Node& goal, const YAML::Node& planner,
                            const WalkingParameters& walking, const Source& source);

// `goal:` and `planner:` as flow maps, every key explicit.
void emitGoalRequest(YAML::Emitter& out, const GoalRequest& request);

}  // namespace wpg::datasets::detail
