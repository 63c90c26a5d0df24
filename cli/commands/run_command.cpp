// `wpg run`: scenario file -> the engine's run (the walk, or the walk to a goal, -> multibody
// replay and dynamic filter) -> HDF5 dataset (+ figure) and a short summary.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "command_options.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "summary_printing.hpp"
#include "wpg/analysis/run_summary.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/run_input_checks.hpp"
#include "wpg/engine/scenario_run.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

// Every bad-input message names the scenario file (the loader's messages usually do already).
std::string aboutFile(const std::string& path, const std::string& message) {
  if (message.find(path) != std::string::npos) return message;
  return path + ": " + message;
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
  } catch (const datasets::InputError& e) {
    throw UsageError(aboutFile(scenario_path, e.what()));
  } catch (const std::invalid_argument& e) {
    throw UsageError(aboutFile(scenario_path, e.what()));
  }
  // The robot's multibody model, the filter's controller and the goal before anything runs.
  engine::RobotModelCache models(robotsDirectory());
  engine::checkRunInput(scenario, scenario_path, models);

  const fs::path dataset_path =
      options.output.empty() ? fs::path("out") / (scenario.name + ".h5") : fs::path(options.output);
  fs::path figure_path = fs::path(dataset_path).replace_extension(".png");
  if (figure_path == dataset_path) figure_path += ".png";  // never draw over the dataset
  // Never replace an input, a device, a folder or a file of another kind (output_file.hpp).
  const std::vector<std::string> inputs = {
      scenario_path, (fs::path(robotsDirectory()) / scenario.robot / "walking.yaml").string(),
      engine::robotUrdfPath(robotsDirectory(), scenario.robot)};
  datasets::checkOutputPath(dataset_path.string(), datasets::OutputKind::kHdf5, inputs);
  if (options.plot) datasets::checkOutputPath(figure_path.string(), datasets::OutputKind::kPng, inputs);
  datasets::checkWritableParent(dataset_path.string());
  // The input is accepted: what it warns about (a clamped command, an implausible value), on
  // stderr and in the dataset.
  printWarnings(scenario.warnings);

  // One walk: its validation replay may use every core (the results do not depend on it).
  const engine::RunResult result = engine::runScenario(
      scenario, {robotsDirectory(), &models,
                 static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))});
  const WalkResult& walk = result.walk.result;

  std::error_code ec;
  if (dataset_path.has_parent_path()) {
    fs::create_directories(dataset_path.parent_path(), ec);
    if (ec) {
      throw UsageError("cannot create the folder of '" + dataset_path.string() + "': " + ec.message());
    }
  }
  try {
    engine::writeRunDataset(dataset_path.string(), scenario, result);
  } catch (const std::invalid_argument& e) {
    // an inconsistent trajectory is a bug, not bad input
    throw std::runtime_error(std::string("cannot write the dataset: ") + e.what());
  }

  printRunSummary(std::cout, scenario, analysis::summarizeRun(walk.trajectory));
  if (result.footsteps) printObstacleClearances(std::cout, result.footsteps->least);
  if (result.walk.goal) printGoalSummary(std::cout, result.walk);
  if (result.replay) printMultibodySummary(std::cout, *result.replay);
  reportDatasetAndFigure(dataset_path.string(), figure_path.string(), options.plot);
  if (result.outcome != engine::RunOutcome::kSucceeded) {
    std::cout.flush();
    printError("the walk failed: " + (walk.message.empty() ? std::string("see mpc/status in the dataset")
                                                           : walk.message) +
               " (dataset written)");
    return kExitRunFailed;
  }
  return kExitSuccess;
}

}  // namespace wpg::cli
