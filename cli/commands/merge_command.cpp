// `wpg merge OUT.h5 SHARD... [--copy]`: the index of a study's shard files (those of
// `wpg batch --shard K/N`, or a folder of them such as OUT.shards/ of an MPI batch), written
// atomically (batch_index.hpp), with OUT.summary.csv/.md/.png beside it as `wpg batch` writes.
#include <algorithm>
#include <filesystem>
#include <system_error>

#include "batch_summary.hpp"
#include "command_options.hpp"
#include "exit_codes.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/storage/output_file.hpp"
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
    } else if (!fs::is_regular_file(argument, ec)) {
      throw UsageError("merge: " + argument + ": no such shard file");
    } else {
      shards.push_back(argument);
    }
  }
  // Never over a shard (by identity, whatever the name), a folder or a file of another kind.
  // ... and so are the summary files beside the index (a shard named OUT.summary.csv).
  datasets::checkOutputPaths(engine::batchOutputs(options.output, options.plot), shards);
  const datasets::IndexReport report = datasets::writeBatchIndex(
      options.output, shards, options.copy ? datasets::IndexLayout::kCopy : datasets::IndexLayout::kLinks);
  (void)report;
  return finishBatchFile(options.output, options.plot);
}

}  // namespace wpg::cli
