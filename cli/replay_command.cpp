// `wpg replay RUN.h5`: an existing run dataset -> its walk and scenario -> multibody replay
// and dynamic filter -> the dataset again with the multibody fields (datasets/SCHEMA.md).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "cli_common.hpp"
#include "pipeline_stages.hpp"
#include "summary_printing.hpp"
#include "wpg/datasets/input_error.hpp"
#include "wpg/datasets/output_file.hpp"
#include "wpg/datasets/run_dataset_reader.hpp"
#include "wpg/datasets/scenario.hpp"
#include "wpg/datasets/stored_run_consistency.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {

int replayCommand(const ReplayOptions& options) {
  // Everything about the input is checked before anything is computed or written.
  datasets::StoredRun stored;
  datasets::Scenario scenario;
  const std::string origin = options.input + ":/scenario";
  try {
    stored = datasets::readRunDataset(options.input);
    // The file's resolved scenario, with the replay switched on: the rewritten dataset's
    // scenario says what ran.
    scenario = datasets::loadScenarioText(
        stored.scenario_yaml, origin,
        // A stored walk can only be filtered offline: the online loop (Fig. 3) filters while
        // the walk is generated, and re-initialises the WPG (mode online or both).
        {"replay=true", std::string("filter=") + (options.filter ? "true" : "false"),
         "filter_settings.mode=offline"},
        robotsDirectory());
    // A walk the stored scenario did not generate would be replayed at the wrong period.
    datasets::checkStoredRunMatchesScenario(options.input, stored, scenario);
  } catch (const datasets::InputError& e) {
    throw UsageError(e.what());
  }
  if (scenario.name != stored.name) {
    throw UsageError(options.input + ": the run /runs/" + stored.name +
                     " does not belong to its scenario '" + scenario.name + "'");
  }
  const robots::RobotModel model = loadRobotModel(scenario.robot);
  if (scenario.filter) checkFilterSettings(scenario, origin);

  const fs::path dataset_path = options.output.empty() ? fs::path(options.input)
                                                       : fs::path(options.output);
  fs::path figure_path = fs::path(dataset_path).replace_extension(".png");
  if (figure_path == dataset_path) figure_path += ".png";  // never draw over the dataset
  // The run file is replaced by default (atomically); no device, folder, robot file or file of
  // another kind is (output_file.hpp).
  const std::vector<std::string> inputs = {
      (fs::path(robotsDirectory()) / scenario.robot / "walking.yaml").string(),
      robotUrdfPath(scenario.robot)};
  try {
    datasets::checkOutputPath(dataset_path.string(), datasets::OutputKind::kHdf5, inputs);
    if (options.plot) {
      std::vector<std::string> figure_inputs = inputs;
      figure_inputs.push_back(options.input);
      datasets::checkOutputPath(figure_path.string(), datasets::OutputKind::kPng, figure_inputs);
    }
  } catch (const datasets::InputError& e) {
    throw UsageError(e.what());
  }
  std::error_code ec;

  const WalkTrajectory& walk = stored.result.trajectory;
  // A stored walk the replay cannot follow is bad input: there is nothing to write.
  if (walk.size() < 3) {
    throw UsageError(options.input + ": the run /runs/" + stored.name + " has " +
                     std::to_string(walk.size()) + " samples, the replay needs at least 3");
  }
  ReplayOutcome replay;
  try {
    replay = replayScenarioWalk(model, scenario, walk, scenario.filter,
                                static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  } catch (const std::runtime_error& e) {
    throw UsageError(options.input + ": " + e.what());
  }

  if (dataset_path.has_parent_path()) {
    fs::create_directories(dataset_path.parent_path(), ec);
    if (ec) {
      throw UsageError("cannot create the folder of '" + dataset_path.string() + "': " +
                       ec.message());
    }
  }
  std::optional<ObstacleClearances> clearances;
  try {
    // Atomic (temporary file, then rename): overwriting RUN.h5 never leaves half a file.
    clearances = writeScenarioDataset(dataset_path.string(), scenario, stored.result,
                                      &replay.validation);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string("cannot write the dataset: ") + e.what());
  }

  std::cout << "run       " << scenario.name << " from " << options.input << ", robot "
            << scenario.robot << ": " << walk.size() << " samples, "
            << fixed(replay.walk_duration, 2) << " s, " << walk.mpc.size() << " NMPC iterations"
            << (stored.result.success ? std::string()
                                      : " (the walk failed: " + stored.result.message + ")")
            << '\n';
  if (clearances) printObstacleClearances(std::cout, *clearances);
  printMultibodySummary(std::cout, replay);
  reportDatasetAndFigure(dataset_path.string(), figure_path.string(), options.plot);
  return kExitSuccess;
}

}  // namespace wpg::cli
