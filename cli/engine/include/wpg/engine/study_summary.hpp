#pragma once
// The summary of a study: the per-run columns of /batch/summary (NMPC statuses and the metrics
// of analysis/), and the summary tables beside a batch file as CSV and Markdown.
#include <cstddef>
#include <string>
#include <vector>

#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/scenario_run.hpp"

namespace wpg::engine {

// The result columns of /batch/summary of `wpg batch`: NMPC iterations per status, then every
// metric of analysis::runMetricTable(); runSummaryValues gives a run's values in that order.
std::vector<datasets::SummaryColumn> runSummaryColumns();
std::vector<double> runSummaryValues(const RunResult& result);

// A table as text cells (numbers in shortest round-trip form) to CSV, and to Markdown under
// `title` with the paragraph `intro`; units from column_units in the Markdown header. Throws
// std::runtime_error when a file cannot be written.
void writeTableCsv(const datasets::BatchSummaryTable& table, const std::string& path);
void writeTableMarkdown(const datasets::BatchSummaryTable& table, const std::string& path,
                        const std::string& title, const std::string& intro);

// OUT.h5 -> OUT.summary.<extension>: the files beside a batch file.
std::string batchSummaryPath(const std::string& batch_file, const std::string& extension);

// Every file a batch (or merge) writes: OUT.h5, OUT.summary.csv, OUT.summary.md and, with
// `plot`, OUT.summary.png; checked together before any work (datasets::checkOutputPaths).
std::vector<datasets::PlannedOutput> batchOutputs(const std::string& batch_file, bool plot);

// OUT.summary.csv and OUT.summary.md of a batch file or index, from its /batch/summary.
struct BatchSummaryFiles {
  std::string csv, markdown;
  std::size_t runs = 0;
  std::size_t failed_runs = 0;  // exit_status not 0
};
BatchSummaryFiles writeBatchSummaryFiles(const std::string& batch_file);

}  // namespace wpg::engine
