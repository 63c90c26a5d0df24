// A comparison study end to end (comparison_study_run.hpp).
#include "wpg/engine/comparison_study_run.hpp"

#include <chrono>
#include <filesystem>
#include <system_error>

#include "study_request_checks.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/comparison_benchmark_logs.hpp"
#include "wpg/engine/data_paths.hpp"
#include "wpg/engine/run_input_checks.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {
namespace {

// The OMPL log folder's errors, named as the front end calls it.
template <typename Action>
auto aboutLogFolder(const StudyRequest& request, Action action) {
  try {
    return action();
  } catch (const datasets::InputError& e) {
    throw datasets::InputError(request.names.ompl_log + ": " + e.what());
  }
}

}  // namespace

std::string comparisonSliceFile(const std::string& folder, const ShardSlice& slice) {
  return (fs::path(folder) / "study.shards" /
          ("slice-" + std::to_string(slice.index) + "-of-" + std::to_string(slice.count) + ".h5"))
      .string();
}

ComparisonStudyResult runComparisonStudy(const StudyRequest& request, StudyObserver& observer) {
  checkStudyRequest(request, "the folder to write (DIR)");
  if (request.shard && !request.ompl_log.empty()) {
    throw datasets::InputError(request.names.ompl_log + ": not with " + request.names.shard +
                               " (the logs describe the whole study)");
  }
  const auto started = std::chrono::steady_clock::now();  // the study's wall time, in the logs
  const fs::path folder(request.output);
  ComparisonStudyResult result;
  result.study_file = (folder / "study.h5").string();
  result.runs_file =
      request.shard ? comparisonSliceFile(request.output, *request.shard) : result.study_file;
  datasets::ComparisonStudy comparison;
  const std::optional<MpiWorld> world = checkStudyInput(request, [&] {
    comparison = datasets::loadComparisonStudy(
        request.study, [](const std::string& base) { return resolveScenarioPath(base); },
        robotsDirectory(), request.jobs);
    for (const datasets::Study::CheckedRun& run : comparison.study.checked) {  // every run
      if (!run.goal) {
        throw datasets::InputError(request.study + ": world '" +
                                   comparison.worlds[comparison.runs[run.index].world] +
                                   "': expected a walk to a goal (a scenario with `goal:`)");
      }
    }
    std::error_code error;
    if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
      throw datasets::InputError("output '" + folder.string() + "' is not a directory");
    }
    // Every file written in DIR, held to the main output's rules (output_file.hpp); a slice
    // writes its shard file only.
    std::vector<datasets::PlannedOutput> outputs = {{result.runs_file, datasets::OutputKind::kHdf5}};
    if (!request.shard) {
      for (datasets::PlannedOutput& output :
           comparisonSideOutputs(result.study_file, comparison.worlds, request.figures)) {
        outputs.push_back(std::move(output));
      }
    }
    datasets::checkOutputPaths(outputs, {request.study});
    checkStudyRobotModels(comparison.study, robotsDirectory());
    if (!request.ompl_log.empty()) {
      aboutLogFolder(request, [&] { checkBenchmarkLogOutputs(request.ompl_log, comparison.worlds); });
    }
  });
  const datasets::Study& study = comparison.study;
  if (!world || world->rank == 0) observer.accepted(study.name, studyWarnings(study));
  result.runs = study.runs.size();
  if (request.shard) result.slice_runs = sliceRuns(study, *request.shard);

  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw datasets::InputError("cannot create the folder '" + folder.string() + "': " + ec.message());
  // An error while running (a full disk) leaves the runs written so far in the file, as a batch
  // does: a resume finishes it.
  const ComparisonOutcome outcome =
      runComparison(comparison, StudyOutput{result.runs_file, request.resume, request.shard},
                    *makeStudyExecutor(request, world), observer);
  if (outcome.complete && !request.shard) {
    result.complete = true;
    result.layout = comparisonLayout(comparison);
    result.cells = outcome.cells;
    result.tables = writeComparisonTableFiles(result.layout, result.cells, folder.string());
    if (!request.ompl_log.empty()) {
      const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - started;
      result.ompl_logs = aboutLogFolder(request, [&] {
        return writeComparisonBenchmarkLogs(result.study_file, request.ompl_log, seconds.count());
      });
    }
  }
  if (world) finishMpi();
  return result;
}

}  // namespace wpg::engine
