// `wpg analyze FILE.h5 [--format table|csv|json]`: the metrics of datasets/METRICS.md for every
// run of a run file or a batch file, recomputed from the stored walk by the engine
// (stored_runs.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "command_options.hpp"
#include "exit_codes.hpp"
#include "json_text.hpp"
#include "wpg/analysis/run_metrics.hpp"
#include "wpg/engine/stored_runs.hpp"

namespace wpg::cli {
namespace {

using AnalyzedRun = engine::StoredRunMetrics;

std::string number(double value, const char* format) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

void printTable(const std::vector<AnalyzedRun>& runs) {
  for (const AnalyzedRun& run : runs) {
    std::cout << "run " << run.name << "\n";
    for (const analysis::MetricDefinition& metric : analysis::runMetricTable()) {
      char line[160];
      std::snprintf(line, sizeof line, "  %-30s %14s %s\n", metric.name,
                    number(run.metrics.*metric.field, metric.integer ? "%.0f" : "%.6g").c_str(),
                    metric.unit);
      std::cout << line;
    }
  }
}

void printCsv(const std::vector<AnalyzedRun>& runs) {
  std::cout << "run";
  for (const analysis::MetricDefinition& metric : analysis::runMetricTable()) {
    std::cout << "," << metric.name;
  }
  std::cout << "\n";
  for (const AnalyzedRun& run : runs) {
    std::cout << run.name;
    for (const analysis::MetricDefinition& metric : analysis::runMetricTable()) {
      std::cout << "," << number(run.metrics.*metric.field, "%.17g");
    }
    std::cout << "\n";
  }
}

// One object per run keyed by its name, metric names as keys, SI units; NaN and inf as null.
void printJson(const std::vector<AnalyzedRun>& runs) {
  std::cout << "{";
  for (std::size_t r = 0; r < runs.size(); ++r) {
    std::cout << (r ? ",\n " : "\n ") << jsonString(runs[r].name) << ": {";
    bool first = true;
    for (const analysis::MetricDefinition& metric : analysis::runMetricTable()) {
      const double value = runs[r].metrics.*metric.field;
      std::cout << (first ? "" : ", ") << jsonString(metric.name) << ": "
                << jsonNumber(value, 17);
      first = false;
    }
    std::cout << "}";
  }
  std::cout << "\n}\n";
}

}  // namespace

int analyzeCommand(const AnalyzeOptions& options) {
  if (options.format != "table" && options.format != "csv" && options.format != "json") {
    throw UsageError("--format: expected table, csv or json, got '" + options.format + "'");
  }
  // Every run is read and analysed before anything is printed: a bad file prints one line.
  const std::vector<AnalyzedRun> runs = engine::analyzeRunFile(options.input, robotsDirectory());
  if (runs.empty()) throw UsageError(options.input + ": no run under /runs");
  if (options.format == "table") printTable(runs);
  if (options.format == "csv") printCsv(runs);
  if (options.format == "json") printJson(runs);
  return kExitSuccess;
}

}  // namespace wpg::cli
