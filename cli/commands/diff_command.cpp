// `wpg diff A.h5 B.h5 [--rtol R] [--atol A] [--compare-wall-time]`: the regression comparison of
// two run or batch datasets (wpg/datasets/storage/dataset_diff.hpp), printed for a reader: the
// first sample beyond the tolerance, then one line per field that differs.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <string>

#include "command_options.hpp"
#include "exit_codes.hpp"
#include "wpg/datasets/storage/dataset_diff.hpp"

namespace wpg::cli {
namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// "/runs/walk_forward/mpc/solve_time" -> "runs/*/mpc/solve_time": one entry for every run of a
// batch file.
std::string ignoredPattern(const std::string& path) {
  if (path.rfind("/runs/", 0) != 0) return path.substr(1);
  const auto end = path.find_first_of("/@", 6);
  return "runs/*" + (end == std::string::npos ? std::string() : path.substr(end));
}

std::string ignoredSummary(const datasets::DatasetDiff& diff) {
  std::set<std::string> patterns;
  for (const std::string& path : diff.ignored) patterns.insert(ignoredPattern(path));
  std::string text;
  for (const std::string& pattern : patterns) text += (text.empty() ? "" : ", ") + pattern;
  return text.empty() ? "nothing" : text;
}

std::string sampleText(const datasets::FieldDifference& d) {
  std::string text = d.scalar ? "" : "row " + std::to_string(d.row);
  if (!d.column_name.empty() || d.column > 0) {
    text += ", column " + std::to_string(d.column);
    if (!d.column_name.empty()) text += " (" + d.column_name + ")";
  }
  return text + (d.scalar ? "A " : ": A ") + format("%.17g", d.a) + ", B " + format("%.17g", d.b) + ", |A - B| " +
         format("%.3g", std::abs(d.a - d.b)) + " > tolerance " + format("%.3g", d.tolerance);
}

std::string fieldLine(const datasets::FieldDifference& d) {
  std::string line = d.path + ": ";
  if (d.what == "text") {
    return line + "text differs at " + (d.line ? "line " + std::to_string(d.line) : "") +
           ": A \"" + d.text_a + "\", B \"" + d.text_b + "\"";
  }
  line += d.what == "values" ? std::string() : d.what;
  if (d.compared_samples > 0 && (d.what == "values" || d.has_sample)) {
    line += (d.what == "values" ? "" : "; ") + std::to_string(d.differing_samples) + " of " +
            std::to_string(d.compared_samples) + " values differ, largest relative difference " +
            format("%.3g", d.max_relative) + " (absolute " + format("%.3g", d.max_absolute) + ")";
    if (d.has_sample) line += (d.scalar ? "; " : "; first at ") + sampleText(d);
  }
  return line;
}

}  // namespace

int diffCommand(const DiffOptions& options) {
  if (!(options.rtol >= 0.0) || !(options.atol >= 0.0)) {
    throw UsageError("--rtol and --atol: expected numbers >= 0, got " +
                     format("%g", options.rtol) + " and " + format("%g", options.atol));
  }
  datasets::DiffSettings settings;
  settings.rtol = options.rtol;
  settings.atol = options.atol;
  settings.ignore_wall_time = options.ignore_wall_time;
  settings.ignore_patterns = options.ignore_patterns;
  const datasets::DatasetDiff diff = datasets::diffDatasets(options.a, options.b, settings);

  const std::string tolerances = "rtol " + format("%g", options.rtol) + ", atol " +
                                 format("%g", options.atol);
  std::cout << "A " << options.a << "\nB " << options.b << "\n";
  std::cout << "compared " << diff.datasets_compared << " datasets and " << diff.attributes_compared
            << " attributes (" << tolerances << "); ignored: " << ignoredSummary(diff) << "\n";
  if (diff.differences.empty()) {
    std::cout << "same within tolerance; largest relative difference "
              << format("%.3g", diff.max_relative_within)
              << (diff.max_relative_within_path.empty() ? "" : " (" + diff.max_relative_within_path + ")")
              << ", largest absolute difference " << format("%.3g", diff.max_absolute_within) << "\n";
    return kExitSuccess;
  }

  std::cout << "different: " << diff.differences.size() << " field"
            << (diff.differences.size() == 1 ? "" : "s") << " differ\n";
  // The first sample of a dataset (the walk itself) says more than a summary attribute: it is
  // preferred; a scalar attribute is reported when no dataset sample differs.
  const datasets::FieldDifference* first = nullptr;
  for (const datasets::FieldDifference& d : diff.differences) {
    if (d.has_sample && (first == nullptr || (first->attribute && !d.attribute))) first = &d;
    if (first != nullptr && !first->attribute) break;
  }
  if (first != nullptr) {
    std::cout << "first differing sample: " << first->path << " " << sampleText(*first) << "\n";
  }
  constexpr std::size_t kListed = 40;
  for (std::size_t i = 0; i < diff.differences.size() && i < kListed; ++i) {
    std::cout << "  " << fieldLine(diff.differences[i]) << "\n";
  }
  if (diff.differences.size() > kListed) {
    std::cout << "  ... and " << diff.differences.size() - kListed << " more fields\n";
  }
  return kExitRunFailed;
}

}  // namespace wpg::cli
