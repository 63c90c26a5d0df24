// `wpg compare STUDY.yaml -o DIR [-j N] [--resume] [--shard K/N]`: a comparison study
// (datasets/SCENARIOS.md, "Comparison studies": worlds x variants x seeds, each a walk to a goal)
// run by the engine (comparison_study_run.hpp: every input and output checked first) on N
// worker threads, or on the ranks of an MPI job (DIR/study.h5 is then the index of
// DIR/study.shards/): DIR/study.h5 (a group per run and
// /batch/summary, as `wpg batch`, plus /compare/summary: one row per world x variant;
// datasets/SCHEMA.md), DIR/summary.csv, DIR/summary.md and the figures of
// analysis/plot_compare.py; with --ompl-log LOGS, LOGS/<world>.log in OMPL's benchmark log
// format (comparison_benchmark_logs.hpp). --resume finishes DIR/study.h5 of the same study;
// --shard K/N runs slice K of N into DIR/study.shards/slice-K-of-N.h5, joined by `wpg merge`.
// This file parses, draws the figures and prints.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "analysis_scripts.hpp"
#include "command_options.hpp"
#include "comparison_files.hpp"
#include "data_paths.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "study_request_options.hpp"
#include "study_progress.hpp"
#include "summary_printing.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/engine/comparison_benchmark_logs.hpp"
#include "wpg/engine/comparison_study_run.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

// A short table on stdout: success, runs that ended blocked, time to goal, clearance per
// world x variant.
void printComparison(const std::vector<analysis::ComparisonCell>& cells) {
  std::printf("%-16s %-20s %9s %8s %14s %10s %9s\n", "world", "variant", "reached", "blocked",
              "time to goal", "clearance", "planning");
  for (const analysis::ComparisonCell& cell : cells) {
    const auto shown = [](double value, const char* unit, int decimals) {
      if (std::isnan(value)) return std::string("-");
      return fixed(value, decimals) + " " + unit;
    };
    const std::string reached = std::to_string(static_cast<int>(cell.reached)) + "/" +
                                std::to_string(static_cast<int>(cell.runs));
    std::printf("%-16s %-20s %9s %8d %14s %10s %9s\n", cell.world.c_str(), cell.variant.c_str(),
                reached.c_str(), static_cast<int>(cell.blocked),
                shown(cell.time_to_goal_median, "s", 1).c_str(),
                std::isnan(cell.clearance_min)
                    ? "-"
                    : (clearanceText(cell.clearance_min, 3) + " m").c_str(),
                shown(1e3 * cell.planning_time_median, "ms", 1).c_str());
  }
  std::cout.flush();
  std::fflush(stdout);
}

}  // namespace

void reportComparisonFiles(const std::string& study_file, std::size_t runs,
                           const std::vector<analysis::ComparisonCell>& cells,
                           const engine::ComparisonTableFiles& files, bool plot) {
  const fs::path folder = fs::path(study_file).parent_path();
  printComparison(cells);
  std::cout << "wrote " << study_file << " (" << runs << " runs), " << files.csv << ", "
            << files.markdown;
  if (plot) {
    const std::string script = (fs::path(dataDirectory()) / "analysis" / "plot_compare.py").string();
    const std::string where = folder.empty() ? std::string(".") : folder.string();
    if (runAnalysisScript(script, {study_file, "-o", where}) == 0) {
      std::cout << ", figures " << (folder / "*.png").string();
    } else {
      std::cout.flush();
      printWarning("the study's figures could not be drawn (Python with h5py and matplotlib?)");
    }
  }
}

int compareCommand(const CompareOptions& options) {
  engine::StudyRequest request = studyRequestOf(options);
  request.ompl_log = options.ompl_log;
  StudyProgress progress;
  const engine::ComparisonStudyResult result = engine::runComparisonStudy(request, progress);
  if (request.shard) {
    std::cout << "wrote " << result.runs_file << " (shard "
              << datasets::shardSliceLabel(request.shard->index, request.shard->count) << ": "
              << result.slice_runs << " of " << result.runs
              << " runs; join the shards with `wpg merge " << result.study_file << " "
              << fs::path(result.runs_file).parent_path().string() << "`)\n";
    return kExitSuccess;
  }
  if (!result.complete) return kExitSuccess;  // an MPI rank other than 0: rank 0 reports
  reportComparisonFiles(result.study_file, result.layout.runs, result.cells, result.tables,
                        options.plot);
  if (!result.ompl_logs.empty()) {
    std::cout << ", OMPL logs";
    for (const std::string& log : result.ompl_logs) std::cout << " " << log;
    // The same as Planner Arena's database (Python's sqlite3: no OMPL script needed).
    std::vector<std::string> arguments = result.ompl_logs;
    const std::string database = engine::benchmarkDatabasePath(request.ompl_log);
    arguments.insert(arguments.end(), {"-o", database});
    const std::string script =
        (fs::path(dataDirectory()) / "analysis" / "ompl_benchmark_database.py").string();
    std::cout.flush();
    if (runAnalysisScript(script, arguments) == 0) {
      std::cout << ", database " << database;
    } else {
      printWarning("the Planner Arena database could not be written (Python 3's sqlite3?)");
    }
  }
  std::cout << "\n";
  // Runs that miss the goal are results of the comparison, not errors of the command.
  return kExitSuccess;
}

}  // namespace wpg::cli
