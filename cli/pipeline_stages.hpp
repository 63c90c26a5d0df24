#pragma once
// The pipeline of one scenario, stage by stage, as `wpg run`, `wpg replay` and `wpg bench` wire
// it: scenario (datasets) -> generateWalk (NMPC + interpolation: libwpg) -> replayWalk (IK,
// multibody ZMP, dynamic filter: robots) -> footstep checks (FCL world: planning) and the
// dataset (datasets). Each function calls one library stage with the scenario's settings and
// turns the stage's failures into the CLI's errors; the numbers of the summaries are computed
// by analysis/, and printed by summary_printing.hpp.
#include <optional>
#include <string>

#include "wpg/datasets/run_dataset.hpp"
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

// Stage walk: generateWalk on the scenario's velocity command, or, when it has a goal, the walk
// to the goal (planning/goal_walk.hpp: route planner + path follower + replanning), whose
// plans and outcome go to the dataset.
struct WalkOutcome {
  WalkResult result;
  std::optional<datasets::GoalOutcome> goal;  // set for a goal walk
  double planning_time = 0.0;                 // [s] of the route planner, all plans
  int replans = 0;                            // plans after the first
  double route_length = 0.0;                  // [m] of the first route (0 without one)
};

// Throws UsageError naming `scenario_path` when the goal request does not fit the world (goal
// or start inside a grown obstacle or out of the bounds, unknown planner): checked before
// anything is generated or written. Nothing to check without a goal.
void checkGoalRequest(const datasets::Scenario& scenario, const std::string& scenario_path);

WalkOutcome runScenarioWalk(const datasets::Scenario& scenario);

// Stage replay + filter, with the wall time it took.
struct ReplayOutcome {
  MultibodyValidation validation;
  double wall_time = 0.0;      // [s] of replayWalk (IK, inverse dynamics, filter, validation)
  double walk_duration = 0.0;  // [s] covered by the walk's samples
  double realTimeFactor() const;  // walk_duration / wall_time (analysis::realTimeFactor)
};

// replayWalk with the scenario's filter settings; `filter` false replays only. `threads`:
// the validation replay's (WalkReplaySettings::threads; 1 on a batch's workers).
ReplayOutcome replayScenarioWalk(const robots::RobotModel& model,
                                 const datasets::Scenario& scenario, const WalkTrajectory& walk,
                                 bool filter, int threads = 1);

// Stages walk + replay + filter as the scenario says (`scenario.replay`, `filter`,
// `filter_settings.mode`): generateWalk then replayScenarioWalk (no filter, or mode offline),
// or the online loop of the paper's Fig. 3 (robots/online_filter_loop.hpp: the walk and its
// filter together; mode both also runs generateWalk + the offline pass, whose ZMP errors
// go to validation.offline_*). `model` is needed (non-null) when the scenario replays.
// A goal walk (runScenarioWalk) is filtered offline only: its online loop would need the goal
// walk inside the filter loop (std::invalid_argument for filter_settings.mode online or both).
// Throws std::invalid_argument for a walk the generator rejects (as generateWalk).
struct ScenarioRun {
  WalkOutcome walk;
  std::optional<ReplayOutcome> replay;
};
ScenarioRun runScenario(const robots::RobotModel* model, const datasets::Scenario& scenario,
                        int replay_threads = 1);

// The least clearances of the landed footsteps to the scenario's obstacles (FCL world,
// wpg/planning/obstacle_checks.hpp), minima over the steps [m].
struct ObstacleClearances {
  int obstacle_count = 0;
  double step_centre = 0.0;  // signed distance of the step centre - the NMPC's bound (margin +
                             // obstacle_foot_radius, or the paper's form): >= 0 when it holds
  const char* step_centre_bound = "";  // that bound in words (wpg::stepCentreBoundName)
  double sole = 0.0;         // signed distance of the sole - margin
  double sole_to_obstacle = 0.0;  // signed distance of the sole, margin not counted
};

// The footstep clearances of the FCL world (sole rectangles against the obstacles) for the
// dataset, with their minima; none without obstacles (or without planning/ linked).
struct FootstepCheck {
  datasets::FootstepClearances clearances;
  ObstacleClearances least;
};
std::optional<FootstepCheck> checkScenarioFootsteps(const datasets::Scenario& scenario,
                                                    const WalkResult& result);

// Stage dataset: writeRunDataset, with the footstep clearances of the FCL world when the
// scenario has obstacles; returns those clearances (none without obstacles).
// `goal`: the goal walk's plans and outcome (WalkOutcome::goal), required for a goal scenario.
std::optional<ObstacleClearances> writeScenarioDataset(
    const std::string& path, const datasets::Scenario& scenario, const WalkResult& result,
    const MultibodyValidation* multibody = nullptr, const datasets::GoalOutcome* goal = nullptr);

}  // namespace wpg::cli
