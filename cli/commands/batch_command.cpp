// `wpg batch STUDY.yaml -o OUT.h5 [-j N] [--resume] [--shard K/N]`: a study
// (datasets/SCENARIOS.md, "Studies") expanded into runs and run by the engine's thread executor
// into one HDF5 file (datasets/SCHEMA.md, "Batch files"), then OUT.summary.csv, OUT.summary.md
// and the summary figure OUT.summary.png beside it. With --shard K/N only the runs of slice K
// into a shard file, joined later by `wpg merge`; under an MPI launcher the ranks share the
// study (the engine's MPI executor) and OUT.h5 is the index.
#include <filesystem>
#include <iostream>
#include <optional>
#include <system_error>

#include "analysis_scripts.hpp"
#include "batch_summary.hpp"
#include "command_options.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "shard_option.hpp"
#include "study_progress.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/datasets/study_design/study.hpp"
#include "wpg/engine/mpi_executor.hpp"
#include "wpg/engine/run_input_checks.hpp"
#include "wpg/engine/study_summary.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

engine::StudyRunHandling batchHandling() {
  engine::StudyRunHandling handling;
  handling.columns = engine::runSummaryColumns();
  handling.summary_values = [](const datasets::StudyRun&, const engine::RunResult& result) {
    return engine::runSummaryValues(result);
  };
  return handling;
}

}  // namespace

int finishBatchFile(const std::string& batch_file, bool plot) {
  const engine::BatchSummaryFiles files = engine::writeBatchSummaryFiles(batch_file);
  std::cout << "wrote " << batch_file << " (" << files.runs << " runs), " << files.csv << ", "
            << files.markdown;
  if (plot) {
    const std::string figure = engine::batchSummaryPath(batch_file, "png");
    const std::string script = (fs::path(dataDirectory()) / "analysis" / "plot_batch.py").string();
    if (runAnalysisScript(script, {batch_file, "-o", figure}) == 0) {
      std::cout << ", " << figure;
    } else {
      std::cout.flush();
      printWarning("the summary figure could not be drawn (Python with h5py and matplotlib?)");
    }
  }
  std::cout << "\n";
  if (files.failed_runs > 0) {
    std::cout.flush();
    printError(
        std::to_string(files.failed_runs) + " of " + std::to_string(files.runs) +
        " runs failed (exit_status in /batch/summary says which, blocked which of them ended "
        "blocked; datasets written)");
    return kExitRunFailed;
  }
  return kExitSuccess;
}

int batchCommand(const BatchOptions& options) {
  if (options.threads < 1) throw UsageError("-j: expected a number of worker threads >= 1");
  if (options.output.empty()) throw UsageError("-o: expected the batch file to write (OUT.h5)");
  const std::optional<engine::ShardSlice> slice =
      options.shard.empty() ? std::nullopt : std::optional(parseShardOption(options.shard));
  if (slice) refuseShardUnderMpi();
  std::error_code ec;
  if (!fs::is_regular_file(options.study, ec)) {
    throw UsageError(options.study + ": cannot read the study file: no such file");
  }
  // Everything about the input is checked before anything is written.
  datasets::Study study;
  const auto check_input = [&] {
    study = datasets::loadStudy(
        options.study, [](const std::string& base) { return resolveScenarioPath(base); },
        robotsDirectory(), options.threads);
    // Never over the study, a device, a folder, a link or a file of another kind, for the
    // batch file and every file beside it (output_file.hpp); a shard has no summary files.
    std::vector<datasets::PlannedOutput> outputs = engine::batchOutputs(options.output, options.plot);
    if (slice) outputs.resize(1);
    datasets::checkOutputPaths(outputs, {options.study});
    engine::checkStudyRobotModels(study, robotsDirectory());
  };
  std::optional<engine::MpiWorld> world;
  if (slice) {
    check_input();  // a slice is one process, whatever launched it
  } else {
    world = engine::checkInputWhileMpiStarts(check_input);
  }

  // What the runs' scenarios warn about (a clamped command, ...), once, from rank 0.
  if (!world || world->rank == 0) {
    std::vector<std::string> warnings;
    for (const datasets::StudyRun& run : study.runs) {
      warnings.insert(warnings.end(), run.scenario.warnings.begin(), run.scenario.warnings.end());
    }
    printWarnings(warnings);
  }
  StudyProgress progress(study.name);
  engine::StudyOutput output{options.output, options.resume, slice};
  if (world) {
    // One worker per rank unless -j says otherwise: a rank per core is the usual launch.
    const bool root =
        engine::makeMpiExecutor(*world, options.threads_given ? options.threads : 1,
                                robotsDirectory())
            ->run(study, output, batchHandling(), progress);
    const int status = root ? finishBatchFile(options.output, options.plot) : kExitSuccess;
    engine::finishMpi();
    return status;
  }
  engine::makeThreadExecutor(options.threads, robotsDirectory())
      ->run(study, output, batchHandling(), progress);
  if (!slice) return finishBatchFile(options.output, options.plot);
  std::size_t slice_runs = 0;
  for (const datasets::StudyRun& run : study.runs) {
    slice_runs += datasets::inShardSlice(run.index, slice->index, slice->count);
  }
  std::cout << "wrote " << options.output << " (shard "
            << datasets::shardSliceLabel(slice->index, slice->count) << ": " << slice_runs
            << " of " << study.runs.size() << " runs; join the shards with `wpg merge`)\n";
  if (progress.failures() > 0) {
    std::cout.flush();
    printError(std::to_string(progress.failures()) + " of these runs failed (exit_status in "
               "/batch/summary says which; datasets written)");
    return kExitRunFailed;
  }
  return kExitSuccess;
}

}  // namespace wpg::cli
