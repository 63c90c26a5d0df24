// `wpg batch STUDY.yaml -o OUT.h5 [-j N] [--resume] [--shard K/N]`: a study
// (datasets/SCENARIOS.md, "Studies") run by the engine (batch_study_run.hpp: every input and
// output checked first, then the runs on threads into one HDF5 file, datasets/SCHEMA.md, "Batch
// files"), then OUT.summary.csv, OUT.summary.md and the summary figure OUT.summary.png beside
// it. With --shard K/N only the runs of slice K into a shard file, joined later by `wpg merge`;
// under an MPI launcher the ranks share the study and OUT.h5 is the index. This file parses,
// draws the figure and prints.
#include <filesystem>
#include <iostream>

#include "analysis_scripts.hpp"
#include "batch_summary.hpp"
#include "command_options.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "study_request_options.hpp"
#include "study_progress.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/engine/batch_study_run.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {

int reportBatchFile(const std::string& batch_file, const engine::BatchSummaryFiles& files,
                    bool plot) {
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
  engine::StudyRequest request = studyRequestOf(options);
  if (!options.fields.empty()) request.fields = datasets::splitFieldList(options.fields);
  request.names.fields = "--fields";
  StudyProgress progress;
  const engine::BatchStudyResult result = engine::runBatchStudy(request, progress);
  if (result.complete) return reportBatchFile(options.output, result.summary, options.plot);
  if (!request.shard) return kExitSuccess;  // an MPI rank other than 0: rank 0 reports
  std::cout << "wrote " << options.output << " (shard "
            << datasets::shardSliceLabel(request.shard->index, request.shard->count) << ": "
            << result.slice_runs << " of " << result.runs
            << " runs; join the shards with `wpg merge`)\n";
  if (progress.failures() > 0) {
    std::cout.flush();
    printError(std::to_string(progress.failures()) + " of these runs failed (exit_status in "
               "/batch/summary says which; datasets written)");
    return kExitRunFailed;
  }
  return kExitSuccess;
}

}  // namespace wpg::cli
