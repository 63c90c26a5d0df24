// The summary of a study (study_summary.hpp).
#include "wpg/engine/study_summary.hpp"

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "wpg/analysis/run_metrics.hpp"
#include "wpg/datasets/storage/provenance.hpp"
#include "wpg/datasets/storage/output_file.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {
namespace {

// The NMPC statuses a count column is kept for: every code libwpg names.
std::vector<IterationStatus> namedStatuses() {
  std::vector<IterationStatus> statuses;
  for (int code = 0; code <= 255; ++code) {
    const auto status = static_cast<IterationStatus>(code);
    if (std::string(iterationStatusName(status)) != "unknown") statuses.push_back(status);
  }
  return statuses;
}

}  // namespace

std::vector<datasets::SummaryColumn> runSummaryColumns() {
  std::vector<datasets::SummaryColumn> columns;
  for (const IterationStatus status : namedStatuses()) {
    columns.push_back({std::string("status_") + iterationStatusName(status), "1",
                       std::string("NMPC iterations with status ") + iterationStatusName(status),
                       true});
  }
  for (const analysis::MetricDefinition& metric : analysis::runMetricTable()) {
    columns.push_back({metric.name, metric.unit,
                       std::string(metric.name) + " (datasets/METRICS.md)", metric.integer});
  }
  return columns;
}

std::vector<double> runSummaryValues(const RunResult& result) {
  std::vector<double> values;
  for (const IterationStatus status : namedStatuses()) {
    double count = 0.0;
    for (const MpcIterationLog& row : result.walk.result.trajectory.mpc) count += row.status == status;
    values.push_back(count);
  }
  for (const analysis::MetricDefinition& metric : analysis::runMetricTable()) {
    values.push_back(result.metrics.*metric.field);
  }
  return values;
}

void writeTableCsv(const datasets::BatchSummaryTable& table, const std::string& path) {
  std::ostringstream out;
  const auto quoted = [](const std::string& cell) {
    if (cell.find_first_of(",\"\n") == std::string::npos) return cell;
    std::string text = "\"";
    for (const char c : cell) text += c == '"' ? std::string("\"\"") : std::string(1, c);
    return text + "\"";
  };
  for (std::size_t c = 0; c < table.column_names.size(); ++c) {
    out << (c ? "," : "") << quoted(table.column_names[c]);
  }
  out << "\n";
  for (std::size_t r = 0; r < table.rows; ++r) {
    for (std::size_t c = 0; c < table.column_names.size(); ++c) {
      out << (c ? "," : "") << quoted(table.cells[c][r]);
    }
    out << "\n";
  }
  datasets::writeFileAtomically(path, out.str());  // never a half table, never through a link
}

void writeTableMarkdown(const datasets::BatchSummaryTable& table, const std::string& path,
                        const std::string& title, const std::string& intro) {
  std::ostringstream out;
  out << "# " << title << "\n\n" << intro << "\n\n|";
  for (std::size_t c = 0; c < table.column_names.size(); ++c) {
    const std::string& unit = table.column_units[c];
    out << " " << table.column_names[c] << (unit == "1" || unit.empty() ? "" : " [" + unit + "]")
        << " |";
  }
  out << "\n|";
  for (std::size_t c = 0; c < table.column_names.size(); ++c) out << "---|";
  out << "\n";
  for (std::size_t r = 0; r < table.rows; ++r) {
    out << "|";
    for (std::size_t c = 0; c < table.column_names.size(); ++c) {
      std::string cell = table.cells[c][r];
      for (char& ch : cell) if (ch == '|') ch = '/';
      out << " " << cell << " |";
    }
    out << "\n";
  }
  const datasets::Provenance who = datasets::currentProvenance();  // as every file of wpg
  out << "\nWritten by wpg " << who.version << " (commit " << who.commit << ") on " << who.machine
      << " at " << who.date << ".\n";
  datasets::writeFileAtomically(path, out.str());
}

std::string batchSummaryPath(const std::string& batch_file, const std::string& extension) {
  fs::path path = batch_file;
  path.replace_extension(".summary." + extension);
  return path.string();
}

std::vector<datasets::PlannedOutput> batchOutputs(const std::string& batch_file, bool plot) {
  std::vector<datasets::PlannedOutput> outputs = {
      {batch_file, datasets::OutputKind::kHdf5},
      {batchSummaryPath(batch_file, "csv"), datasets::OutputKind::kText},
      {batchSummaryPath(batch_file, "md"), datasets::OutputKind::kText}};
  if (plot) outputs.push_back({batchSummaryPath(batch_file, "png"), datasets::OutputKind::kPng});
  return outputs;
}

BatchSummaryFiles writeBatchSummaryFiles(const std::string& batch_file) {
  const datasets::BatchSummaryTable table = datasets::readBatchSummary(batch_file);
  BatchSummaryFiles files;
  files.csv = batchSummaryPath(batch_file, "csv");
  files.markdown = batchSummaryPath(batch_file, "md");
  files.runs = table.rows;
  writeTableCsv(table, files.csv);
  writeTableMarkdown(table, files.markdown, "Study " + table.study,
                     std::to_string(table.rows) +
                         " runs; units in the header; definitions: datasets/METRICS.md.");
  for (std::size_t c = 0; c < table.column_names.size(); ++c) {
    if (table.column_names[c] != "exit_status") continue;
    for (const std::string& cell : table.cells[c]) files.failed_runs += cell != "0";
  }
  return files;
}

}  // namespace wpg::engine
