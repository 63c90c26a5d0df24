#pragma once
// The steps that `wpg run`, `wpg replay` and `wpg bench` share: generate a walk (with the FCL
// world when the scenario has obstacles), replay it on the robot's multibody model with the
// dynamic filter, write the dataset, and print the multibody part of the summary.
#include <iosfwd>
#include <string>

#include "wpg/datasets/scenario.hpp"
#include "wpg/multibody_validation.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/walk_generator.hpp"

namespace wpg::cli {

// <robots directory>/<robot>/<robot>.urdf: the multibody model of a robot folder.
std::string robotUrdfPath(const std::string& robot);

// The robot's multibody model; throws UsageError naming the URDF path when the robot has no
// URDF or it cannot be read (checked before anything is generated or written).
robots::RobotModel loadRobotModel(const std::string& robot);

// Throws UsageError when the scenario's filter_settings give no preview controller (the
// Riccati iteration does not converge), naming `scenario_path`.
void checkFilterSettings(const datasets::Scenario& scenario, const std::string& scenario_path);

// generateWalk with the FCL world of the scenario's obstacles (none: no world).
WalkResult generateScenarioWalk(const datasets::Scenario& scenario);

struct ReplayOutcome {
  MultibodyValidation validation;
  double wall_time = 0.0;      // [s] of replayWalk (IK, inverse dynamics, filter, validation)
  double walk_duration = 0.0;  // [s] covered by the walk's samples
  double realTimeFactor() const { return wall_time > 0.0 ? walk_duration / wall_time : 0.0; }
};

// replayWalk with the scenario's filter settings; `filter` false replays only.
ReplayOutcome replayScenarioWalk(const robots::RobotModel& model,
                                 const datasets::Scenario& scenario, const WalkTrajectory& walk,
                                 bool filter);

// writeRunDataset with the footstep clearances of the FCL world when the scenario has
// obstacles; returns the summary line about them (empty without obstacles).
std::string writeScenarioDataset(const std::string& path, const datasets::Scenario& scenario,
                                 const WalkResult& result,
                                 const MultibodyValidation* multibody = nullptr);

// The summary lines of a replay: ZMP error before/after, IK status, timing of the chain.
void printMultibodySummary(std::ostream& out, const ReplayOutcome& outcome);

// The last lines of `wpg run` and `wpg replay`: the dataset, and when `plot` its figure next to
// it (a figure that cannot be drawn is a warning: the dataset is complete).
void reportDatasetAndFigure(const std::string& dataset_path, const std::string& figure_path,
                            bool plot);

// "%.<digits>f" of value.
std::string fixed(double value, int digits);

}  // namespace wpg::cli
