#pragma once
// The end of `wpg batch` and `wpg merge`: what they print of the summary files beside a batch
// file or index (written by the engine), and the summary figure they draw.
#include <string>

#include "wpg/engine/study_summary.hpp"

namespace wpg::cli {

// Prints "wrote OUT.h5 (N runs), CSV, MD", draws OUT.summary.png with `plot` (a warning when
// Python cannot); kExitRunFailed when a run failed.
int reportBatchFile(const std::string& batch_file, const engine::BatchSummaryFiles& files,
                    bool plot);

}  // namespace wpg::cli
