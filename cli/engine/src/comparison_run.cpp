// A comparison study run by an executor (comparison_run.hpp).
#include "wpg/engine/comparison_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "wpg/datasets/storage/comparison_table.hpp"
#include "wpg/engine/study_summary.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool hasPlanner(const datasets::Scenario& scenario) {
  return scenario.goal.planner.algorithm != "none";
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

// A sample as the numbers a run's report carries (an MPI rank sends them to rank 0), and back:
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
  if (values.size() < 8) {
    throw std::runtime_error("a comparison sample of " + std::to_string(values.size()) + " values");
  }
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

analysis::ComparisonRunSample comparisonSampleOf(const datasets::Scenario& scenario,
                                                 const RunResult& result) {
  analysis::ComparisonRunSample sample;
  const std::optional<datasets::GoalOutcome>& goal = result.walk.goal;
  sample.goal_reached = goal && goal->goal_reached;
  sample.time_to_goal = goal ? goal->time_to_goal : kNaN;
  sample.walked_length = result.metrics.path_length;
  sample.steps = result.metrics.steps;
  sample.clearance_min = result.footsteps ? result.footsteps->least.step_centre : kNaN;
  sample.route_length = kNaN;
  if (goal && !goal->plans.empty()) {
    const datasets::RoutePlanRecord& first = goal->plans.front();
    if (!first.route.empty()) sample.route_length = first.route_length;
    sample.replans = static_cast<int>(goal->plans.size()) - 1;
    if (hasPlanner(scenario)) {
      for (const datasets::RoutePlanRecord& plan : goal->plans) {
        sample.planning_times.push_back(plan.planning_time);
      }
    }
  }
  for (const MpcIterationLog& row : result.walk.result.trajectory.mpc) {
    sample.nmpc_solve_times.push_back(row.solve_time);
  }
  return sample;
}

std::vector<datasets::SummaryColumn> comparisonSummaryColumns() {
  std::vector<datasets::SummaryColumn> columns = runSummaryColumns();
  const std::vector<datasets::SummaryColumn> goal = {
      {"goal_reached", "1", "1 when the robot stood at the goal within the tolerances", true},
      {"time_to_goal", "s", "walk time when the goal was reached (NaN: not reached)", false},
      {"route_length", "m", "length of the first plan's route (the straight line without a planner)", false},
      {"step_centre_clearance_min", "m",
       "least step-centre clearance to the margins, FCL check (< 0: a margin entered)", false},
      {"replans", "1", "plans after the first", true},
      {"planning_time_median", "s", "median wall time of the plans' solve() (NaN: no planner)", false},
      {"planning_time_max", "s", "largest wall time of the plans' solve() (NaN: no planner)", false},
  };
  columns.insert(columns.end(), goal.begin(), goal.end());
  return columns;
}

ComparisonOutcome runComparison(const datasets::ComparisonStudy& comparison,
                                const std::string& batch_file, StudyExecutor& executor,
                                StudyObserver& observer) {
  const datasets::Study& study = comparison.study;
  const std::size_t variants = comparison.variants.size();
  // The samples of each world x variant cell, in study order (the same sums, the same bits,
  // whatever executes the runs).
  std::vector<std::vector<analysis::ComparisonRunSample>> samples(comparison.worlds.size() *
                                                                  variants);
  StudyRunHandling handling;
  handling.columns = comparisonSummaryColumns();
  handling.summary_values = [](const datasets::StudyRun& run, const RunResult& result) {
    std::vector<double> values = runSummaryValues(result);
    for (const double value : goalSummaryValues(comparisonSampleOf(run.scenario, result))) {
      values.push_back(value);
    }
    return values;
  };
  // The sample is made twice per run (summary row, then its cell): cheap next to the walk.
  handling.report = [](const datasets::StudyRun& run, const RunResult& result) {
    return serializeSample(comparisonSampleOf(run.scenario, result));
  };
  handling.collect = [&](std::size_t run, std::vector<double>&& report) {
    const datasets::ComparisonRun& cell = comparison.runs[run];
    samples[cell.world * variants + cell.variant].push_back(deserializeSample(report));
  };
  StudyOutput output;
  output.path = batch_file;
  ComparisonOutcome outcome;
  if (!executor.run(study, output, handling, observer)) return outcome;

  for (std::size_t w = 0; w < comparison.worlds.size(); ++w) {
    for (std::size_t v = 0; v < variants; ++v) {
      outcome.cells.push_back(analysis::summarizeComparisonCell(
          comparison.worlds[w], comparison.variants[v], samples[w * variants + v]));
    }
  }
  datasets::writeComparisonTable(batch_file, comparison.worlds, comparison.variants,
                                 comparison.seeds, h5Table(outcome.cells));
  outcome.complete = true;
  return outcome;
}

ComparisonTableFiles writeComparisonTableFiles(const datasets::ComparisonStudy& comparison,
                                               const std::vector<analysis::ComparisonCell>& cells,
                                               const std::string& folder) {
  const datasets::Study& study = comparison.study;
  ComparisonTableFiles files;
  files.csv = (fs::path(folder) / "summary.csv").string();
  files.markdown = (fs::path(folder) / "summary.md").string();
  writeTableCsv(textTable(study.name, cells, 10), files.csv);
  writeTableMarkdown(
      textTable(study.name, cells, 4), files.markdown, "Comparison " + study.name,
      std::to_string(study.runs.size()) + " runs: " + std::to_string(comparison.worlds.size()) +
          " worlds x " + std::to_string(comparison.variants.size()) + " variants x " +
          std::to_string(comparison.seeds.size()) +
          " seeds; one row per world x variant; columns: datasets/SCHEMA.md, \"Comparison "
          "studies\".");
  return files;
}

}  // namespace wpg::engine
