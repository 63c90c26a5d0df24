// Shared steps of `wpg run`, `wpg replay` and `wpg bench` (walk_pipeline.hpp).
#include "walk_pipeline.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <system_error>

#include "cli_common.hpp"
#include "wpg/datasets/run_dataset.hpp"
#include "wpg/preview_control.hpp"
#include "wpg/robots/walk_replay.hpp"

// The FCL world of planning/ (one obstacle model for the NMPC and the footstep checks), used as
// soon as the executable links wpg_planning (its headers are then on the include path).
// Without it, generateWalk measures obstacles with libwpg's exact 2-D distance and the dataset
// holds the step-centre clearances only.
#if __has_include("wpg/planning/obstacle_checks.hpp")
#define WPG_CLI_WITH_PLANNING 1
#include "wpg/planning/obstacle_checks.hpp"
#include "wpg/planning/world.hpp"
#endif

namespace fs = std::filesystem;

namespace wpg::cli {

std::string fixed(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
  return buffer;
}

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

WalkResult generateScenarioWalk(const datasets::Scenario& scenario) {
  return generateWalk(scenario.walking, scenario.request);
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
  outcome.walk_duration = walk.time.empty() ? 0.0 : walk.time.back() - walk.time.front();
  return outcome;
}

std::string writeScenarioDataset(const std::string& path, const datasets::Scenario& scenario,
                                 const WalkResult& result, const MultibodyValidation* multibody) {
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
    return "obstacles " + std::to_string(world.obstacleCount()) +
           "; least clearance to the margins: step centre " +
           fixed(report.min_centre_clearance, 3) + " m, sole " + fixed(report.min_clearance, 3) +
           " m; sole to obstacle " + fixed(report.min_foot_distance, 3) + " m\n";
  }
#endif
  datasets::writeRunDataset(path, scenario, result, nullptr, multibody);
  return "";
}

void printMultibodySummary(std::ostream& out, const ReplayOutcome& outcome) {
  const MultibodyValidation& v = outcome.validation;
  const bool filtered = v.com_filtered.size() > 0;
  if (filtered) {
    out << "multibody ZMP error  RMS " << fixed(1e3 * v.before.rms, 1) << " mm -> "
        << fixed(1e3 * v.after.rms, 1) << " mm, max " << fixed(1e3 * v.before.max, 1)
        << " mm -> " << fixed(1e3 * v.after.max, 1) << " mm (dynamic filter)\n";
  } else {
    out << "multibody ZMP error  RMS " << fixed(1e3 * v.before.rms, 1) << " mm, max "
        << fixed(1e3 * v.before.max, 1) << " mm (no filter)\n";
  }
  char errors[96];
  std::snprintf(errors, sizeof errors, "max error CoM %.1e m, feet %.1e m", v.max_ik_com_error,
                v.max_ik_foot_error);
  out << "IK        "
      << (v.ik_failures == 0 ? std::string("solved on every sample")
                             : std::to_string(v.ik_failures) + " samples NOT solved")
      << " (" << errors << "); ";
  if (v.samples_with_limit_violations == 0) {
    out << "joint limits respected\n";
  } else {
    std::string joints;
    for (const std::string& joint : v.violated_joints) joints += (joints.empty() ? "" : ", ") + joint;
    out << v.samples_with_limit_violations << " samples outside joint limits (max "
        << fixed(v.max_limit_violation, 3) << " rad: " << joints << ")\n";
  }
  const Eigen::VectorXd& chain = v.chain_time;
  if (chain.size() > 0) {
    const double average = chain.mean();
    const double std_dev =
        chain.size() > 1
            ? std::sqrt((chain.array() - average).square().sum() / double(chain.size() - 1))
            : 0.0;
    out << "chain     per NMPC iteration " << fixed(1e3 * average, 3) << " ms average, std "
        << fixed(1e3 * std_dev, 3) << ", min " << fixed(1e3 * chain.minCoeff(), 3) << ", max "
        << fixed(1e3 * chain.maxCoeff(), 3) << " ms; replay" << (filtered ? " + filter " : " ")
        << fixed(outcome.realTimeFactor(), 0) << "x real time\n";
  }
}

void reportDatasetAndFigure(const std::string& dataset_path, const std::string& figure_path,
                            bool plot) {
  std::cout << "dataset   " << dataset_path << '\n';
  if (!plot) return;
  std::cout.flush();
  if (drawFigure(dataset_path, figure_path) == kExitSuccess) {
    std::cout << "figure    " << figure_path << '\n';
  } else {
    printWarning("no figure drawn (the dataset is complete; retry with `wpg plot " +
                 dataset_path + "`)");
  }
}

}  // namespace wpg::cli
