// `wpg run`: scenario file -> generateWalk (-> multibody replay and dynamic filter) -> HDF5
// dataset (+ figure) and a short summary.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <system_error>

#include <optional>

#include "cli_common.hpp"
#include "walk_pipeline.hpp"
#include "wpg/datasets/input_error.hpp"
#include "wpg/datasets/scenario.hpp"
#include "wpg/walk_generator.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

// Every bad-input message names the scenario file (the loader's messages usually do already).
std::string aboutFile(const std::string& path, const std::string& message) {
  if (message.find(path) != std::string::npos) return message;
  return path + ": " + message;
}

std::string format(const char* fmt, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, value);
  return buffer;
}

void printSummary(std::ostream& out, const datasets::Scenario& scenario, const WalkResult& result) {
  const WalkTrajectory& trajectory = result.trajectory;
  // Distance walked: length of the horizontal CoM path and net displacement.
  double path_length = 0.0;
  double displacement = 0.0;
  for (std::size_t i = 1; i < trajectory.com.size(); ++i) {
    path_length += (trajectory.com[i].head<2>() - trajectory.com[i - 1].head<2>()).norm();
  }
  if (!trajectory.com.empty()) {
    displacement = (trajectory.com.back().head<2>() - trajectory.com.front().head<2>()).norm();
  }
  // The two initial feet are the first two footsteps; every other one is a step taken.
  const std::size_t steps = trajectory.footsteps.size() > 2 ? trajectory.footsteps.size() - 2 : 0;
  const double duration = trajectory.time.empty() ? 0.0 : trajectory.time.back() - trajectory.time.front();

  std::map<int, int> status_counts;
  std::vector<double> solve_us;
  for (const MpcIterationLog& log : trajectory.mpc) {
    ++status_counts[static_cast<int>(log.status)];
    solve_us.push_back(log.solve_time * 1e6);
  }
  std::string statuses;
  for (const auto& [status, count] : status_counts) {
    statuses += (statuses.empty() ? "" : ", ") + std::to_string(count) + " " +
                iterationStatusName(static_cast<IterationStatus>(status));
  }

  out << "scenario  " << scenario.name << " (" << scenario.source_path << "), robot "
      << scenario.robot << ", " << generatorAlgorithmName(scenario.request.generator.algorithm)
      << '\n';
  out << "walked    " << format("%.3f", path_length) << " m along the CoM path, "
      << format("%.3f", displacement) << " m net displacement, " << steps << " steps in "
      << format("%.2f", duration) << " s\n";
  out << "status    " << (statuses.empty() ? std::string("no NMPC iterations") : statuses) << " ("
      << trajectory.mpc.size() << " NMPC iterations)\n";
  if (!solve_us.empty()) {
    std::sort(solve_us.begin(), solve_us.end());
    const std::size_t n = solve_us.size();
    const double median = n % 2 ? solve_us[n / 2] : 0.5 * (solve_us[n / 2 - 1] + solve_us[n / 2]);
    out << "solve     median " << format("%.0f", median) << " us, max "
        << format("%.0f", solve_us.back()) << " us per NMPC iteration\n";
  }
}

}  // namespace

int runCommand(const RunOptions& options) {
  const std::string scenario_path = resolveScenarioPath(options.scenario);
  for (const std::string& item : options.overrides) {
    const auto equal = item.find('=');
    if (equal == std::string::npos || equal == 0) {
      throw UsageError("--set '" + item + "': expected key=value (e.g. --set duration=5)");
    }
  }

  // --replay and --filter switch the scenario's keys on, after every --set (the filter implies
  // the replay), so that the resolved scenario in the dataset says what ran.
  std::vector<std::string> overrides = options.overrides;
  if (options.replay) overrides.push_back("replay=true");
  if (options.filter) overrides.push_back("filter=true");

  // Everything about the input is checked before anything is written.
  datasets::Scenario scenario;
  try {
    scenario = datasets::loadScenario(scenario_path, overrides, robotsDirectory());
    scenario.walking.validate();
    scenario.request.validate();
  } catch (const datasets::InputError& e) {
    throw UsageError(aboutFile(scenario_path, e.what()));
  } catch (const std::invalid_argument& e) {
    throw UsageError(aboutFile(scenario_path, e.what()));
  }
  // The robot's multibody model and the filter's controller before anything is generated.
  std::optional<robots::RobotModel> model;
  if (scenario.replay) {
    model.emplace(loadRobotModel(scenario.robot));
    if (scenario.filter) checkFilterSettings(scenario, scenario_path);
  }

  const fs::path dataset_path =
      options.output.empty() ? fs::path("out") / (scenario.name + ".h5") : fs::path(options.output);
  fs::path figure_path = fs::path(dataset_path).replace_extension(".png");
  if (figure_path == dataset_path) figure_path += ".png";  // never draw over the dataset
  std::error_code ec;
  if (fs::is_directory(dataset_path, ec)) {
    throw UsageError("output '" + dataset_path.string() + "' is a directory");
  }
  for (fs::path folder = dataset_path.parent_path(); !folder.empty(); folder = folder.parent_path()) {
    if (fs::exists(folder, ec)) {
      if (!fs::is_directory(folder, ec) || ::access(folder.c_str(), W_OK | X_OK) != 0) {
        throw UsageError("cannot write output '" + dataset_path.string() + "': '" +
                         folder.string() + "' is not a writable directory");
      }
      break;
    }
    if (folder == folder.parent_path()) break;
  }

  WalkResult result;
  try {
    result = generateScenarioWalk(scenario);
  } catch (const std::invalid_argument& e) {
    throw UsageError(aboutFile(scenario_path, e.what()));
  }
  std::optional<ReplayOutcome> replay;
  if (model) replay = replayScenarioWalk(*model, scenario, result.trajectory, scenario.filter);

  if (dataset_path.has_parent_path()) {
    fs::create_directories(dataset_path.parent_path(), ec);
    if (ec) {
      throw UsageError("cannot create the folder of '" + dataset_path.string() + "': " + ec.message());
    }
  }
  std::string obstacle_summary;  // one line of the summary when the FCL world checked the steps
  try {
    obstacle_summary = writeScenarioDataset(dataset_path.string(), scenario, result,
                                            replay ? &replay->validation : nullptr);
  } catch (const std::invalid_argument& e) {
    // an inconsistent trajectory is a bug, not bad input
    throw std::runtime_error(std::string("cannot write the dataset: ") + e.what());
  }

  printSummary(std::cout, scenario, result);
  std::cout << obstacle_summary;
  if (replay) printMultibodySummary(std::cout, *replay);
  reportDatasetAndFigure(dataset_path.string(), figure_path.string(), options.plot);
  if (!result.success) {
    std::cout.flush();
    printError("the walk failed: " + (result.message.empty() ? std::string("see mpc/status in the dataset")
                                                             : result.message) +
               " (dataset written)");
    return kExitRunFailed;
  }
  return kExitSuccess;
}

}  // namespace wpg::cli
