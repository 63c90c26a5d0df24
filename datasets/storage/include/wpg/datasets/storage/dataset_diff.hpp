#pragma once
// Comparing two run or batch datasets field by field (`wpg diff`, the regression references of
// datasets/references/): a generic walk over both files' groups, datasets and attributes, so that
// a field added to the schema is compared without a change here. Numbers are compared within a
// tolerance, text exactly; wall-time fields (machine-dependent by nature) and the provenance
// attributes can be left out.
#include <cstddef>
#include <string>
#include <vector>

#include "wpg/datasets/input/input_error.hpp"

namespace wpg::datasets {

struct DiffSettings {
  // Two numbers a, b agree when |a - b| <= atol + rtol * max(|a|, |b|) (NaN agrees with NaN,
  // an infinity with the same infinity). Integers and codes go through the same test.
  double rtol = 1e-9;
  double atol = 1e-12;
  // Leave out the wall-time fields listed by isWallTimeField (datasets/SCHEMA.md).
  bool ignore_wall_time = true;
  // Fields left out as well: shell patterns (fnmatch, `*` also matches `/`) on the field's path,
  // e.g. "*/checks@*_violation_time" (an attribute) or "/runs/*/mpc/qp_iterations".
  std::vector<std::string> ignore_patterns;
};

// One field (dataset or attribute) that differs between A and B.
struct FieldDifference {
  std::string path;        // "/runs/walk_forward/com"; an attribute: "/runs/walk_forward@success"
  bool attribute = false;
  std::string what;        // "values", "text", "only in A", "only in B", "shape (..) vs (..)", ...
  // The first sample beyond the tolerance (numbers; row-major order): its row and column (column
  // 0 for a 1-D field), the column's name from the `columns` attribute when there is one.
  bool has_sample = false;
  bool scalar = false;  // a scalar field (most attributes): no row or column to report
  std::size_t row = 0, column = 0;
  std::string column_name;
  double a = 0.0, b = 0.0, tolerance = 0.0;
  std::size_t differing_samples = 0, compared_samples = 0;
  double max_relative = 0.0;  // largest |a - b| / max(|a|, |b|) over the compared samples
  double max_absolute = 0.0;  // largest |a - b|
  // Text: the first line that differs (1-based; for a list of strings, the element), both sides.
  std::size_t line = 0;
  std::string text_a, text_b;
};

struct DatasetDiff {
  std::vector<FieldDifference> differences;  // in walk order (attributes, then members by name)
  std::size_t datasets_compared = 0, attributes_compared = 0;
  std::vector<std::string> ignored;          // fields left out (wall time, provenance)
  // Over the numeric fields that agree within the tolerance: the largest relative and absolute
  // differences and where (what the tolerance actually had to absorb).
  double max_relative_within = 0.0, max_absolute_within = 0.0;
  std::string max_relative_within_path;
};

// The wall-time fields (datasets/SCHEMA.md): mpc/solve_time, the timing/ group, plans/
// planning_time and plans/simplification_time, and the batch summary's nmpc_time_* columns.
// `path` is an object path such as "/runs/x/mpc/solve_time".
bool isWallTimeField(const std::string& path);

// Root attributes that say who wrote the file, where and when, not what it holds: wpg_version,
// created_by, wpg_commit, created_on, created_at (provenance.hpp).
bool isProvenanceAttribute(const std::string& name);

// Compares the files at path_a and path_b. Throws InputError (one line naming the file) when
// one is missing, unreadable, not HDF5, or not a wpg dataset (no root `schema_version`
// attribute or no /runs group). Holds hdf5Mutex() while it reads.
DatasetDiff diffDatasets(const std::string& path_a, const std::string& path_b,
                         const DiffSettings& settings);

}  // namespace wpg::datasets
