// The table of a comparison study (wpg/analysis/comparison_summary.hpp).
#include "wpg/analysis/comparison_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "wpg/analysis/run_metrics.hpp"

namespace wpg::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> finite(const std::vector<double>& values) {
  std::vector<double> kept;
  for (const double value : values) {
    if (std::isfinite(value)) kept.push_back(value);
  }
  return kept;
}

}  // namespace

ComparisonCell summarizeComparisonCell(const std::string& world, const std::string& variant,
                                       const std::vector<ComparisonRunSample>& runs) {
  ComparisonCell cell;
  cell.world = world;
  cell.variant = variant;
  cell.runs = static_cast<double>(runs.size());
  std::vector<double> times, walked, routes, steps, replans, planning, solve;
  double clearance = kNaN;
  for (const ComparisonRunSample& run : runs) {
    cell.reached += run.goal_reached ? 1.0 : 0.0;
    cell.blocked += run.blocked ? 1.0 : 0.0;
    if (run.goal_reached) times.push_back(run.time_to_goal);
    walked.push_back(run.walked_length);
    routes.push_back(run.route_length);
    steps.push_back(run.steps);
    replans.push_back(run.replans);
    if (std::isfinite(run.clearance_min)) {
      cell.margin_entered += run.clearance_min < -kMarginTolerance ? 1.0 : 0.0;
      clearance = std::isfinite(clearance) ? std::min(clearance, run.clearance_min)
                                           : run.clearance_min;
    }
    planning.insert(planning.end(), run.planning_times.begin(), run.planning_times.end());
    solve.insert(solve.end(), run.nmpc_solve_times.begin(), run.nmpc_solve_times.end());
  }
  cell.success_rate = runs.empty() ? kNaN : cell.reached / cell.runs;
  times = finite(times);
  cell.time_to_goal_median = quantile(times, 0.5);
  cell.time_to_goal_q1 = quantile(times, 0.25);
  cell.time_to_goal_q3 = quantile(times, 0.75);
  cell.walked_length_median = quantile(finite(walked), 0.5);
  cell.route_length_median = quantile(finite(routes), 0.5);
  cell.steps_median = quantile(steps, 0.5);
  cell.clearance_min = clearance;
  double replan_sum = 0.0, replan_max = 0.0;
  for (const double count : replans) {
    replan_sum += count;
    replan_max = std::max(replan_max, count);
  }
  cell.replans_mean = replans.empty() ? kNaN : replan_sum / static_cast<double>(replans.size());
  cell.replans_max = replans.empty() ? kNaN : replan_max;
  cell.planning_time_median = quantile(planning, 0.5);
  cell.planning_time_max =
      planning.empty() ? kNaN : *std::max_element(planning.begin(), planning.end());
  cell.nmpc_time_median = quantile(solve, 0.5);
  cell.nmpc_time_p99 = quantile(solve, 0.99);
  return cell;
}

const std::vector<ComparisonColumn>& comparisonColumns() {
  static const std::vector<ComparisonColumn> columns = {
      {"runs", "1", false, &ComparisonCell::runs},
      {"reached", "1", false, &ComparisonCell::reached},
      {"success_rate", "1", false, &ComparisonCell::success_rate},
      {"blocked", "1", false, &ComparisonCell::blocked},
      {"margin_entered", "1", false, &ComparisonCell::margin_entered},
      {"time_to_goal_median", "s", false, &ComparisonCell::time_to_goal_median},
      {"time_to_goal_q1", "s", false, &ComparisonCell::time_to_goal_q1},
      {"time_to_goal_q3", "s", false, &ComparisonCell::time_to_goal_q3},
      {"walked_length_median", "m", false, &ComparisonCell::walked_length_median},
      {"route_length_median", "m", false, &ComparisonCell::route_length_median},
      {"steps_median", "1", false, &ComparisonCell::steps_median},
      {"clearance_min", "m", false, &ComparisonCell::clearance_min},
      {"replans_mean", "1", false, &ComparisonCell::replans_mean},
      {"replans_max", "1", false, &ComparisonCell::replans_max},
      {"planning_time_median", "s", true, &ComparisonCell::planning_time_median},
      {"planning_time_max", "s", true, &ComparisonCell::planning_time_max},
      {"nmpc_time_median", "s", true, &ComparisonCell::nmpc_time_median},
      {"nmpc_time_p99", "s", true, &ComparisonCell::nmpc_time_p99},
  };
  return columns;
}

}  // namespace wpg::analysis
