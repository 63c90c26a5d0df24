// `wpg compare STUDY.yaml -o DIR [-j N] [--resume] [--shard K/N]`: a comparison study
// (datasets/SCENARIOS.md, "Comparison studies": worlds x variants x seeds, each a walk to a goal)
// run by the engine (comparison_run.hpp) on N worker threads, or on the ranks of an MPI job
// (DIR/study.h5 is then the index of DIR/study.shards/): DIR/study.h5 (a group per run and
// /batch/summary, as `wpg batch`, plus /compare/summary: one row per world x variant;
// datasets/SCHEMA.md), DIR/summary.csv, DIR/summary.md and the figures of
// analysis/plot_compare.py; with --ompl-log LOGS, LOGS/<world>.log in OMPL's benchmark log
// format (comparison_benchmark_logs.hpp). --resume finishes DIR/study.h5 of the same study;
// --shard K/N runs slice K of N into DIR/study.shards/slice-K-of-N.h5, joined by `wpg merge`.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <system_error>

#include "analysis_scripts.hpp"
#include "command_options.hpp"
#include "comparison_files.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "shard_option.hpp"
#include "study_progress.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/comparison_benchmark_logs.hpp"
#include "wpg/engine/comparison_run.hpp"
#include "wpg/engine/mpi_executor.hpp"
#include "wpg/engine/run_input_checks.hpp"

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
      if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;  // no "-0.000"
      char text[32];
      std::snprintf(text, sizeof text, "%.*f %s", decimals, value, unit);
      return std::string(text);
    };
    const std::string reached = std::to_string(static_cast<int>(cell.reached)) + "/" +
                                std::to_string(static_cast<int>(cell.runs));
    std::printf("%-16s %-20s %9s %8d %14s %10s %9s\n", cell.world.c_str(), cell.variant.c_str(),
                reached.c_str(), static_cast<int>(cell.blocked),
                shown(cell.time_to_goal_median, "s", 1).c_str(),
                shown(cell.clearance_min, "m", 3).c_str(),
                shown(1e3 * cell.planning_time_median, "ms", 1).c_str());
  }
  std::cout.flush();
  std::fflush(stdout);
}

// The shard file of slice K of N: DIR/study.shards/slice-K-of-N.h5 (the folder of an MPI
// comparison's rank shards too; `wpg merge DIR/study.h5 DIR/study.shards` joins them).
fs::path sliceFile(const fs::path& folder, const engine::ShardSlice& slice) {
  return folder / "study.shards" /
         ("slice-" + std::to_string(slice.index) + "-of-" + std::to_string(slice.count) + ".h5");
}

}  // namespace

std::vector<datasets::PlannedOutput> comparisonSideOutputs(const std::string& study_file,
                                                           const std::vector<std::string>& worlds,
                                                           bool plot) {
  const fs::path folder = fs::path(study_file).parent_path();
  std::vector<datasets::PlannedOutput> outputs = {
      {(folder / "summary.csv").string(), datasets::OutputKind::kText},
      {(folder / "summary.md").string(), datasets::OutputKind::kText}};
  if (plot) {
    for (const std::string& name : {std::string("success_rates"), std::string("time_to_goal")})
      outputs.push_back({(folder / (name + ".png")).string(), datasets::OutputKind::kPng});
    for (const std::string& name : worlds)
      outputs.push_back({(folder / ("top_" + name + ".png")).string(), datasets::OutputKind::kPng});
  }
  return outputs;
}

void finishComparisonFiles(const std::string& study_file, const engine::ComparisonLayout& layout,
                           const std::vector<analysis::ComparisonCell>& cells, bool plot) {
  const fs::path folder = fs::path(study_file).parent_path();
  const engine::ComparisonTableFiles files =
      engine::writeComparisonTableFiles(layout, cells, folder.string());
  printComparison(cells);
  std::cout << "wrote " << study_file << " (" << layout.runs << " runs), " << files.csv << ", "
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
  if (options.threads < 1) throw UsageError("-j: expected a number of worker threads >= 1");
  if (options.output.empty()) throw UsageError("-o: expected the folder to write (DIR)");
  const std::optional<engine::ShardSlice> slice =
      options.shard.empty() ? std::nullopt : std::optional(parseShardOption(options.shard));
  if (slice) refuseShardUnderMpi();
  if (slice && !options.ompl_log.empty()) {
    throw UsageError("--ompl-log: not with --shard (the logs describe the whole study)");
  }
  const auto started = std::chrono::steady_clock::now();  // the study's wall time, in the logs
  std::error_code ec;
  if (!fs::is_regular_file(options.study, ec)) {
    throw UsageError(options.study + ": cannot read the study file: no such file");
  }
  // Everything about the input is checked before anything is written.
  const fs::path folder(options.output);
  const fs::path batch_file = folder / "study.h5";
  // What this process writes the runs into: the study file, or the slice's shard file.
  const fs::path runs_file = slice ? sliceFile(folder, *slice) : batch_file;
  datasets::ComparisonStudy comparison;
  const auto check_input = [&] {
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
    // Every file the command writes in DIR, held to the main output's rules (output_file.hpp);
    // a slice writes its shard file only.
    std::vector<datasets::PlannedOutput> outputs = {{runs_file.string(), datasets::OutputKind::kHdf5}};
    if (!slice) {
      for (datasets::PlannedOutput& output :
           comparisonSideOutputs(batch_file.string(), comparison.worlds, options.plot)) {
        outputs.push_back(std::move(output));
      }
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
  };
  std::optional<engine::MpiWorld> world;
  if (slice) {
    check_input();  // a slice is one process, whatever launched it
  } else {
    world = engine::checkInputWhileMpiStarts(check_input);
  }
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
  // An error while running (a full disk) leaves the runs written so far in the file, as
  // `wpg batch` does: --resume finishes it.
  const engine::StudyOutput output{runs_file.string(), options.resume, slice};
  const engine::ComparisonOutcome outcome =
      engine::runComparison(comparison, output, *executor, progress);
  if (slice) {
    std::size_t slice_runs = 0;
    for (const datasets::StudyRun& run : study.runs) {
      slice_runs += datasets::inShardSlice(run.index, slice->index, slice->count);
    }
    std::cout << "wrote " << runs_file.string() << " (shard "
              << datasets::shardSliceLabel(slice->index, slice->count) << ": " << slice_runs
              << " of " << study.runs.size() << " runs; join the shards with `wpg merge "
              << batch_file.string() << " " << runs_file.parent_path().string() << "`)\n";
    return kExitSuccess;
  }
  if (!outcome.complete) {  // an MPI rank other than 0
    engine::finishMpi();
    return kExitSuccess;
  }

  finishComparisonFiles(batch_file.string(), engine::comparisonLayout(comparison), outcome.cells,
                        options.plot);
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
