// `wpg replay RUN.h5`: an existing run dataset -> its walk and scenario -> the engine's replay
// on the multibody model with the dynamic filter -> the dataset again with the multibody fields
// (datasets/SCHEMA.md).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "command_options.hpp"
#include "exit_codes.hpp"
#include "summary_printing.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/run_input_checks.hpp"
#include "wpg/engine/stored_runs.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {

int replayCommand(const ReplayOptions& options) {
  // Everything about the input is checked before anything is computed or written.
  const engine::StoredRunReplay run =
      engine::loadRunForReplay(options.input, options.filter, robotsDirectory());
  const datasets::Scenario& scenario = run.scenario;
  const robots::RobotModel model = engine::loadRobotModel(robotsDirectory(), scenario.robot, scenario.multibody);
  if (scenario.filter) engine::checkFilterSettings(scenario, run.origin);

  const fs::path dataset_path = options.output.empty() ? fs::path(options.input)
                                                       : fs::path(options.output);
  fs::path figure_path = fs::path(dataset_path).replace_extension(".png");
  if (figure_path == dataset_path) figure_path += ".png";  // never draw over the dataset
  // The run file is replaced by default (atomically); no device, folder, robot file or file of
  // another kind is (output_file.hpp).
  const std::vector<std::string> inputs = {
      engine::robotWalkingFilePath(robotsDirectory(), scenario.robot),
      engine::robotUrdfPath(robotsDirectory(), scenario.robot, scenario.multibody)};
  datasets::checkOutputPath(dataset_path.string(), datasets::OutputKind::kHdf5, inputs);
  if (options.plot) {
    std::vector<std::string> figure_inputs = inputs;
    figure_inputs.push_back(options.input);
    datasets::checkOutputPath(figure_path.string(), datasets::OutputKind::kPng, figure_inputs);
  }

  // A stored walk the replay cannot follow is bad input: there is nothing to write.
  const engine::RunResult result = engine::replayStoredRun(
      run, model, static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));

  std::error_code ec;
  if (dataset_path.has_parent_path()) {
    fs::create_directories(dataset_path.parent_path(), ec);
    if (ec) {
      throw UsageError("cannot create the folder of '" + dataset_path.string() + "': " +
                       ec.message());
    }
  }
  try {
    // Atomic (temporary file, then rename): overwriting RUN.h5 never leaves half a file.
    engine::writeRunDataset(dataset_path.string(), scenario, result);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string("cannot write the dataset: ") + e.what());
  }

  const WalkResult& walk = result.walk.result;
  const engine::ReplayOutcome& replay = *result.replay;
  std::cout << "run       " << scenario.name << " from " << options.input << ", robot "
            << scenario.robot << ": " << walk.trajectory.size() << " samples, "
            << fixed(replay.walk_duration, 2) << " s, " << walk.trajectory.mpc.size()
            << " NMPC iterations"
            << (walk.success ? std::string() : " (the walk failed: " + walk.message + ")") << '\n';
  if (result.footsteps) printObstacleClearances(std::cout, result.footsteps->least);
  printMultibodySummary(std::cout, replay);
  reportDatasetAndFigure(dataset_path.string(), figure_path.string(), options.plot);
  return kExitSuccess;
}

}  // namespace wpg::cli
