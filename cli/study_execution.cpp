// What `wpg batch` and `wpg compare` share (study_execution.hpp).
#include "study_execution.hpp"

#include <unistd.h>

#include <exception>
#include <fstream>
#include <mutex>
#include <thread>
#include <system_error>

#include "batch_progress.hpp"
#include "cli_common.hpp"
#include "wpg/analysis/run_metrics.hpp"
#include "wpg/datasets/provenance.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
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

datasets::BatchRunRecord recordOf(const datasets::StudyRun* run, const ScenarioOutcome& outcome) {
  datasets::BatchRunRecord record;
  record.run = run;
  record.result = &outcome.result;
  record.clearances = outcome.footsteps ? &outcome.footsteps->clearances : nullptr;
  record.multibody = outcome.replay ? &outcome.replay->validation : nullptr;
  record.goal = outcome.goal ? &*outcome.goal : nullptr;
  record.exit_status = outcome.exit_status;
  return record;
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

std::vector<double> runSummaryValues(const ScenarioOutcome& outcome) {
  std::vector<double> values;
  for (const IterationStatus status : namedStatuses()) {
    double count = 0.0;
    for (const MpcIterationLog& row : outcome.result.trajectory.mpc) count += row.status == status;
    values.push_back(count);
  }
  for (const analysis::MetricDefinition& metric : analysis::runMetricTable()) {
    values.push_back(outcome.metrics.*metric.field);
  }
  return values;
}

void runStudyInto(const std::vector<const datasets::StudyRun*>& runs, int threads,
                  BatchProgress* progress, datasets::BatchDatasetWriter* writer,
                  const std::function<std::vector<double>(const datasets::StudyRun&,
                                                          const ScenarioOutcome&)>& values,
                  const std::function<void(const datasets::StudyRun&, const ScenarioOutcome&)>&
                      delivered) {
  std::vector<const datasets::Scenario*> scenarios;
  for (const datasets::StudyRun* run : runs) scenarios.push_back(&run->scenario);
  // Each slot is written by the worker of its run, then read by the writer: no slot is shared.
  std::vector<datasets::PreparedRun> prepared(runs.size());
  runScenarios(
      scenarios, threads, progress,
      [&](std::size_t position, ScenarioOutcome& outcome) {
        prepared[position] = datasets::BatchDatasetWriter::prepare(recordOf(runs[position], outcome));
      },
      [&](std::size_t position, ScenarioOutcome&& outcome) {
        datasets::BatchRunRecord record = recordOf(runs[position], outcome);
        record.values = values(*runs[position], outcome);
        writer->write(record, &prepared[position]);
        prepared[position] = datasets::PreparedRun{};  // free the chunks
        if (delivered) delivered(*runs[position], outcome);
      });
}

void runStudyPulled(const RunSource& next, int threads, datasets::BatchDatasetWriter* writer,
                    const std::function<std::vector<double>(const datasets::StudyRun&,
                                                            const ScenarioOutcome&)>& values,
                    const std::function<std::vector<double>(const datasets::StudyRun&,
                                                            const ScenarioOutcome&)>& report) {
  std::mutex mutex;  // the writer and the first error
  std::exception_ptr error;
  const auto worker = [&]() {
    RobotModelCache models;
    const datasets::StudyRun* finished = nullptr;
    std::vector<double> finished_report;
    try {
      while (const datasets::StudyRun* run = next(finished, std::move(finished_report))) {
        {
          std::lock_guard<std::mutex> lock(mutex);
          if (error) return;
        }
        const ScenarioOutcome outcome = runScenarioPipeline(run->scenario, &models);
        datasets::BatchRunRecord record = recordOf(run, outcome);
        const datasets::PreparedRun prepared = datasets::BatchDatasetWriter::prepare(record);
        record.values = values(*run, outcome);
        {
          std::lock_guard<std::mutex> lock(mutex);
          writer->write(record, &prepared);
        }
        finished = run;
        finished_report = report(*run, outcome);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();
  if (error) std::rethrow_exception(error);
}

void checkWritableParent(const fs::path& output) {
  std::error_code ec;
  for (fs::path folder = output.parent_path(); !folder.empty(); folder = folder.parent_path()) {
    if (fs::exists(folder, ec)) {
      if (!fs::is_directory(folder, ec) || ::access(folder.c_str(), W_OK | X_OK) != 0) {
        throw UsageError("cannot write output '" + output.string() + "': '" + folder.string() +
                         "' is not a writable directory");
      }
      break;
    }
    if (folder == folder.parent_path()) break;
  }
}

void writeTableCsv(const datasets::BatchSummaryTable& table, const std::string& path) {
  std::ofstream out(path);
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
  if (!out) throw std::runtime_error("cannot write " + path);
}

void writeTableMarkdown(const datasets::BatchSummaryTable& table, const std::string& path,
                        const std::string& title, const std::string& intro) {
  std::ofstream out(path);
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
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace wpg::cli
