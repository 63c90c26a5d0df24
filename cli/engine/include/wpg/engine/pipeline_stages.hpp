#pragma once
// The stages of one scenario's pipeline: scenario (datasets) -> the walk (generateWalk, or the
// walk to a goal of planning/) -> its replay on the multibody model and the dynamic filter
// (robots) -> the footsteps against the obstacles (FCL world: planning). runScenario
// (scenario_run.hpp) chains them for a run; `wpg replay` and `wpg bench` call single stages.
#include <optional>
#include <string>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/multibody_validation.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/walk_generator.hpp"

namespace wpg::engine {

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

// Throws std::invalid_argument for a walk the generator rejects (as generateWalk).
WalkOutcome runScenarioWalk(const datasets::Scenario& scenario);

// Stage replay + filter, with the wall time it took.
struct ReplayOutcome {
  MultibodyValidation validation;
  double wall_time = 0.0;      // [s] of replayWalk (IK, inverse dynamics, filter, validation)
  double walk_duration = 0.0;  // [s] covered by the walk's samples
  double realTimeFactor() const;  // walk_duration / wall_time (analysis::realTimeFactor)
};

// replayWalk with the scenario's filter settings; `filter` false replays only. `threads`: the
// validation replay's (WalkReplaySettings::threads; 1 on a batch's workers; the results do not
// depend on it). Throws std::runtime_error ("cannot replay the walk: ...") when the replay
// cannot follow the walk (too short, or joint angles, filtered CoM or multibody ZMP that are
// not finite).
ReplayOutcome replayScenarioWalk(const robots::RobotModel& model,
                                 const datasets::Scenario& scenario, const WalkTrajectory& walk,
                                 bool filter, int threads = 1);

// Stages walk + replay + filter as the scenario says (`scenario.replay`, `filter`,
// `filter_settings.mode`): runScenarioWalk then replayScenarioWalk (no filter, or mode
// offline), or the online loop of the paper's Fig. 3 (robots/online_filter_loop.hpp: the walk
// and its filter together, the velocity-command walk or the walk to a goal alike; mode both
// also runs the walk again without the loop + the offline pass, whose ZMP errors go to
// validation.offline_*). `model` is needed (non-null) when the scenario replays.
// A replay that cannot follow the walk is written into the walk (success false, the reason
// appended to its message) and into `replay_failure`: the run failed, its walk is kept. When the
// online loop cannot follow its walk it returns none, and the walk is generated without it.
// Throws std::invalid_argument for a walk the generator rejects (as generateWalk).
struct WalkAndReplay {
  WalkOutcome walk;
  std::optional<ReplayOutcome> replay;
  std::string replay_failure;  // why the replay failed (one line); empty when it did not
  bool walk_succeeded = true;  // the walk's own success, before a failed replay was recorded
  // The walk's datasets compressed while the replay ran (replay_threads > 1), for the writer.
  std::optional<datasets::PreparedRun> prepared_walk;
};
WalkAndReplay runWalkAndReplay(const robots::RobotModel* model, const datasets::Scenario& scenario,
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
// dataset, with their minima; none without obstacles.
struct FootstepCheck {
  datasets::FootstepClearances clearances;
  ObstacleClearances least;
};
std::optional<FootstepCheck> checkScenarioFootsteps(const datasets::Scenario& scenario,
                                                    const WalkResult& result);

}  // namespace wpg::engine
