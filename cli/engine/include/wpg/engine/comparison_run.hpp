#pragma once
// A comparison study (worlds x variants x seeds of walks to a goal) run by a study executor
// (study_executor.hpp) into DIR/study.h5: a group per run and /batch/summary as `wpg batch`
// writes them, with the goal columns, then /compare/summary, one row per world x variant
// (datasets/SCHEMA.md, "Comparison studies"); and the same table as summary.csv and summary.md.
#include <cstddef>
#include <string>
#include <vector>

#include "wpg/analysis/comparison_summary.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/datasets/study_design/comparison_study.hpp"
#include "wpg/engine/study_executor.hpp"

namespace wpg::engine {

// What a run adds to its cell of the comparison table.
analysis::ComparisonRunSample comparisonSampleOf(const datasets::Scenario& scenario,
                                                 const RunResult& result);

// The columns of /batch/summary of a comparison: those of `wpg batch` (runSummaryColumns), then
// the goal's (reached, time to goal, route, clearance, replans, planning times).
std::vector<datasets::SummaryColumn> comparisonSummaryColumns();

// What a comparison's table is laid out by: the study's name, its worlds and variants (names,
// study order) and seeds, and its number of runs (worlds x variants x seeds).
struct ComparisonLayout {
  std::string study_name;
  std::vector<std::string> worlds, variants;
  std::vector<int> seeds;
  std::size_t runs = 0;
};
ComparisonLayout comparisonLayout(const datasets::ComparisonStudy& comparison);
// The same from a comparison's study file (or one of its shards): the swept columns of
// /batch/summary in study order (runs are worlds slowest, then variants, then seeds). Throws
// datasets::InputError when it is not the study file of `wpg compare`.
ComparisonLayout readComparisonLayout(const std::string& study_file);

// The table of the comparison in `study_file` (every run done), computed from the runs the file
// holds (datasets::readComparisonRuns: the summary's goal columns, the plans' and NMPC
// iterations' times), written as /compare (replacing one there) and returned: a study run in one
// go, resumed after a kill, or merged from shards gives the same table. Throws
// datasets::InputError when a run is missing or the file is not of this comparison.
std::vector<analysis::ComparisonCell> writeComparisonSummary(const std::string& study_file,
                                                             const ComparisonLayout& layout);

// Runs the comparison with `executor` into `output` (its runs not yet there with
// output.resume; only slice output.shard, into a shard file, with a shard) and, on the process
// whose executor returns true and without a shard, writes /compare/summary there
// (writeComparisonSummary) and returns the table's rows (world-major, in study order);
// otherwise returns no rows and `complete` false.
struct ComparisonOutcome {
  bool complete = false;
  std::vector<analysis::ComparisonCell> cells;
};
ComparisonOutcome runComparison(const datasets::ComparisonStudy& comparison,
                                const StudyOutput& output, StudyExecutor& executor,
                                StudyObserver& observer);
// The whole study into a new `batch_file`.
ComparisonOutcome runComparison(const datasets::ComparisonStudy& comparison,
                                const std::string& batch_file, StudyExecutor& executor,
                                StudyObserver& observer);

// The files written beside a comparison's study file, in its folder: summary.csv, summary.md
// and, with `figures`, those of analysis/plot_compare.py (success_rates.png, time_to_goal.png,
// top_<world>.png per world): the outputs checked with the study file before any work
// (datasets::checkOutputPaths), by `wpg compare` and by `wpg merge` of a comparison's shards.
std::vector<datasets::PlannedOutput> comparisonSideOutputs(const std::string& study_file,
                                                           const std::vector<std::string>& worlds,
                                                           bool figures);

// summary.csv (10 significant digits) and summary.md (4) of the table, in `folder`.
struct ComparisonTableFiles {
  std::string csv, markdown;
};
ComparisonTableFiles writeComparisonTableFiles(const ComparisonLayout& layout,
                                               const std::vector<analysis::ComparisonCell>& cells,
                                               const std::string& folder);
ComparisonTableFiles writeComparisonTableFiles(const datasets::ComparisonStudy& comparison,
                                               const std::vector<analysis::ComparisonCell>& cells,
                                               const std::string& folder);

}  // namespace wpg::engine
