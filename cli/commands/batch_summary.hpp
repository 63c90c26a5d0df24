#pragma once
// The end of `wpg batch` and `wpg merge`: the summary files beside a batch file or index.
#include <string>

namespace wpg::cli {

// OUT.summary.csv/.md (and .png with `plot`) beside a batch file or index; prints "wrote ...";
// kExitRunFailed when a run failed.
int finishBatchFile(const std::string& batch_file, bool plot);

}  // namespace wpg::cli
