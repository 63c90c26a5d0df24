// A comparison study run by an executor (comparison_run.hpp).
#include "wpg/engine/comparison_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/storage/comparison_runs.hpp"
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

// What a run read back from the study file adds to its cell (as comparisonSampleOf made it
// when the run finished: the summary's columns are its values, the times those of its groups).
analysis::ComparisonRunSample sampleOf(const datasets::StoredComparisonRun& run) {
  analysis::ComparisonRunSample sample;
  sample.goal_reached = run.goal_reached;
  sample.blocked = run.blocked;
  sample.time_to_goal = run.time_to_goal;
  sample.walked_length = run.path_length;
  sample.route_length = run.route_length;
  sample.steps = run.steps;
  sample.clearance_min = run.clearance_min;
  sample.replans = run.replans;
  sample.planning_times = run.planning_times;
  sample.nmpc_solve_times = run.nmpc_solve_times;
  return sample;
}

std::size_t indexOf(const std::vector<std::string>& names, const std::string& name) {
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

}  // namespace

analysis::ComparisonRunSample comparisonSampleOf(const datasets::Scenario& scenario,
                                                 const RunResult& result) {
  analysis::ComparisonRunSample sample;
  const std::optional<datasets::GoalOutcome>& goal = result.walk.goal;
  sample.goal_reached = goal && goal->goal_reached;
  sample.blocked = result.walk.result.blocked;
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

ComparisonLayout comparisonLayout(const datasets::ComparisonStudy& comparison) {
  return {comparison.study.name, comparison.worlds, comparison.variants, comparison.seeds,
          comparison.study.runs.size()};
}

ComparisonLayout readComparisonLayout(const std::string& study_file) {
  ComparisonLayout layout;
  layout.study_name = datasets::readShardContents(study_file).study_name;
  const std::vector<datasets::StoredComparisonRun> runs = datasets::readComparisonRuns(study_file);
  layout.runs = runs.size();
  for (const datasets::StoredComparisonRun& run : runs) {
    if (indexOf(layout.worlds, run.world) == layout.worlds.size()) layout.worlds.push_back(run.world);
    if (indexOf(layout.variants, run.variant) == layout.variants.size()) {
      layout.variants.push_back(run.variant);
    }
    const int seed = static_cast<int>(run.seed);
    if (std::find(layout.seeds.begin(), layout.seeds.end(), seed) == layout.seeds.end()) {
      layout.seeds.push_back(seed);
    }
  }
  return layout;
}

std::vector<analysis::ComparisonCell> writeComparisonSummary(const std::string& study_file,
                                                             const ComparisonLayout& layout) {
  const std::size_t variants = layout.variants.size();
  // The samples of each world x variant cell, in study order (the same sums, the same bits,
  // whoever ran the runs and in how many goes).
  std::vector<std::vector<analysis::ComparisonRunSample>> samples(layout.worlds.size() * variants);
  const std::vector<datasets::StoredComparisonRun> runs = datasets::readComparisonRuns(study_file);
  if (runs.size() != layout.runs) {
    throw datasets::InputError(study_file + ": holds " + std::to_string(runs.size()) +
                               " runs, expected " + std::to_string(layout.runs) +
                               " (another comparison)");
  }
  for (const datasets::StoredComparisonRun& run : runs) {
    const std::size_t w = indexOf(layout.worlds, run.world), v = indexOf(layout.variants, run.variant);
    if (w == layout.worlds.size() || v == variants) {
      throw datasets::InputError(study_file + ": run " + run.name + " is of world '" + run.world +
                                 "' and variant '" + run.variant + "', not of this comparison");
    }
    if (!run.done) {
      throw datasets::InputError(study_file + ": run " + run.name +
                                 " is not in the file (an unfinished study)");
    }
    samples[w * variants + v].push_back(sampleOf(run));
  }
  std::vector<analysis::ComparisonCell> cells;
  for (std::size_t w = 0; w < layout.worlds.size(); ++w) {
    for (std::size_t v = 0; v < variants; ++v) {
      cells.push_back(analysis::summarizeComparisonCell(layout.worlds[w], layout.variants[v],
                                                        samples[w * variants + v]));
    }
  }
  datasets::writeComparisonTable(study_file, layout.worlds, layout.variants, layout.seeds,
                                 h5Table(cells));
  return cells;
}

ComparisonOutcome runComparison(const datasets::ComparisonStudy& comparison,
                                const StudyOutput& output, StudyExecutor& executor,
                                StudyObserver& observer) {
  StudyRunHandling handling;
  handling.columns = comparisonSummaryColumns();
  handling.summary_values = [](const datasets::StudyRun& run, const RunResult& result) {
    std::vector<double> values = runSummaryValues(result);
    for (const double value : goalSummaryValues(comparisonSampleOf(run.scenario, result))) {
      values.push_back(value);
    }
    return values;
  };
  ComparisonOutcome outcome;
  if (!executor.run(comparison.study, output, handling, observer) || output.shard) return outcome;
  outcome.cells = writeComparisonSummary(output.path, comparisonLayout(comparison));
  outcome.complete = true;
  return outcome;
}

ComparisonOutcome runComparison(const datasets::ComparisonStudy& comparison,
                                const std::string& batch_file, StudyExecutor& executor,
                                StudyObserver& observer) {
  StudyOutput output;
  output.path = batch_file;
  return runComparison(comparison, output, executor, observer);
}

std::vector<datasets::PlannedOutput> comparisonSideOutputs(const std::string& study_file,
                                                           const std::vector<std::string>& worlds,
                                                           bool figures) {
  const fs::path folder = fs::path(study_file).parent_path();
  std::vector<datasets::PlannedOutput> outputs = {
      {(folder / "summary.csv").string(), datasets::OutputKind::kText},
      {(folder / "summary.md").string(), datasets::OutputKind::kText}};
  if (figures) {
    for (const std::string& name : {std::string("success_rates"), std::string("time_to_goal")})
      outputs.push_back({(folder / (name + ".png")).string(), datasets::OutputKind::kPng});
    for (const std::string& name : worlds)
      outputs.push_back({(folder / ("top_" + name + ".png")).string(), datasets::OutputKind::kPng});
  }
  return outputs;
}

ComparisonTableFiles writeComparisonTableFiles(const ComparisonLayout& layout,
                                               const std::vector<analysis::ComparisonCell>& cells,
                                               const std::string& folder) {
  ComparisonTableFiles files;
  files.csv = (fs::path(folder) / "summary.csv").string();
  files.markdown = (fs::path(folder) / "summary.md").string();
  writeTableCsv(textTable(layout.study_name, cells, 10), files.csv);
  writeTableMarkdown(
      textTable(layout.study_name, cells, 4), files.markdown, "Comparison " + layout.study_name,
      std::to_string(layout.runs) + " runs: " + std::to_string(layout.worlds.size()) +
          " worlds x " + std::to_string(layout.variants.size()) + " variants x " +
          std::to_string(layout.seeds.size()) +
          " seeds; one row per world x variant; columns: datasets/SCHEMA.md, \"Comparison "
          "studies\".");
  return files;
}

ComparisonTableFiles writeComparisonTableFiles(const datasets::ComparisonStudy& comparison,
                                               const std::vector<analysis::ComparisonCell>& cells,
                                               const std::string& folder) {
  return writeComparisonTableFiles(comparisonLayout(comparison), cells, folder);
}

}  // namespace wpg::engine
