// `wpg batch STUDY.yaml -o OUT.h5 [-j N] [--resume]`: a study (datasets/SCENARIOS.md,
// "Studies") expanded into runs, run on N worker threads, written run by run into one HDF5
// file (datasets/SCHEMA.md, "Batch files"), then OUT.summary.csv, OUT.summary.md and the
// summary figure OUT.summary.png beside it.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <system_error>
#include <thread>

#include "batch_progress.hpp"
#include "cli_common.hpp"
#include "scenario_runner.hpp"
#include "wpg/analysis/run_metrics.hpp"
#include "wpg/datasets/batch_dataset.hpp"
#include "wpg/datasets/input_error.hpp"
#include "wpg/datasets/output_file.hpp"
#include "wpg/datasets/study.hpp"

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

// The result columns of /batch/summary: NMPC iterations per status, then every metric.
std::vector<datasets::SummaryColumn> summaryColumns() {
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

std::vector<double> summaryValues(const ScenarioOutcome& outcome) {
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

void checkOutputFolder(const fs::path& output, const std::string& study) {
  std::error_code ec;
  // Never over the study, a device, a folder or a file that is not HDF5 (output_file.hpp).
  try {
    datasets::checkOutputPath(output.string(), datasets::OutputKind::kHdf5, {study});
  } catch (const datasets::InputError& e) {
    throw UsageError(e.what());
  }
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

// OUT.h5 -> OUT.summary.<extension>
std::string besideOutput(const fs::path& output, const std::string& extension) {
  fs::path path = output;
  path.replace_extension(".summary." + extension);
  return path.string();
}

void writeCsv(const datasets::BatchSummaryTable& table, const std::string& path) {
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

void writeMarkdown(const datasets::BatchSummaryTable& table, const std::string& path) {
  std::ofstream out(path);
  out << "# Study " << table.study << "\n\n" << table.rows
      << " runs; units in the header; definitions: datasets/METRICS.md.\n\n|";
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
  if (!out) throw std::runtime_error("cannot write " + path);
}

int drawSummaryFigure(const std::string& batch_file, const std::string& figure) {
  const std::string script = (fs::path(dataDirectory()) / "analysis" / "plot_batch.py").string();
  return runAnalysisScript(script, {batch_file, "-o", figure});
}

}  // namespace

int batchCommand(const BatchOptions& options) {
  if (options.threads < 1) throw UsageError("-j: expected a number of worker threads >= 1");
  const fs::path output(options.output);
  if (options.output.empty()) throw UsageError("-o: expected the batch file to write (OUT.h5)");
  std::error_code ec;
  if (!fs::is_regular_file(options.study, ec)) {
    throw UsageError(options.study + ": cannot read the study file: no such file");
  }
  // Everything about the input is checked before anything is written.
  const datasets::Study study = datasets::loadStudy(
      options.study, [](const std::string& base) { return resolveScenarioPath(base); },
      robotsDirectory(), options.threads);
  checkOutputFolder(output, options.study);
  std::set<std::string> replayed_robots;
  for (const datasets::StudyRun& run : study.runs) {
    if (run.scenario.replay) replayed_robots.insert(run.scenario.robot);
  }
  for (const std::string& robot : replayed_robots) (void)loadRobotModel(robot);

  const std::vector<datasets::SummaryColumn> columns = summaryColumns();
  std::unique_ptr<datasets::BatchDatasetWriter> writer;
  if (options.resume && fs::exists(output, ec)) {
    writer = datasets::BatchDatasetWriter::resume(output.string(), study, columns);
  } else {
    if (output.has_parent_path()) fs::create_directories(output.parent_path(), ec);
    writer = datasets::BatchDatasetWriter::create(output.string(), study, columns);
  }

  std::vector<const datasets::StudyRun*> todo;
  std::vector<const datasets::Scenario*> scenarios;
  for (const datasets::StudyRun& run : study.runs) {
    if (writer->done()[run.index]) continue;
    todo.push_back(&run);
    scenarios.push_back(&run.scenario);
  }
  const std::size_t already = study.runs.size() - todo.size();
  if (already > 0) {
    std::cerr << study.name << ": resuming, " << already << " of " << study.runs.size()
              << " runs already in " << output.string() << "\n";
  }
  BatchProgress progress(study.name, todo.size(), stderr);
  const auto recordOf = [&](std::size_t position, const ScenarioOutcome& outcome) {
    datasets::BatchRunRecord record;
    record.run = todo[position];
    record.result = &outcome.result;
    record.clearances = outcome.footsteps ? &outcome.footsteps->clearances : nullptr;
    record.multibody = outcome.replay ? &outcome.replay->validation : nullptr;
    record.goal = outcome.goal ? &*outcome.goal : nullptr;
    record.exit_status = outcome.exit_status;
    return record;
  };
  // Each slot is written by the worker of its run, then read by the writer: no slot is shared.
  std::vector<datasets::PreparedRun> prepared(todo.size());
  runScenarios(
      scenarios, options.threads, &progress,
      [&](std::size_t position, ScenarioOutcome& outcome) {
        prepared[position] = datasets::BatchDatasetWriter::prepare(recordOf(position, outcome));
      },
      [&](std::size_t position, ScenarioOutcome&& outcome) {
        datasets::BatchRunRecord record = recordOf(position, outcome);
        record.values = summaryValues(outcome);
        writer->write(record, &prepared[position]);
        prepared[position] = datasets::PreparedRun{};  // free the chunks
      });
  progress.finish();
  writer->close();

  const datasets::BatchSummaryTable table = datasets::readBatchSummary(output.string());
  writeCsv(table, besideOutput(output, "csv"));
  writeMarkdown(table, besideOutput(output, "md"));
  std::size_t failed = 0;
  for (std::size_t c = 0; c < table.column_names.size(); ++c) {
    if (table.column_names[c] != "exit_status") continue;
    for (const std::string& cell : table.cells[c]) failed += cell != "0";
  }
  std::cout << "wrote " << output.string() << " (" << table.rows << " runs), "
            << besideOutput(output, "csv") << ", " << besideOutput(output, "md");
  if (options.plot) {
    const std::string figure = besideOutput(output, "png");
    if (drawSummaryFigure(output.string(), figure) == 0) {
      std::cout << ", " << figure;
    } else {
      std::cout.flush();
      printWarning("the summary figure could not be drawn (Python with h5py and matplotlib?)");
    }
  }
  std::cout << "\n";
  if (failed > 0) {
    std::cout.flush();
    printError(std::to_string(failed) + " of " + std::to_string(table.rows) +
               " runs failed (exit_status in /batch/summary says which; datasets written)");
    return kExitRunFailed;
  }
  return kExitSuccess;
}

}  // namespace wpg::cli
