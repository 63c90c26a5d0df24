// What the Python package asks of the engine, as the `wpg` subcommands do it (cli/commands/).
#include "engine_calls.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"
#include "wpg/datasets/study_design/study.hpp"
#include "wpg/engine/comparison_run.hpp"
#include "wpg/engine/run_input_checks.hpp"
#include "wpg/engine/stored_runs.hpp"
#include "wpg/engine/study_executor.hpp"
#include "wpg/engine/study_summary.hpp"

namespace fs = std::filesystem;

namespace wpg::python {
namespace {

using datasets::InputError;

// Every bad-input message names the scenario file (the loader's messages usually do already).
std::string aboutFile(const std::string& path, const std::string& message) {
  if (message.find(path) != std::string::npos) return message;
  return path + ": " + message;
}

void requireJobs(int jobs) {
  if (jobs < 1) throw InputError("jobs: expected a number of worker threads >= 1, got " +
                                 std::to_string(jobs));
}

void requireStudyFile(const std::string& study) {
  std::error_code ec;
  if (!fs::is_regular_file(study, ec)) {
    throw InputError(study + ": cannot read the study file: no such file");
  }
}

}  // namespace

std::shared_ptr<RunSession> runScenarioFile(const std::string& scenario,
                                            std::vector<std::string> overrides, bool replay,
                                            bool filter) {
  auto run = std::make_shared<RunSession>();
  run->scenario_path = resolveScenarioPath(scenario);
  // As `wpg run --replay --filter`: after every override, so the stored scenario says what ran.
  if (replay) overrides.push_back("replay=true");
  if (filter) overrides.push_back("filter=true");
  try {
    run->scenario = datasets::loadScenario(run->scenario_path, overrides, robotsDirectory());
  } catch (const InputError& e) {
    throw InputError(aboutFile(run->scenario_path, e.what()));
  } catch (const std::invalid_argument& e) {
    throw InputError(aboutFile(run->scenario_path, e.what()));
  }
  engine::RobotModelCache models(robotsDirectory());
  engine::checkRunInput(run->scenario, run->scenario_path, models);
  run->result = engine::runScenario(run->scenario, {robotsDirectory(), &models});
  return run;
}

void saveRun(const RunSession& run, const std::string& path) {
  if (!run.stored_file.empty()) {
    throw InputError("save: a run read back from '" + run.stored_file +
                     "' is already stored there (wpg.run() gives runs to save)");
  }
  const fs::path dataset_path(path);
  const std::string robots = robotsDirectory();
  const std::vector<std::string> inputs = {
      run.scenario_path, (fs::path(robots) / run.scenario.robot / "walking.yaml").string(),
      engine::robotUrdfPath(robots, run.scenario.robot)};
  datasets::checkOutputPath(path, datasets::OutputKind::kHdf5, inputs);
  datasets::checkWritableParent(path);
  std::error_code ec;
  if (dataset_path.has_parent_path()) {
    fs::create_directories(dataset_path.parent_path(), ec);
    if (ec) throw InputError("cannot create the folder of '" + path + "': " + ec.message());
  }
  engine::writeRunDataset(path, run.scenario, run.result);
}

std::vector<std::string> storedRunNames(const std::string& path) {
  return datasets::listRuns(path);
}

std::shared_ptr<RunSession> loadStoredRun(const std::string& path, const std::string& name) {
  auto run = std::make_shared<RunSession>();
  // As `wpg analyze`: the walk checked against its stored scenario, the metrics recomputed
  // from it with the stored ZMP errors.
  engine::StoredRunAnalysis analyzed = engine::analyzeStoredRun(path, name, robotsDirectory());
  datasets::StoredRun& stored = analyzed.stored;
  run->stored_file = path;
  run->stored_name = stored.name;
  run->scenario = std::move(analyzed.scenario);
  engine::RunResult& result = run->result;
  result.metrics = std::move(analyzed.metrics);
  result.outcome = engine::walkOutcome(stored.result);
  result.failure = stored.result.message;
  result.walk.result = std::move(stored.result);
  return run;
}

StudyFiles runBatch(const std::string& study_path, const std::string& output, int jobs,
                    bool resume) {
  requireJobs(jobs);
  if (output.empty()) throw InputError("output: expected the batch file to write (OUT.h5)");
  requireStudyFile(study_path);
  // Everything about the input is checked before anything is written (`wpg batch`).
  const datasets::Study study = datasets::loadStudy(
      study_path, [](const std::string& base) { return resolveScenarioPath(base); },
      robotsDirectory(), jobs);
  datasets::checkOutputPath(output, datasets::OutputKind::kHdf5, {study_path});
  datasets::checkWritableParent(output);
  engine::checkStudyRobotModels(study, robotsDirectory());

  engine::StudyRunHandling handling;
  handling.columns = engine::runSummaryColumns();
  handling.summary_values = [](const datasets::StudyRun&, const engine::RunResult& result) {
    return engine::runSummaryValues(result);
  };
  engine::StudyObserver quiet;
  engine::makeThreadExecutor(jobs, robotsDirectory())
      ->run(study, engine::StudyOutput{output, resume, std::nullopt}, handling, quiet);
  const engine::BatchSummaryFiles files = engine::writeBatchSummaryFiles(output);
  return {output, files.runs, files.failed_runs};
}

StudyFiles runCompare(const std::string& study_path, const std::string& folder_path, int jobs) {
  requireJobs(jobs);
  if (folder_path.empty()) throw InputError("output: expected the folder to write (DIR)");
  requireStudyFile(study_path);
  const fs::path folder(folder_path);
  const fs::path batch_file = folder / "study.h5";
  // Everything about the input is checked before anything is written (`wpg compare`).
  const datasets::ComparisonStudy comparison = datasets::loadComparisonStudy(
      study_path, [](const std::string& base) { return resolveScenarioPath(base); },
      robotsDirectory(), jobs);
  for (const datasets::StudyRun& run : comparison.study.runs) {
    if (!run.scenario.goal.enabled) {
      throw InputError(study_path + ": world '" +
                       comparison.worlds[comparison.runs[run.index].world] +
                       "': expected a walk to a goal (a scenario with `goal:`)");
    }
  }
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
    throw InputError("output '" + folder.string() + "' is not a directory");
  }
  datasets::checkWritableParent(batch_file.string());
  engine::checkStudyRobotModels(comparison.study, robotsDirectory());

  fs::create_directories(folder, ec);
  if (ec) throw InputError("cannot create the folder '" + folder_path + "': " + ec.message());
  engine::StudyObserver quiet;
  const std::unique_ptr<engine::StudyExecutor> executor =
      engine::makeThreadExecutor(jobs, robotsDirectory());
  const engine::ComparisonOutcome outcome =
      engine::runComparison(comparison, batch_file.string(), *executor, quiet);
  engine::writeComparisonTableFiles(comparison, outcome.cells, folder.string());
  StudyFiles files{batch_file.string(), comparison.study.runs.size(), 0};
  return files;
}

}  // namespace wpg::python
