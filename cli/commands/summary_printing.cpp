// The summary lines of `wpg run` and `wpg replay` (summary_printing.hpp).
#include "summary_printing.hpp"

#include <cstdio>
#include <iostream>
#include <ostream>

#include "analysis_scripts.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "wpg/analysis/chain_timing.hpp"
#include "wpg/analysis/comparison_summary.hpp"
#include "wpg/analysis/zmp_error.hpp"

namespace wpg::cli {

std::string fixed(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
  std::string text = buffer;
  // A small negative value (a clearance of -1e-16 m) prints as "-0.000": zero has no sign here.
  if (!text.empty() && text.front() == '-' &&
      text.find_first_not_of("0.", 1) == std::string::npos) {
    text.erase(0, 1);
  }
  return text;
}

std::string clearanceText(double value, int digits) {
  std::string text = fixed(value, digits);
  if (value < -analysis::kMarginTolerance && text.front() != '-') {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2g", value);
    text = buffer;
  }
  return text;
}

void printRunSummary(std::ostream& out, const datasets::Scenario& scenario,
                     const analysis::RunSummary& summary) {
  std::string statuses;
  for (const analysis::StatusCount& entry : summary.status_counts) {
    statuses += (statuses.empty() ? "" : ", ") + std::to_string(entry.count) + " " +
                iterationStatusName(entry.status);
  }
  out << "scenario  " << scenario.name << " (" << scenario.source_path << "), robot "
      << scenario.robot << ", " << generatorAlgorithmName(scenario.request.generator.algorithm)
      << '\n';
  out << "walked    " << fixed(summary.path_length, 3) << " m along the CoM path, "
      << fixed(summary.displacement, 3) << " m net displacement, " << summary.steps
      << " steps in " << fixed(summary.duration, 2) << " s\n";
  out << "status    " << (statuses.empty() ? std::string("no NMPC iterations") : statuses) << " ("
      << summary.nmpc_iterations << " NMPC iterations)\n";
  if (summary.nmpc_iterations > 0) {
    out << "solve     median " << fixed(1e6 * summary.median_solve_time, 0) << " us, max "
        << fixed(1e6 * summary.max_solve_time, 0) << " us per NMPC iteration\n";
  }
}

void printObstacleClearances(std::ostream& out, const engine::ObstacleClearances& clearances) {
  out << "obstacles " << clearances.obstacle_count
      << "; least clearance: step centre to " << clearances.step_centre_bound
      << " (the NMPC's constraint) "
      << clearanceText(clearances.step_centre, 3) << " m, sole to margin "
      << clearanceText(clearances.sole, 3) << " m; sole to obstacle "
      << clearanceText(clearances.sole_to_obstacle, 3) << " m\n";
}

void printGoalSummary(std::ostream& out, const engine::WalkOutcome& walk) {
  const datasets::GoalOutcome& goal = *walk.goal;
  out << "goal      ";
  if (goal.goal_reached) {
    out << "reached in " << fixed(goal.time_to_goal, 1) << " s";
  } else {
    out << "not reached (" << goal.outcome << ")";
  }
  out << ", route " << fixed(walk.route_length, 1) << " m, " << walk.replans
      << (walk.replans == 1 ? " replan" : " replans") << ", planning "
      << fixed(1e3 * walk.planning_time, walk.planning_time < 0.01 ? 1 : 0) << " ms\n";
}

void printMultibodySummary(std::ostream& out, const engine::ReplayOutcome& outcome) {
  const MultibodyValidation& v = outcome.validation;
  const analysis::ZmpErrorComparison zmp = analysis::compareZmpError(v);
  if (zmp.filtered) {
    out << "multibody ZMP error  RMS " << fixed(1e3 * zmp.before.rms, 1) << " mm -> "
        << fixed(1e3 * zmp.after.rms, 1) << " mm, max " << fixed(1e3 * zmp.before.max, 1)
        << " mm -> " << fixed(1e3 * zmp.after.max, 1) << " mm (dynamic filter)\n";
  } else {
    out << "multibody ZMP error  RMS " << fixed(1e3 * zmp.before.rms, 1) << " mm, max "
        << fixed(1e3 * zmp.before.max, 1) << " mm (no filter)\n";
  }
  char errors[96];
  std::snprintf(errors, sizeof errors, "max error CoM %.1e m, feet %.1e m", v.max_ik_com_error,
                v.max_ik_foot_error);
  out << "IK        "
      << (v.ik_failures == 0 ? std::string("solved on every sample")
                             : std::to_string(v.ik_failures) + " samples NOT solved")
      << " (" << errors << "); ";
  if (v.samples_with_limit_violations == 0) {
    out << "joint limits respected\n";
  } else {
    std::string joints;
    for (const std::string& joint : v.violated_joints) joints += (joints.empty() ? "" : ", ") + joint;
    out << v.samples_with_limit_violations << " samples outside joint limits (max "
        << fixed(v.max_limit_violation, 3) << " rad: " << joints << ")\n";
  }
  const analysis::ChainTiming timing = analysis::chainTiming(v);
  const analysis::SampleStatistics& chain = timing.per_iteration;
  if (chain.count > 0) {
    out << "chain     per NMPC iteration " << fixed(1e3 * chain.mean, 3) << " ms average, std "
        << fixed(1e3 * chain.std_dev, 3) << ", min " << fixed(1e3 * chain.min, 3) << ", max "
        << fixed(1e3 * chain.max, 3) << " ms; replay" << (zmp.filtered ? " + filter " : " ")
        << fixed(outcome.realTimeFactor(), 0) << "x real time\n";
  }
  const analysis::TickTiming ticks = analysis::tickTiming(v);
  if (ticks.measured && ticks.nmpc_ticks.count > 0) {
    out << "tick      with the NMPC " << fixed(1e3 * ticks.nmpc_ticks.mean, 3)
        << " ms average, max " << fixed(1e3 * ticks.nmpc_ticks.max, 3) << " ms; every tick "
        << fixed(1e3 * ticks.all_ticks.mean, 3) << " ms average (" << ticks.all_ticks.count
        << " control periods)\n";
  }
  if (!v.filter_mode.empty()) {
    out << "filter    " << v.filter_mode
        << (v.filter_mode == "online"
                ? (v.wpg_reinitialized ? " (WPG re-initialised every NMPC iteration)" : " (open loop)")
                : "");
    if (v.has_offline_comparison) {
      out << "; offline pass: RMS " << fixed(1e3 * v.offline_before.rms, 1) << " mm -> "
          << fixed(1e3 * v.offline_after.rms, 1) << " mm, max "
          << fixed(1e3 * v.offline_before.max, 1) << " mm -> "
          << fixed(1e3 * v.offline_after.max, 1) << " mm";
    }
    out << '\n';
  }
}

void reportDatasetAndFigure(const std::string& dataset_path, const std::string& figure_path,
                            bool plot) {
  std::cout << "dataset   " << dataset_path << '\n';
  if (!plot) return;
  std::cout.flush();
  if (drawFigure(dataset_path, figure_path) == kExitSuccess) {
    std::cout << "figure    " << figure_path << '\n';
  } else {
    printWarning("no figure drawn (the dataset is complete; retry with `wpg plot " +
                 dataset_path + "`)");
  }
}

}  // namespace wpg::cli
