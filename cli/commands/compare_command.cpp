// `wpg compare STUDY.yaml -o DIR [-j N]`: a comparison study (datasets/SCENARIOS.md,
// "Comparison studies": worlds x variants x seeds, each a walk to a goal) run by the engine
// (comparison_run.hpp) on N worker threads, or on the ranks of an MPI job (DIR/study.h5 is then
// the index of DIR/study.shards/): DIR/study.h5 (a group per run and /batch/summary, as
// `wpg batch`, plus /compare/summary: one row per world x variant; datasets/SCHEMA.md),
// DIR/summary.csv, DIR/summary.md and the figures of analysis/plot_compare.py; with
// --ompl-log LOGS, LOGS/<world>.log in OMPL's benchmark log format
// (comparison_benchmark_logs.hpp).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <system_error>

#include "analysis_scripts.hpp"
#include "command_options.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "study_progress.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/comparison_benchmark_logs.hpp"
#include "wpg/engine/comparison_run.hpp"
#include "wpg/engine/mpi_executor.hpp"
#include "wpg/engine/run_input_checks.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

// A short table on stdout: success, time to goal, clearance per world x variant.
void printComparison(const std::vector<analysis::ComparisonCell>& cells) {
  std::printf("%-16s %-20s %9s %14s %10s %9s\n", "world", "variant", "reached", "time to goal",
              "clearance", "planning");
  for (const analysis::ComparisonCell& cell : cells) {
    const auto shown = [](double value, const char* unit, int decimals) {
      if (std::isnan(value)) return std::string("-");
      if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;  // no "-0.000"
      char text[32];
      std::snprintf(text, sizeof text, "%.*f %s", decimals, value, unit);
      return std::string(text);
    };
    const std::string reached = std::to_string(static_cast<int>(cell.reached)) + "/" +
                                std::to_string(static_cast<int>(cell.runs));
    std::printf("%-16s %-20s %9s %14s %10s %9s\n", cell.world.c_str(), cell.variant.c_str(),
                reached.c_str(), shown(cell.time_to_goal_median, "s", 1).c_str(),
                shown(cell.clearance_min, "m", 3).c_str(),
                shown(1e3 * cell.planning_time_median, "ms", 1).c_str());
  }
  std::cout.flush();
  std::fflush(stdout);
}

}  // namespace

int compareCommand(const CompareOptions& options) {
  if (options.threads < 1) throw UsageError("-j: expected a number of worker threads >= 1");
  if (options.output.empty()) throw UsageError("-o: expected the folder to write (DIR)");
  const auto started = std::chrono::steady_clock::now();  // the study's wall time, in the logs
  std::error_code ec;
  if (!fs::is_regular_file(options.study, ec)) {
    throw UsageError(options.study + ": cannot read the study file: no such file");
  }
  // Everything about the input is checked before anything is written.
  const fs::path folder(options.output);
  const fs::path batch_file = folder / "study.h5";
  datasets::ComparisonStudy comparison;
  const std::optional<engine::MpiWorld> world = engine::checkInputWhileMpiStarts([&] {
    comparison = datasets::loadComparisonStudy(
        options.study, [](const std::string& base) { return resolveScenarioPath(base); },
        robotsDirectory(), options.threads);
    for (const datasets::StudyRun& run : comparison.study.runs) {
      if (!run.scenario.goal.enabled) {
        throw datasets::InputError(options.study + ": world '" +
                                   comparison.worlds[comparison.runs[run.index].world] +
                                   "': expected a walk to a goal (a scenario with `goal:`)");
      }
    }
    std::error_code error;
    if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
      throw UsageError("output '" + folder.string() + "' is not a directory");
    }
    // Every file the command writes in DIR, held to the main output's rules (output_file.hpp).
    std::vector<datasets::PlannedOutput> outputs = {
        {batch_file.string(), datasets::OutputKind::kHdf5},
        {(folder / "summary.csv").string(), datasets::OutputKind::kText},
        {(folder / "summary.md").string(), datasets::OutputKind::kText}};
    if (options.plot) {
      for (const std::string& name : {std::string("success_rates"), std::string("time_to_goal")})
        outputs.push_back({(folder / (name + ".png")).string(), datasets::OutputKind::kPng});
      for (const std::string& name : comparison.worlds)
        outputs.push_back({(folder / ("top_" + name + ".png")).string(), datasets::OutputKind::kPng});
    }
    datasets::checkOutputPaths(outputs, {options.study});
    engine::checkStudyRobotModels(comparison.study, robotsDirectory());
    if (!options.ompl_log.empty()) {
      try {
        engine::checkBenchmarkLogOutputs(options.ompl_log, comparison.worlds);
      } catch (const datasets::InputError& e) {
        throw UsageError(std::string("--ompl-log: ") + e.what());
      }
    }
  });
  const datasets::Study& study = comparison.study;

  // What the runs' scenarios warn about (a clamped command, ...), once, from rank 0.
  if (!world || world->rank == 0) {
    std::vector<std::string> warnings;
    for (const datasets::StudyRun& run : study.runs) {
      warnings.insert(warnings.end(), run.scenario.warnings.begin(), run.scenario.warnings.end());
    }
    printWarnings(warnings);
  }
  fs::create_directories(folder, ec);
  StudyProgress progress(study.name);
  // Under MPI the ranks share the runs, one worker per rank unless -j says otherwise.
  const std::unique_ptr<engine::StudyExecutor> executor =
      world ? engine::makeMpiExecutor(*world, options.threads_given ? options.threads : 1,
                                      robotsDirectory())
            : engine::makeThreadExecutor(options.threads, robotsDirectory());
  engine::ComparisonOutcome outcome;
  engine::ComparisonTableFiles files;
  try {
    outcome = engine::runComparison(comparison, batch_file.string(), *executor, progress);
    if (outcome.complete) {
      files = engine::writeComparisonTableFiles(comparison, outcome.cells, folder.string());
    }
  } catch (const datasets::InputError&) {
    throw;  // refused before anything was written (a file in use is another's)
  } catch (...) {
    // Could not complete (a full disk): a comparison is not resumed, its partial file is
    // of no use; removed, as `wpg run` leaves no partial dataset.
    if (!world) fs::remove(batch_file, ec);
    throw;
  }
  if (!outcome.complete) {  // an MPI rank other than 0
    engine::finishMpi();
    return kExitSuccess;
  }

  printComparison(outcome.cells);
  std::cout << "wrote " << batch_file.string() << " (" << study.runs.size() << " runs), "
            << files.csv << ", " << files.markdown;
  if (options.plot) {
    const std::string script = (fs::path(dataDirectory()) / "analysis" / "plot_compare.py").string();
    if (runAnalysisScript(script, {batch_file.string(), "-o", folder.string()}) == 0) {
      std::cout << ", figures " << (folder / "*.png").string();
    } else {
      std::cout.flush();
      printWarning("the study's figures could not be drawn (Python with h5py and matplotlib?)");
    }
  }
  if (!options.ompl_log.empty()) {
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - started;
    std::vector<std::string> logs;
    try {
      logs = engine::writeComparisonBenchmarkLogs(batch_file.string(), options.ompl_log,
                                                  seconds.count());
    } catch (const datasets::InputError& e) {
      throw UsageError(std::string("--ompl-log: ") + e.what());
    }
    std::cout << ", OMPL logs";
    for (const std::string& log : logs) std::cout << " " << log;
  }
  std::cout << "\n";
  if (world) engine::finishMpi();
  // Runs that miss the goal are results of the comparison, not errors of the command.
  return kExitSuccess;
}

}  // namespace wpg::cli
