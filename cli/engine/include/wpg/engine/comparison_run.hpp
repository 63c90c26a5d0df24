#pragma once
// A comparison study (worlds x variants x seeds of walks to a goal) run by a study executor
// (study_executor.hpp) into DIR/study.h5: a group per run and /batch/summary as `wpg batch`
// writes them, with the goal columns, then /compare/summary, one row per world x variant
// (datasets/SCHEMA.md, "Comparison studies"); and the same table as summary.csv and summary.md.
#include <string>
#include <vector>

#include "wpg/analysis/comparison_summary.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/study_design/comparison_study.hpp"
#include "wpg/engine/study_executor.hpp"

namespace wpg::engine {

// What a run adds to its cell of the comparison table.
analysis::ComparisonRunSample comparisonSampleOf(const datasets::Scenario& scenario,
                                                 const RunResult& result);

// The columns of /batch/summary of a comparison: those of `wpg batch` (runSummaryColumns), then
// the goal's (reached, time to goal, route, clearance, replans, planning times).
std::vector<datasets::SummaryColumn> comparisonSummaryColumns();

// Runs the comparison with `executor` into `batch_file` and, on the process whose executor
// returns true, writes /compare/summary there and returns the table's rows (world-major, in
// study order); elsewhere returns no rows and `complete` false.
struct ComparisonOutcome {
  bool complete = false;
  std::vector<analysis::ComparisonCell> cells;
};
ComparisonOutcome runComparison(const datasets::ComparisonStudy& comparison,
                                const std::string& batch_file, StudyExecutor& executor,
                                StudyObserver& observer);

// summary.csv (10 significant digits) and summary.md (4) of the table, in `folder`.
struct ComparisonTableFiles {
  std::string csv, markdown;
};
ComparisonTableFiles writeComparisonTableFiles(const datasets::ComparisonStudy& comparison,
                                               const std::vector<analysis::ComparisonCell>& cells,
                                               const std::string& folder);

}  // namespace wpg::engine
