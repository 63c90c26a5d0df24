// A batch study end to end (batch_study_run.hpp).
#include "wpg/engine/batch_study_run.hpp"

#include "study_request_checks.hpp"
#include "wpg/datasets/input/input_limits.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/data_paths.hpp"
#include "wpg/engine/run_input_checks.hpp"

namespace wpg::engine {
namespace {

StudyRunHandling batchHandling() {
  StudyRunHandling handling;
  handling.columns = runSummaryColumns();
  handling.summary_values = [](const datasets::StudyRun&, const RunResult& result) {
    return runSummaryValues(result);
  };
  return handling;
}

}  // namespace

BatchStudyResult runBatchStudy(const StudyRequest& request, StudyObserver& observer) {
  checkStudyRequest(request, "the batch file to write (OUT.h5)");
  datasets::Study study;
  const std::optional<MpiWorld> world = checkStudyInput(request, [&] {
    study = datasets::loadStudy(
        request.study, [](const std::string& base) { return resolveScenarioPath(base); },
        robotsDirectory(), request.jobs);
    if (request.fields) {
      study.fields = datasets::parseRunFields(*request.fields, request.names.fields);
    }
    // One file's summary table holds at most kMaxBatchFileRuns rows: a larger study in slices.
    const std::size_t file_runs =
        request.shard ? sliceRuns(study, *request.shard) : study.runs.size();
    if (file_runs > datasets::kMaxBatchFileRuns) {
      throw datasets::InputError(
          request.study + ": " + std::to_string(study.runs.size()) + " runs, " +
          std::to_string(file_runs) + " in one file: expected at most " +
          std::to_string(datasets::kMaxBatchFileRuns) + " per batch file (run it in slices: " +
          request.names.shard + " K/N with N >= " +
          std::to_string((study.runs.size() - 1) / datasets::kMaxBatchFileRuns + 1) + ")");
    }
    // Never over the study, a device, a folder, a link or a file of another kind, for the
    // batch file and every file beside it (output_file.hpp); a slice has no summary files.
    std::vector<datasets::PlannedOutput> outputs = batchOutputs(request.output, request.figures);
    if (request.shard) outputs.resize(1);
    datasets::checkOutputPaths(outputs, {request.study});
    checkStudyRobotModels(study, robotsDirectory());
  });
  if (!world || world->rank == 0) observer.accepted(study.name, studyWarnings(study));

  BatchStudyResult result;
  result.runs = study.runs.size();
  if (request.shard) result.slice_runs = sliceRuns(study, *request.shard);
  const bool root = makeStudyExecutor(request, world)
                        ->run(study, StudyOutput{request.output, request.resume, request.shard},
                              batchHandling(), observer);
  if (root && !request.shard) {
    result.complete = true;
    result.summary = writeBatchSummaryFiles(request.output);
    if (request.figures) result.figure = batchSummaryPath(request.output, "png");
  }
  if (world) finishMpi();
  return result;
}

}  // namespace wpg::engine
