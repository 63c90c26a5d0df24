// `wpg compare STUDY.yaml -o DIR [-j N]`: a comparison study (datasets/SCENARIOS.md,
// "Comparison studies": worlds x variants x seeds, each a walk to a goal) run on N worker
// threads through the batch machinery (study_execution.hpp), written to DIR/study.h5 (a group
// per run and /batch/summary, as `wpg batch`, plus /compare/summary: one row per world x
// variant; datasets/SCHEMA.md), DIR/summary.csv, DIR/summary.md and the figures of
// analysis/plot_compare.py. Under an MPI launcher the ranks share the runs
// (distributed_study.hpp): DIR/study.h5 is then the index of DIR/study.shards/.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>
#include <system_error>

#include "batch_progress.hpp"
#include "compare_ompl_log.hpp"
#include "cli_common.hpp"
#include "distributed_study.hpp"
#include "mpi_world.hpp"
#include "study_execution.hpp"
#include "wpg/analysis/comparison_summary.hpp"
#include "wpg/datasets/comparison_study.hpp"
#include "wpg/datasets/comparison_table.hpp"
#include "wpg/datasets/input_error.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool hasPlanner(const datasets::Scenario& scenario) {
  return scenario.goal.planner.algorithm != "none";
}

// What a run adds to its cell of the comparison table.
analysis::ComparisonRunSample sampleOf(const datasets::Scenario& scenario,
                                       const ScenarioOutcome& outcome) {
  analysis::ComparisonRunSample sample;
  sample.goal_reached = outcome.goal && outcome.goal->goal_reached;
  sample.time_to_goal = outcome.goal ? outcome.goal->time_to_goal : kNaN;
  sample.walked_length = outcome.metrics.path_length;
  sample.steps = outcome.metrics.steps;
  sample.clearance_min = outcome.footsteps ? outcome.footsteps->least.step_centre : kNaN;
  sample.route_length = kNaN;
  if (outcome.goal && !outcome.goal->plans.empty()) {
    const datasets::RoutePlanRecord& first = outcome.goal->plans.front();
    if (!first.route.empty()) sample.route_length = first.route_length;
    sample.replans = static_cast<int>(outcome.goal->plans.size()) - 1;
    if (hasPlanner(scenario)) {
      for (const datasets::RoutePlanRecord& plan : outcome.goal->plans) {
        sample.planning_times.push_back(plan.planning_time);
      }
    }
  }
  for (const MpcIterationLog& row : outcome.result.trajectory.mpc) {
    sample.nmpc_solve_times.push_back(row.solve_time);
  }
  return sample;
}

// The goal columns added to /batch/summary after those of `wpg batch`.
std::vector<datasets::SummaryColumn> goalSummaryColumns() {
  return {
      {"goal_reached", "1", "1 when the robot stood at the goal within the tolerances", true},
      {"time_to_goal", "s", "walk time when the goal was reached (NaN: not reached)", false},
      {"route_length", "m", "length of the first plan's route (the straight line without a planner)", false},
      {"step_centre_clearance_min", "m",
       "least step-centre clearance to the margins, FCL check (< 0: a margin entered)", false},
      {"replans", "1", "plans after the first", true},
      {"planning_time_median", "s", "median wall time of the plans' solve() (NaN: no planner)", false},
      {"planning_time_max", "s", "largest wall time of the plans' solve() (NaN: no planner)", false},
  };
}

std::vector<double> goalSummaryValues(const analysis::ComparisonRunSample& sample) {
  const double median = analysis::quantile(sample.planning_times, 0.5);
  double largest = kNaN;
  for (const double time : sample.planning_times) {
    largest = std::isfinite(largest) ? std::max(largest, time) : time;
  }
  return {sample.goal_reached ? 1.0 : 0.0, sample.time_to_goal, sample.route_length,
          sample.clearance_min, static_cast<double>(sample.replans), median, largest};
}

std::string formatCell(double value, int digits) {
  if (std::isnan(value)) return "nan";
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

// The comparison table as text cells (summary.csv: 10 significant digits; summary.md: 4).
datasets::BatchSummaryTable textTable(const std::string& study,
                                      const std::vector<analysis::ComparisonCell>& cells,
                                      int digits) {
  datasets::BatchSummaryTable table;
  table.study = study;
  table.rows = cells.size();
  table.column_names = {"world", "variant"};
  table.column_units = {"1", "1"};
  table.cells.resize(2);
  for (const analysis::ComparisonCell& cell : cells) {
    table.cells[0].push_back(cell.world);
    table.cells[1].push_back(cell.variant);
  }
  for (const analysis::ComparisonColumn& column : analysis::comparisonColumns()) {
    table.column_names.push_back(column.name);
    table.column_units.push_back(column.unit);
    std::vector<std::string> texts;
    for (const analysis::ComparisonCell& cell : cells) {
      texts.push_back(formatCell(cell.*column.field, digits));
    }
    table.cells.push_back(std::move(texts));
  }
  return table;
}

std::vector<datasets::TableColumn> h5Table(const std::vector<analysis::ComparisonCell>& cells) {
  std::vector<datasets::TableColumn> columns(2);
  columns[0] = {"world", "1", "world name (the study's worlds)", true, {}, {}};
  columns[1] = {"variant", "1", "variant name (the study's variants)", true, {}, {}};
  for (const analysis::ComparisonCell& cell : cells) {
    columns[0].strings.push_back(cell.world);
    columns[1].strings.push_back(cell.variant);
  }
  for (const analysis::ComparisonColumn& column : analysis::comparisonColumns()) {
    datasets::TableColumn data;
    data.name = column.name;
    data.units = column.unit;
    data.description = std::string(column.name) + " (datasets/SCHEMA.md, \"Comparison studies\")" +
                       (column.wall_time ? "; a wall time" : "");
    for (const analysis::ComparisonCell& cell : cells) data.numbers.push_back(cell.*column.field);
    columns.push_back(std::move(data));
  }
  return columns;
}

// A sample as the doubles an MPI rank sends to rank 0 (distributed_study.hpp), and back:
// [reached, time_to_goal, walked, route, steps, clearance, replans, n planning times, the
// planning times, the NMPC solve times].
std::vector<double> serializeSample(const analysis::ComparisonRunSample& sample) {
  std::vector<double> values = {sample.goal_reached ? 1.0 : 0.0, sample.time_to_goal,
                                sample.walked_length, sample.route_length, sample.steps,
                                sample.clearance_min, static_cast<double>(sample.replans),
                                static_cast<double>(sample.planning_times.size())};
  values.insert(values.end(), sample.planning_times.begin(), sample.planning_times.end());
  values.insert(values.end(), sample.nmpc_solve_times.begin(), sample.nmpc_solve_times.end());
  return values;
}

analysis::ComparisonRunSample deserializeSample(const std::vector<double>& values) {
  analysis::ComparisonRunSample sample;
  if (values.size() < 8) throw std::runtime_error("MPI: a comparison sample of " + std::to_string(values.size()) + " values");
  sample.goal_reached = values[0] != 0.0;
  sample.time_to_goal = values[1];
  sample.walked_length = values[2];
  sample.route_length = values[3];
  sample.steps = values[4];
  sample.clearance_min = values[5];
  sample.replans = static_cast<int>(values[6]);
  const auto plans = static_cast<std::size_t>(values[7]);
  sample.planning_times.assign(values.begin() + 8, values.begin() + 8 + static_cast<long>(plans));
  sample.nmpc_solve_times.assign(values.begin() + 8 + static_cast<long>(plans), values.end());
  return sample;
}

}  // namespace

int compareCommand(const CompareOptions& options) {
  if (options.threads < 1) throw UsageError("-j: expected a number of worker threads >= 1");
  if (options.output.empty()) throw UsageError("-o: expected the folder to write (DIR)");
  const auto started = std::chrono::steady_clock::now();
  std::error_code ec;
  if (!fs::is_regular_file(options.study, ec)) {
    throw UsageError(options.study + ": cannot read the study file: no such file");
  }
  // Everything about the input is checked before anything is written.
  const fs::path folder(options.output);
  const fs::path batch_file = folder / "study.h5";
  datasets::ComparisonStudy comparison;
  const std::optional<mpi::World> world = checkInputWhileMpiStarts([&] {
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
    checkWritableParent(batch_file);
    std::set<std::string> replayed_robots;
    for (const datasets::StudyRun& run : comparison.study.runs) {
      if (run.scenario.replay) replayed_robots.insert(run.scenario.robot);
    }
    for (const std::string& robot : replayed_robots) (void)loadRobotModel(robot);
    if (!options.ompl_log.empty()) checkOmplLogOutputs(options.ompl_log, comparison.worlds);
  });
  const datasets::Study& study = comparison.study;

  fs::create_directories(folder, ec);
  std::vector<datasets::SummaryColumn> columns = runSummaryColumns();
  for (const datasets::SummaryColumn& column : goalSummaryColumns()) columns.push_back(column);
  const auto summary_values = [](const datasets::StudyRun& run, const ScenarioOutcome& outcome) {
    std::vector<double> values = runSummaryValues(outcome);
    for (const double value : goalSummaryValues(sampleOf(run.scenario, outcome))) {
      values.push_back(value);
    }
    return values;
  };
  const std::size_t variants = comparison.variants.size();
  std::vector<std::vector<analysis::ComparisonRunSample>> samples(comparison.worlds.size() *
                                                                  variants);
  if (world) {
    // The ranks share the runs (distributed_study.hpp); each run's sample comes to rank 0 and
    // goes to its cell in run order, as the thread runner delivers them (same sums, same bits).
    std::vector<analysis::ComparisonRunSample> by_run(study.runs.size());
    const bool root = runStudyOnRanks(
        *world, study, columns, {batch_file.string(), false, options.threads_given ? options.threads : 1},
        summary_values,
        [](const datasets::StudyRun& run, const ScenarioOutcome& outcome) {
          return serializeSample(sampleOf(run.scenario, outcome));
        },
        [&](std::size_t run, std::vector<double>&& values) { by_run[run] = deserializeSample(values); });
    if (!root) {
      mpi::finish();
      return kExitSuccess;
    }
    for (const datasets::StudyRun& run : study.runs) {
      const datasets::ComparisonRun& cell = comparison.runs[run.index];
      samples[cell.world * variants + cell.variant].push_back(std::move(by_run[run.index]));
    }
  } else {
    std::unique_ptr<datasets::BatchDatasetWriter> writer =
        datasets::BatchDatasetWriter::create(batch_file.string(), study, columns);
    std::vector<const datasets::StudyRun*> runs;
    for (const datasets::StudyRun& run : study.runs) runs.push_back(&run);
    BatchProgress progress(study.name, runs.size(), stderr);
    // The sample is made twice per run (summary row, then its cell): cheap next to the walk.
    runStudyInto(runs, options.threads, &progress, writer.get(), summary_values,
                 [&](const datasets::StudyRun& run, const ScenarioOutcome& outcome) {
                   const datasets::ComparisonRun& cell = comparison.runs[run.index];
                   samples[cell.world * variants + cell.variant].push_back(
                       sampleOf(run.scenario, outcome));
                 });
    progress.finish();
    writer->close();
  }

  std::vector<analysis::ComparisonCell> cells;
  for (std::size_t w = 0; w < comparison.worlds.size(); ++w) {
    for (std::size_t v = 0; v < variants; ++v) {
      cells.push_back(analysis::summarizeComparisonCell(comparison.worlds[w],
                                                        comparison.variants[v],
                                                        samples[w * variants + v]));
    }
  }
  datasets::writeComparisonTable(batch_file.string(), comparison.worlds, comparison.variants,
                                 comparison.seeds, h5Table(cells));
  const std::string csv = (folder / "summary.csv").string();
  const std::string markdown = (folder / "summary.md").string();
  writeTableCsv(textTable(study.name, cells, 10), csv);
  writeTableMarkdown(
      textTable(study.name, cells, 4), markdown, "Comparison " + study.name,
      std::to_string(study.runs.size()) + " runs: " + std::to_string(comparison.worlds.size()) +
          " worlds x " + std::to_string(variants) + " variants x " +
          std::to_string(comparison.seeds.size()) +
          " seeds; one row per world x variant; columns: datasets/SCHEMA.md, \"Comparison "
          "studies\".");

  // A short table on stdout: success, time to goal, clearance per world x variant.
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
  std::cout << "wrote " << batch_file.string() << " (" << study.runs.size() << " runs), " << csv
            << ", " << markdown;
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
    std::cout << ", OMPL logs";
    for (const std::string& log : writeOmplLogs(batch_file.string(), options.ompl_log, seconds.count())) {
      std::cout << " " << log;
    }
  }
  std::cout << "\n";
  if (world) mpi::finish();
  // Runs that miss the goal are results of the comparison, not errors of the command.
  return kExitSuccess;
}

}  // namespace wpg::cli
