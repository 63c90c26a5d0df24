// `wpg run`: scenario file -> generateWalk, or the walk to a goal (-> multibody replay and
// dynamic filter) -> HDF5 dataset (+ figure) and a short summary.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <system_error>
#include <thread>

#include "cli_common.hpp"
#include "pipeline_stages.hpp"
#include "study_execution.hpp"
#include "summary_printing.hpp"
#include "wpg/analysis/run_summary.hpp"
#include "wpg/datasets/input_error.hpp"
#include "wpg/datasets/output_file.hpp"
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
  checkGoalRequest(scenario, scenario_path);

  const fs::path dataset_path =
      options.output.empty() ? fs::path("out") / (scenario.name + ".h5") : fs::path(options.output);
  fs::path figure_path = fs::path(dataset_path).replace_extension(".png");
  if (figure_path == dataset_path) figure_path += ".png";  // never draw over the dataset
  // Never replace an input, a device, a folder or a file of another kind (output_file.hpp).
  const std::vector<std::string> inputs = {
      scenario_path, (fs::path(robotsDirectory()) / scenario.robot / "walking.yaml").string(),
      robotUrdfPath(scenario.robot)};
  try {
    datasets::checkOutputPath(dataset_path.string(), datasets::OutputKind::kHdf5, inputs);
    if (options.plot)
      datasets::checkOutputPath(figure_path.string(), datasets::OutputKind::kPng, inputs);
  } catch (const datasets::InputError& e) {
    throw UsageError(e.what());
  }
  std::error_code ec;
  checkWritableParent(dataset_path);

  ScenarioRun run;
  try {
    // One walk: the validation replay may use every core (its results do not depend on it).
    run = runScenario(model ? &*model : nullptr, scenario,
                      static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  } catch (const std::invalid_argument& e) {
    throw UsageError(aboutFile(scenario_path, e.what()));
  }
  const WalkOutcome& walk = run.walk;
  const WalkResult& result = walk.result;
  const std::optional<ReplayOutcome>& replay = run.replay;

  if (dataset_path.has_parent_path()) {
    fs::create_directories(dataset_path.parent_path(), ec);
    if (ec) {
      throw UsageError("cannot create the folder of '" + dataset_path.string() + "': " + ec.message());
    }
  }
  std::optional<ObstacleClearances> clearances;  // when the FCL world checked the steps
  try {
    clearances = writeScenarioDataset(dataset_path.string(), scenario, result,
                                      replay ? &replay->validation : nullptr,
                                      walk.goal ? &*walk.goal : nullptr);
  } catch (const std::invalid_argument& e) {
    // an inconsistent trajectory is a bug, not bad input
    throw std::runtime_error(std::string("cannot write the dataset: ") + e.what());
  }

  printRunSummary(std::cout, scenario, analysis::summarizeRun(result.trajectory));
  if (clearances) printObstacleClearances(std::cout, *clearances);
  if (walk.goal) printGoalSummary(std::cout, walk);
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
