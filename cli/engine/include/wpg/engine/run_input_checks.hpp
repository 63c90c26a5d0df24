#pragma once
// The input checks of a run that need more than its scenario file (datasets/input checks the
// file itself: keys, types, limits): the robot's multibody model, the filter's controller, the
// goal against the world. Run before anything is generated or written; each throws
// datasets::InputError, one line naming `origin` (the scenario file, or "RUN.h5:/scenario").
#include <string>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/study_design/study.hpp"
#include "wpg/engine/robot_models.hpp"

namespace wpg::engine {

// The scenario's filter_settings give a preview controller (its Riccati iteration converges).
void checkFilterSettings(const datasets::Scenario& scenario, const std::string& origin);

// The goal request fits the world: goal and start outside every grown obstacle and inside the
// bounds, a known planner. Nothing to check without a goal.
void checkGoalRequest(const datasets::Scenario& scenario, const std::string& origin);

// Every check above that applies to the scenario, after loading the robot's multibody model into
// `models` when the scenario replays, in the order `wpg run` reports them.
void checkRunInput(const datasets::Scenario& scenario, const std::string& origin,
                   RobotModelCache& models);

// The multibody model of every robot the study's runs replay loads (once per robot).
void checkStudyRobotModels(const datasets::Study& study, const std::string& robots_directory);

}  // namespace wpg::engine
