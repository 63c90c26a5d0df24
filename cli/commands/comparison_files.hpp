#pragma once
// The end of `wpg compare` and of `wpg merge` of a comparison's shards: what they print of the
// table and its files beside the study file (written by the engine), and the figures of
// analysis/plot_compare.py they draw (datasets/SCHEMA.md, "Comparison studies").
#include <cstddef>
#include <string>
#include <vector>

#include "wpg/analysis/comparison_summary.hpp"
#include "wpg/engine/comparison_run.hpp"

namespace wpg::cli {

// Prints the table (success, time to goal, clearance per world x variant), draws the figures
// with `plot` (a warning when Python cannot), and prints "wrote STUDY (N runs), CSV, MD[,
// figures ...]" without ending the line.
void reportComparisonFiles(const std::string& study_file, std::size_t runs,
                           const std::vector<analysis::ComparisonCell>& cells,
                           const engine::ComparisonTableFiles& files, bool plot);

}  // namespace wpg::cli
