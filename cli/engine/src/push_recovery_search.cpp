// The push-recovery search of `wpg push-sweep` (push_recovery_search.hpp).
#include "wpg/engine/push_recovery_search.hpp"

#include <utility>

#include "wpg/walk_checks.hpp"
#include "wpg/walk_trajectory.hpp"

namespace wpg::engine {

const std::vector<PushDirection>& pushDirections() {
  static const std::vector<PushDirection> directions = {
      {"sagittal+", Eigen::Vector2d(1.0, 0.0)},
      {"sagittal-", Eigen::Vector2d(-1.0, 0.0)},
      {"coronal+", Eigen::Vector2d(0.0, 1.0)},
      {"coronal-", Eigen::Vector2d(0.0, -1.0)},
  };
  return directions;
}

std::vector<double> liftOffTimes(const WalkTrajectory& trajectory) {
  std::vector<double> times;
  for (std::size_t i = 1; i < trajectory.size(); ++i) {
    if (trajectory.support[i - 1] == SupportState::kDouble &&
        trajectory.support[i] != SupportState::kDouble) {
      times.push_back(trajectory.time[i]);
    }
  }
  return times;
}

datasets::Scenario withPush(const datasets::Scenario& base, double t, const Eigen::Vector2d& force,
                            double duration) {
  datasets::Scenario scenario = base;
  Push push;
  push.t = t;
  push.force = force;
  push.duration = duration;
  if (scenario.request.pushes.empty()) {
    scenario.request.pushes.push_back(push);
  } else {
    scenario.request.pushes[0] = push;  // as `--set pushes[0]=...` does
  }
  return scenario;
}

bool walkRecovers(const datasets::Scenario& scenario, double push_start,
                  const RunSettings& settings, const PushSearchSettings& limits,
                  SwingPeaks* peaks) {
  const RunResult result = runScenario(scenario, settings);
  const WalkTrajectory& trajectory = result.walk.result.trajectory;
  const WalkCheckReport& report = result.checks.walk;  // the run's checks hold the swing peaks
  if (peaks) *peaks = {report.swing_foot_speed_max, report.swing_foot_acceleration_max};
  if (result.outcome != RunOutcome::kSucceeded) return false;
  for (const MpcIterationLog& row : trajectory.mpc) {
    if (row.time >= push_start && row.status != IterationStatus::kSolved) return false;
  }
  if (limits.max_swing_speed > 0.0 && !(report.swing_foot_speed_max <= limits.max_swing_speed))
    return false;
  if (limits.max_swing_acceleration > 0.0 &&
      !(report.swing_foot_acceleration_max <= limits.max_swing_acceleration))
    return false;
  return true;
}

PushSearchResult searchLargestRecoveredForce(const std::function<bool(double force)>& recovered,
                                             const PushSearchSettings& settings) {
  PushSearchResult result;
  const auto recovers = [&](double force) {
    ++result.walks;
    return recovered(force);
  };
  // Invariant: `low` recovered (or is 0), `high` failed.
  double low = 0.0, high = settings.max_force;
  const auto bisect = [&] {
    while (high - low > settings.tolerance) {
      const double middle = 0.5 * (low + high);
      // Adjacent doubles: the bracket cannot shrink further, whatever the tolerance asked.
      if (middle <= low || middle >= high) break;
      (recovers(middle) ? low : high) = middle;
    }
  };
  if (recovers(settings.max_force)) {
    result.force = settings.max_force;
    result.at_upper_bound = true;
    return result;
  }
  bisect();
  // Each pass raises `low` by the factor, up to max_force: this ends well before the guard.
  for (int pass = 0; pass < 64; ++pass) {
    if (low <= 0.0) {  // nothing recovered: the weakest push tried (<= tolerance) failed
      result.stronger_fails = true;
      break;
    }
    const double stronger = settings.stronger_factor * low;
    if (!recovers(stronger)) {
      result.stronger_fails = true;
      break;
    }
    low = stronger;
    if (low >= settings.max_force) {  // beyond the bracket: report it as at the bound
      result.at_upper_bound = true;
      break;
    }
    high = settings.max_force;
    bisect();
  }
  result.force = low;
  return result;
}

PushSearchResult searchLargestRecoveredPush(const datasets::Scenario& base, double t,
                                            const Eigen::Vector2d& unit,
                                            const PushSearchSettings& settings,
                                            const RunSettings& run_settings) {
  // The peaks of every recovered walk, to report those of the force found.
  std::vector<std::pair<double, SwingPeaks>> recovered;
  PushSearchResult result = searchLargestRecoveredForce(
      [&](double force) {
        SwingPeaks peaks;
        const bool ok = walkRecovers(withPush(base, t, force * unit, settings.duration), t,
                                     run_settings, settings, &peaks);
        if (ok) recovered.emplace_back(force, peaks);
        return ok;
      },
      settings);
  for (const auto& [force, peaks] : recovered)
    if (force == result.force) result.swing = peaks;
  return result;
}

}  // namespace wpg::engine
