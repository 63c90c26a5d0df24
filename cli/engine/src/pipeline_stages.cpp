// The pipeline of one scenario, stage by stage (pipeline_stages.hpp).
#include "wpg/engine/pipeline_stages.hpp"

#include <chrono>
#include <future>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "wpg/analysis/chain_timing.hpp"
#include "wpg/analysis/run_summary.hpp"
#include "wpg/planning/goal_walk.hpp"
#include "wpg/planning/obstacle_checks.hpp"
#include "wpg/planning/world.hpp"
#include "wpg/engine/robot_models.hpp"
#include "wpg/robots/online_filter_loop.hpp"
#include "wpg/robots/walk_replay.hpp"

namespace wpg::engine {

namespace {

// The walk of the scenario as WalkOutcome's stage records it: generateWalk, or the walk to its
// goal with its plans and outcome; `observer` (may be null) around every control period.
WalkOutcome scenarioWalk(const datasets::Scenario& scenario, ControlLoopObserver* observer) {
  WalkOutcome outcome;
  if (!scenario.goal.enabled) {
    outcome.result = generateWalk(scenario.walking, scenario.request, {}, observer);
    return outcome;
  }
  planning::GoalWalkResult walk =
      planning::walkToGoal(scenario.walking, scenario.request, scenario.goal, {}, observer);
  outcome.result = std::move(walk.walk);
  outcome.planning_time = walk.planning_time;
  outcome.replans = walk.plans.empty() ? 0 : static_cast<int>(walk.plans.size()) - 1;
  if (!walk.plans.empty()) outcome.route_length = walk.plans.front().plan.length;
  datasets::GoalOutcome& goal = outcome.goal.emplace();
  goal.goal_reached = walk.goal_reached;
  goal.time_to_goal = walk.time_to_goal;
  goal.final_pose = walk.final_pose;
  goal.final_distance = walk.final_distance;
  goal.final_yaw_error = walk.final_yaw_error;
  goal.outcome = walk.outcome;
  goal.status_codes = planning::planStatusCodes();
  goal.trigger_codes = planning::planTriggerCodes();
  for (const planning::PlanRecord& record : walk.plans) {
    datasets::RoutePlanRecord row;
    const planning::PlanStatistics& stats = record.plan.statistics;
    row.time = record.time;
    row.trigger = static_cast<int>(record.trigger);
    row.status = static_cast<int>(record.plan.status);
    row.start = record.start;
    row.known_obstacles = record.known_obstacles;
    row.planning_time = stats.time;
    row.route_length = record.plan.length;
    row.solution_length = stats.solution_length;
    row.simplified_solution_length = stats.simplified_solution_length;
    row.solution_clearance = stats.solved ? stats.solution_clearance : 0.0;
    row.simplification_time = stats.simplification_time;
    row.graph_states = stats.graph_states;
    row.graph_motions = stats.graph_motions;
    row.iterations = stats.iterations;
    row.route = record.plan.waypoints;
    goal.plans.push_back(std::move(row));
  }
  return outcome;
}

}  // namespace

WalkOutcome runScenarioWalk(const datasets::Scenario& scenario) {
  return scenarioWalk(scenario, nullptr);
}

double ReplayOutcome::realTimeFactor() const {
  return analysis::realTimeFactor(walk_duration, wall_time);
}

namespace {

const char* const kNotFinite =
    "cannot replay the walk: the joint angles, the filtered CoM or the multibody ZMP are not "
    "finite";

bool allFinite(const MultibodyValidation& v) {
  return v.q.allFinite() && v.com_filtered.allFinite() && v.zmp_multibody.allFinite() &&
         v.zmp_multibody_filtered.allFinite();
}

}  // namespace

ReplayOutcome replayScenarioWalk(const robots::RobotModel& model,
                                 const datasets::Scenario& scenario, const WalkTrajectory& walk,
                                 bool filter, int threads) {
  robots::WalkReplaySettings settings;
  settings.filter = filter;
  settings.threads = threads;
  settings.preview = scenario.filter_settings;
  settings.ik = walkingIkSettings(scenario.multibody);
  ReplayOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  try {
    outcome.validation =
        robots::replayWalk(model, scenario.walking, scenario.request, walk, settings);
  } catch (const std::invalid_argument& e) {
    // a walk too short to replay (a fall in the first samples) is a failed run, not bad input
    throw std::runtime_error(std::string("cannot replay the walk: ") + e.what());
  }
  // The replay is a stage with its own verdict: a motion it could not follow (joint angles or a
  // filtered CoM that are not finite) is a failed replay, never numbers in the dataset.
  if (!allFinite(outcome.validation)) throw std::runtime_error(kNotFinite);
  outcome.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.walk_duration = analysis::walkDuration(walk);
  return outcome;
}

namespace {

// A walk the replay cannot follow fails the run; the walk is still written (exit 1).
void recordReplayFailure(WalkAndReplay& run, const std::string& why) {
  WalkResult& result = run.walk.result;
  run.walk_succeeded = result.success;
  result.success = false;
  result.message = result.message.empty() ? why : result.message + "; " + why;
  run.replay_failure = why;
}

}  // namespace

WalkAndReplay runWalkAndReplay(const robots::RobotModel* model,
                               const datasets::Scenario& scenario, int replay_threads) {
  WalkAndReplay run;
  const bool online = scenario.filter && model != nullptr &&
                      scenario.filter_loop.mode != DynamicFilterMode::kOffline;
  if (!online) {
    run.walk = runScenarioWalk(scenario);
    if (!model) return run;
    WalkResult& result = run.walk.result;
    // Long enough by the scenario's duration (checked when it was loaded); a walk that fell in
    // its first samples is not, and is written without the multibody fields.
    if (result.trajectory.size() < 3) {
      recordReplayFailure(run, "the walk is too short to replay (" +
                                      std::to_string(result.trajectory.size()) +
                                      " samples, the replay needs 3)");
      return run;
    }
    // A single run with cores to spare: the walk's datasets are compressed on one of them
    // while the replay runs (the validation's Simbody part uses every core only at its end), so
    // that writing the file is shorter. The same bytes either way.
    std::future<datasets::PreparedRun> preparing;
    if (replay_threads > 1) {
      try {
        preparing = std::async(std::launch::async,
                               [&] { return datasets::prepareWalkDatasets(scenario, result); });
      } catch (const std::system_error&) {  // no thread to spare
      }
    }
    std::optional<std::string> replay_failure;
    try {
      run.replay = replayScenarioWalk(*model, scenario, result.trajectory, scenario.filter,
                                      replay_threads);
    } catch (const std::runtime_error& e) {
      replay_failure = e.what();
    }
    // Its errors are the writer's (bad input, out of memory): they stop the run as the
    // writer's would.
    if (preparing.valid()) run.prepared_walk = preparing.get();
    // After the preparation has read the result: a failed replay changes its message.
    if (replay_failure) recordReplayFailure(run, *replay_failure);
    return run;
  }
  robots::OnlineFilterLoopSettings settings;
  settings.preview = robots::onlinePreviewSettings(scenario.filter_settings, scenario.filter_loop);
  settings.reinitialize_wpg = scenario.filter_loop.reinitialize_wpg;
  settings.closed_loop = scenario.filter_loop.mode == DynamicFilterMode::kClosedLoop;
  settings.ik = walkingIkSettings(scenario.multibody);
  ReplayOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  robots::OnlineFilterRun loop;
  try {
    // The loop runs around the scenario's own walk: the velocity schedule, or the path
    // follower of a walk to a goal (its plans and outcome kept in run.walk).
    loop = robots::runOnlineFilterLoop(
        *model, scenario.walking, scenario.request, settings, [&](ControlLoopObserver& observer) {
          run.walk = scenarioWalk(scenario, &observer);
          return std::move(run.walk.result);
        });
  } catch (const std::runtime_error& e) {
    // The loop keeps no walk it cannot follow (one too short to replay): the walk is
    // generated again without the loop, and the run fails for the replay.
    run.walk = runScenarioWalk(scenario);
    recordReplayFailure(run, std::string("cannot replay the walk: ") + e.what());
    return run;
  }
  outcome.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.walk.result = std::move(loop.walk);
  outcome.validation = std::move(loop.validation);
  outcome.walk_duration = analysis::walkDuration(run.walk.result.trajectory);
  if (!allFinite(outcome.validation)) {
    recordReplayFailure(run, kNotFinite);
    return run;
  }
  if (scenario.filter_loop.mode == DynamicFilterMode::kBoth) {
    // The offline pass needs the open-loop walk (the online one's CoM jumps where the WPG was
    // re-initialised): generated again without the loop.
    const WalkResult open_loop = runScenarioWalk(scenario).result;
    try {
      const ReplayOutcome offline =
          replayScenarioWalk(*model, scenario, open_loop.trajectory, true);
      outcome.validation.has_offline_comparison = true;
      outcome.validation.offline_before = offline.validation.before;
      outcome.validation.offline_after = offline.validation.after;
    } catch (const std::runtime_error& e) {
      recordReplayFailure(run, std::string("offline pass: ") + e.what());
      return run;
    }
  }
  run.replay = std::move(outcome);
  return run;
}

std::optional<FootstepCheck> checkScenarioFootsteps(const datasets::Scenario& scenario,
                                                    const WalkResult& result) {
  if (scenario.request.obstacles.empty()) return std::nullopt;
  const planning::World world(scenario.request.obstacles);
  const planning::FootstepObstacleReport report =
      planning::checkFootsteps(world, scenario.walking, result.trajectory);
  FootstepCheck check;
  check.clearances.clearance = report.clearance;
  check.clearances.clearance_obstacle = report.clearance_obstacle;
  check.clearances.foot_distance = report.foot_distance;
  check.least.obstacle_count = world.obstacleCount();
  check.least.step_centre = report.min_centre_clearance;
  check.least.step_centre_bound = stepCentreBoundName(scenario.walking);
  check.least.sole = report.min_clearance;
  check.least.sole_to_obstacle = report.min_foot_distance;
  return check;
}

}  // namespace wpg::engine
