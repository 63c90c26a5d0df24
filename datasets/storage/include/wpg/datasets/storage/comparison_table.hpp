#pragma once
// The per world x variant table of a comparison study, added to its batch file as
// /compare/summary once every run is written (`wpg compare`; layout: datasets/SCHEMA.md,
// "Comparison studies"). The values come from the caller (wpg::analysis computes them).
#include <string>
#include <vector>

namespace wpg::datasets {

struct TableColumn {
  std::string name;         // dataset name under /compare/summary
  std::string units;        // "m", "s", "1"
  std::string description;  // one sentence
  bool text = false;        // strings (variable-length UTF-8) instead of float64
  std::vector<std::string> strings;  // one per row when `text`
  std::vector<double> numbers;       // one per row otherwise
};

// Opens the batch file at `path` and writes /compare, replacing one there (attributes `worlds`,
// `variants`: the names in study order; `seeds`) and /compare/summary, one 1-D dataset per
// column with `units` and `description`, its `columns` attribute listing them in order. Throws
// std::invalid_argument when columns differ in length, std::runtime_error on I/O errors.
void writeComparisonTable(const std::string& path, const std::vector<std::string>& worlds,
                          const std::vector<std::string>& variants, const std::vector<int>& seeds,
                          const std::vector<TableColumn>& columns);

}  // namespace wpg::datasets
