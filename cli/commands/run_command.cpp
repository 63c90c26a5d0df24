// `wpg run`: scenario file -> the engine's run (the walk, or the walk to a goal, -> multibody
// replay and dynamic filter) -> HDF5 dataset (+ figure) and a short summary.
#include <algorithm>
#include <iostream>
#include <thread>

#include "command_options.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "summary_printing.hpp"
#include "wpg/analysis/run_summary.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/engine/scenario_request.hpp"
#include "wpg/engine/scenario_run.hpp"

namespace wpg::cli {

int runCommand(const RunOptions& options) {
  for (const std::string& item : options.overrides) {
    const auto equal = item.find('=');
    if (equal == std::string::npos || equal == 0) {
      throw UsageError("--set '" + item + "': expected key=value (e.g. --set duration=5)");
    }
  }
  // The engine checks the scenario, the robot's model, the filter, the goal and both outputs
  // before anything runs or is written.
  engine::RobotModelCache models(robotsDirectory());
  const engine::LoadedScenario loaded = engine::loadScenarioRequest(
      {options.scenario, options.overrides, options.replay, options.filter}, models);
  const datasets::Scenario& scenario = loaded.scenario;
  const engine::RunOutputs outputs = engine::runOutputsOf(loaded, options.output, options.plot);
  engine::checkRunOutputs(loaded, outputs);
  // The input is accepted: what it warns about (a clamped command, an implausible value), on
  // stderr and in the dataset.
  printWarnings(scenario.warnings);

  // One walk: its validation replay may use every core (the results do not depend on it).
  const engine::RunResult result = engine::runScenario(
      scenario, {robotsDirectory(), &models,
                 static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))});
  const WalkResult& walk = result.walk.result;
  engine::saveRun(loaded, result, outputs.dataset);

  printRunSummary(std::cout, scenario, analysis::summarizeRun(walk.trajectory));
  if (result.footsteps) printObstacleClearances(std::cout, result.footsteps->least);
  if (result.walk.goal) printGoalSummary(std::cout, result.walk);
  if (result.replay) printMultibodySummary(std::cout, *result.replay);
  reportDatasetAndFigure(outputs.dataset, outputs.figure, options.plot);
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
