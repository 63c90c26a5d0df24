// The pipeline of one scenario, stage by stage (pipeline_stages.hpp).
#include "pipeline_stages.hpp"

#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "cli_common.hpp"
#include "wpg/analysis/chain_timing.hpp"
#include "wpg/analysis/run_summary.hpp"
#include "wpg/datasets/run_dataset.hpp"
#include "wpg/preview_control.hpp"
#include "wpg/robots/walk_replay.hpp"

// The FCL world of planning/ (the post-run footstep checks), used as soon as the executable
// links wpg_planning (its headers are then on the include path). Without it the dataset holds
// the step-centre clearances only, computed by datasets/ with libwpg's exact 2-D distances.
#if __has_include("wpg/planning/obstacle_checks.hpp")
#define WPG_CLI_WITH_PLANNING 1
#include "wpg/planning/obstacle_checks.hpp"
#include "wpg/planning/world.hpp"
#endif

namespace fs = std::filesystem;

namespace wpg::cli {

std::string robotUrdfPath(const std::string& robot) {
  return (fs::path(robotsDirectory()) / robot / (robot + ".urdf")).string();
}

robots::RobotModel loadRobotModel(const std::string& robot) {
  const std::string path = robotUrdfPath(robot);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw UsageError("robot '" + robot + "' has no multibody model for the replay: " + path +
                     " not found (a robot folder needs <robot>.urdf to be replayed)");
  }
  try {
    return robots::RobotModel(path);
  } catch (const std::exception& e) {
    throw UsageError("cannot load the multibody model of robot '" + robot + "' (" + path +
                     "): " + e.what());
  }
}

void checkFilterSettings(const datasets::Scenario& scenario, const std::string& scenario_path) {
  try {
    const PreviewController controller(scenario.walking.control_period,
                                       scenario.walking.com_height, scenario.walking.gravity,
                                       scenario.filter_settings);
    (void)controller;
  } catch (const std::exception& e) {
    throw UsageError(scenario_path + ": key 'filter_settings': no preview controller for these "
                     "weights (" + e.what() + ")");
  }
}

double ReplayOutcome::realTimeFactor() const {
  return analysis::realTimeFactor(walk_duration, wall_time);
}

ReplayOutcome replayScenarioWalk(const robots::RobotModel& model,
                                 const datasets::Scenario& scenario, const WalkTrajectory& walk,
                                 bool filter) {
  robots::WalkReplaySettings settings;
  settings.filter = filter;
  settings.preview = scenario.filter_settings;
  ReplayOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  try {
    outcome.validation =
        robots::replayWalk(model, scenario.walking, scenario.request, walk, settings);
  } catch (const std::invalid_argument& e) {
    // a walk too short to replay (a fall in the first samples) is a failed run, not bad input
    throw std::runtime_error(std::string("cannot replay the walk: ") + e.what());
  }
  outcome.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.walk_duration = analysis::walkDuration(walk);
  return outcome;
}

std::optional<ObstacleClearances> writeScenarioDataset(const std::string& path,
                                                       const datasets::Scenario& scenario,
                                                       const WalkResult& result,
                                                       const MultibodyValidation* multibody) {
#ifdef WPG_CLI_WITH_PLANNING
  if (!scenario.request.obstacles.empty()) {
    const planning::World world(scenario.request.obstacles);
    const planning::FootstepObstacleReport report =
        planning::checkFootsteps(world, scenario.walking, result.trajectory);
    datasets::FootstepClearances clearances;
    clearances.clearance = report.clearance;
    clearances.clearance_obstacle = report.clearance_obstacle;
    clearances.foot_distance = report.foot_distance;
    datasets::writeRunDataset(path, scenario, result, &clearances, multibody);
    ObstacleClearances least;
    least.obstacle_count = world.obstacleCount();
    least.step_centre = report.min_centre_clearance;
    least.step_centre_bound = stepCentreBoundName(scenario.walking);
    least.sole = report.min_clearance;
    least.sole_to_obstacle = report.min_foot_distance;
    return least;
  }
#endif
  datasets::writeRunDataset(path, scenario, result, nullptr, multibody);
  return std::nullopt;
}

}  // namespace wpg::cli
