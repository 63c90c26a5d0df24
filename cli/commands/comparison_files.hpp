#pragma once
// The end of `wpg compare` and of `wpg merge` of a comparison's shards: the files beside the
// study file (in its folder): summary.csv, summary.md and the figures of
// analysis/plot_compare.py (datasets/SCHEMA.md, "Comparison studies").
#include <string>
#include <vector>

#include "wpg/analysis/comparison_summary.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/comparison_run.hpp"

namespace wpg::cli {

// Those files (the figures with `plot`: success_rates, time_to_goal, top_<world> per world), as
// the outputs the command checks before any work (output_file.hpp).
std::vector<datasets::PlannedOutput> comparisonSideOutputs(const std::string& study_file,
                                                           const std::vector<std::string>& worlds,
                                                           bool plot);

// Prints the table (success, time to goal, clearance per world x variant), writes summary.csv
// and summary.md, draws the figures with `plot` (a warning when Python cannot), and prints
// "wrote STUDY (N runs), CSV, MD[, figures ...]" without ending the line.
void finishComparisonFiles(const std::string& study_file, const engine::ComparisonLayout& layout,
                           const std::vector<analysis::ComparisonCell>& cells, bool plot);

}  // namespace wpg::cli
