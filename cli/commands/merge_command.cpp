// `wpg merge OUT.h5 SHARD... [--copy]`: the index of a study's shard files (those of
// `wpg batch --shard K/N`, or a folder of them such as OUT.shards/ of an MPI batch), written
// atomically (batch_index.hpp), with OUT.summary.csv/.md/.png beside it as `wpg batch` writes.
// The shards of a comparison (`wpg compare --shard K/N`) give its study file: the index with
// /compare/summary (written before the index is renamed into place), and summary.csv,
// summary.md and the figures beside it, as `wpg compare` writes them.
#include <algorithm>
#include <iostream>
#include <filesystem>
#include <system_error>

#include "batch_summary.hpp"
#include "command_options.hpp"
#include "comparison_files.hpp"
#include "exit_codes.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/storage/input_file.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/comparison_run.hpp"
#include "wpg/engine/study_summary.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {

int mergeCommand(const MergeOptions& options) {
  if (options.output.empty()) throw UsageError("merge: expected the index file to write (OUT.h5)");
  if (options.shards.empty()) throw UsageError("merge: expected shard files or a folder of them");
  std::vector<std::string> shards;
  std::error_code ec;
  for (const std::string& argument : options.shards) {
    if (fs::is_directory(argument, ec)) {
      std::vector<std::string> files;
      for (const fs::directory_entry& entry : fs::directory_iterator(argument, ec)) {
        if (entry.is_regular_file(ec) && entry.path().extension() == ".h5") {
          files.push_back(entry.path().string());
        }
      }
      if (files.empty()) throw UsageError("merge: " + argument + ": no *.h5 shard file in the folder");
      std::sort(files.begin(), files.end());
      shards.insert(shards.end(), files.begin(), files.end());
    } else if (!fs::exists(argument, ec)) {
      throw UsageError("merge: " + argument + ": no such shard file");
    } else {
      datasets::checkInputFile(argument);
      shards.push_back(argument);
    }
  }
  const datasets::IndexLayout layout = options.copy ? datasets::IndexLayout::kCopy : datasets::IndexLayout::kLinks;
  if (datasets::readShardContents(shards.front()).created_by == "wpg compare") {
    // A comparison: its layout from the first shard (every shard holds the whole table).
    const engine::ComparisonLayout comparison = engine::readComparisonLayout(shards.front());
    std::vector<datasets::PlannedOutput> outputs = {{options.output, datasets::OutputKind::kHdf5}};
    for (datasets::PlannedOutput& output :
         engine::comparisonSideOutputs(options.output, comparison.worlds, options.plot)) {
      outputs.push_back(std::move(output));
    }
    datasets::checkOutputPaths(outputs, shards);
    std::vector<analysis::ComparisonCell> cells;
    datasets::writeBatchIndex(options.output, shards, layout, [&](const std::string& index) {
      cells = engine::writeComparisonSummary(index, comparison);
    });
    const fs::path folder = fs::path(options.output).parent_path();
    reportComparisonFiles(options.output, comparison.runs, cells,
                          engine::writeComparisonTableFiles(comparison, cells, folder.string()),
                          options.plot);
    std::cout << "\n";
    return kExitSuccess;  // runs that miss the goal are results of the comparison
  }
  // Never over a shard (by identity, whatever the name), a folder or a file of another kind.
  // ... and so are the summary files beside the index (a shard named OUT.summary.csv).
  datasets::checkOutputPaths(engine::batchOutputs(options.output, options.plot), shards);
  datasets::writeBatchIndex(options.output, shards, layout);
  return reportBatchFile(options.output, engine::writeBatchSummaryFiles(options.output),
                         options.plot);
}

}  // namespace wpg::cli
