// The metrics of one walk (run_metrics.hpp; definitions: datasets/METRICS.md).
#include "wpg/analysis/run_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "wpg/analysis/command_tracking.hpp"
#include "wpg/analysis/run_summary.hpp"
#include "wpg/analysis/sample_statistics.hpp"
#include "wpg/obstacles.hpp"
#include "wpg/progress_monitor.hpp"
#include "wpg/support_polygon.hpp"
#include "wpg/walk_checks.hpp"

namespace wpg::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The robot-frame command in force at each sample: the request's schedule at the sample's
// time, or the command of the last NMPC iteration that started at or before it (a walk to a
// goal: the path follower's). False when a command is not known (NaN).
bool commandsAtSamples(const WalkRequest& request, const WalkTrajectory& tr,
                       VelocityReference source, std::vector<Eigen::Vector3d>* commands) {
  const std::size_t n = tr.size();
  commands->resize(n);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (source == VelocityReference::kSchedule) {
      (*commands)[i] = request.commandAt(tr.time[i]);
      continue;
    }
    while (k + 1 < tr.mpc.size() && tr.mpc[k + 1].time <= tr.time[i] + 1e-9) ++k;
    if (tr.mpc.empty() || !tr.mpc[k].command.allFinite()) return false;
    (*commands)[i] = tr.mpc[k].command;
  }
  return true;
}

// Velocity tracking over one gait cycle W (two steps): the CoM's mean velocity over the last W,
// (c(t) - c(t - W)) / W, against the mean over the same samples of the command turned into
// the world by the free-flyer yaw. Averaging over a cycle removes the lateral sway. The start
// is left out: the windows that begin within one cycle of the first command that is not zero
// (the CoM needs about a cycle to reach the commanded speed from rest: an error that grew with
// the speed, 0.076 m/s median RMS at 0.3 m/s in speeds_weights_heights.yaml against 0.017
// without the start, and said nothing of the tracking).
void velocityError(const WalkingParameters& w, const WalkRequest& request,
                   const WalkTrajectory& tr, VelocityReference source, RunMetrics* metrics) {
  const std::size_t n = tr.size();
  const std::size_t window =
      static_cast<std::size_t>(std::lround(2.0 * w.stepDuration() / w.control_period));
  metrics->velocity_error_rms = kNaN;
  metrics->velocity_error_max = kNaN;
  if (window == 0 || n <= window) return;
  std::vector<Eigen::Vector3d> commands;
  if (!commandsAtSamples(request, tr, source, &commands)) return;
  // The first sample whose command is not zero (the first sample when none is): windows
  // begin `window` samples after it or later.
  std::size_t moving = 0;
  while (moving < n && (commands[moving].array() == 0.0).all()) ++moving;
  if (moving == n) moving = 0;
  const std::size_t first = moving + 2 * window;  // the first window's end
  if (first >= n) return;
  std::vector<Eigen::Vector2d> reference(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& command = commands[i];
    const double c = std::cos(tr.free_flyer_yaw[i]), s = std::sin(tr.free_flyer_yaw[i]);
    reference[i] = Eigen::Vector2d(c * command.x() - s * command.y(),
                                   s * command.x() + c * command.y());
  }
  Eigen::Vector2d reference_sum = Eigen::Vector2d::Zero();
  for (std::size_t i = first - window + 1; i <= first; ++i) reference_sum += reference[i];
  double squares = 0.0, largest = 0.0;
  std::size_t count = 0;
  for (std::size_t i = first; i < n; ++i) {
    if (i > first) reference_sum += reference[i] - reference[i - window];
    const double elapsed = tr.time[i] - tr.time[i - window];
    const Eigen::Vector2d mean_velocity = (tr.com[i] - tr.com[i - window]).head<2>() / elapsed;
    const double error = (mean_velocity - reference_sum / static_cast<double>(window)).norm();
    squares += error * error;
    largest = std::max(largest, error);
    ++count;
  }
  metrics->velocity_error_rms = std::sqrt(squares / static_cast<double>(count));
  metrics->velocity_error_max = largest;
}

void copMargin(const WalkingParameters& w, const WalkTrajectory& tr, RunMetrics* metrics) {
  std::vector<double> margins;
  margins.reserve(tr.size());
  double sum = 0.0;
  SupportPolygonCache polygon;  // built once per support phase
  for (std::size_t i = 0; i < tr.size(); ++i) {
    // violation() is minus the distance to the nearest edge inside a convex polygon
    // The support polygon without security margins: the sole in single support, the hull of
    // both soles in double support (the polygon of checkWalk's cop_control_violation).
    const double margin = -polygon.violation(tr.cop[i], tr.support[i], tr.left_foot[i],
                                             tr.right_foot[i], w.foot_length, w.foot_width);
    margins.push_back(margin);
    sum += margin;
  }
  metrics->cop_margin_min = margins.empty() ? kNaN : *std::min_element(margins.begin(), margins.end());
  metrics->cop_margin_mean = margins.empty() ? kNaN : sum / static_cast<double>(margins.size());
  metrics->cop_margin_p05 = quantile(margins, 0.05);
  metrics->cop_margin_median = quantile(std::move(margins), 0.5);
}

// The landed steps against the last footstep of the other side (eq. 14, eq. 16): checkWalk's
// worst excursions, as margins.
void stepMargins(const WalkingParameters& w, const WalkTrajectory& tr, RunMetrics* metrics) {
  const WalkCheckReport report = checkSteps(w, tr);
  const bool stepped = report.landed_steps > 0;
  metrics->step_feasibility_margin_min = stepped ? -report.feasibility_violation : kNaN;
  metrics->yaw_bound_margin_min = stepped ? w.max_step_yaw_change - report.max_step_yaw_change : kNaN;
}

double obstacleClearance(const WalkingParameters& w, const WalkRequest& request,
                         const WalkTrajectory& tr) {
  if (request.obstacles.empty() || tr.footsteps.empty()) return kNaN;
  const ObstacleSet obstacles(request.obstacles);
  double least = std::numeric_limits<double>::infinity();
  for (const Footstep& step : tr.footsteps) {
    for (int i = 0; i < obstacles.obstacleCount(); ++i) {
      least = std::min(least, stepCentreClearance(obstacles, i, obstacles.obstacle(i), w,
                                                  step.pose.head<2>()));
    }
  }
  return least;
}

// The whole walk's progress along its command (METRICS.md, progress_ratio): over the NMPC
// rows with a linear command whose next sampling instant is a sample of the walk, the CoM's
// displacement to that instant along the command, over the commanded distance. The same sums,
// in the same order, as libwpg's ProgressMonitor (the run's `progress_ratio` attribute).
double progressRatio(const WalkingParameters& w, const WalkTrajectory& tr) {
  const double T = w.sampling_period;
  const long sub = std::lround(T / w.control_period);
  const long n = static_cast<long>(tr.size());
  double walked = 0.0, commanded = 0.0;
  for (const MpcIterationLog& row : tr.mpc) {
    if (!row.commanded_velocity.allFinite()) return kNaN;  // not stored (an older file)
    const long i = std::lround(row.time / w.control_period);
    if (i < 0 || i + sub > n - 1) continue;  // no period after it in the walk
    if (!(row.commanded_velocity.norm() > ProgressMonitor::kMinLinearCommand)) continue;
    const Eigen::Vector2d displacement = row.commanded_velocity * T;
    const double length = displacement.norm();
    walked += (tr.com[i + sub].head<2>() - tr.com[i].head<2>()).dot(displacement) / length;
    commanded += length;
  }
  return commanded > 0.0 ? walked / commanded : kNaN;
}

void nmpcLog(const WalkTrajectory& tr, RunMetrics* metrics) {
  const std::size_t k = tr.mpc.size();
  metrics->nmpc_iterations = static_cast<double>(k);
  Eigen::VectorXd times(static_cast<Eigen::Index>(k));
  std::vector<double> time_values;
  double qp_total = 0.0, qp_max = 0.0, relaxed = 0.0, failed = 0.0;
  for (std::size_t i = 0; i < k; ++i) {
    const MpcIterationLog& row = tr.mpc[i];
    times[static_cast<Eigen::Index>(i)] = row.solve_time;
    time_values.push_back(row.solve_time);
    qp_total += row.qp_iterations;
    qp_max = std::max(qp_max, static_cast<double>(row.qp_iterations));
    switch (row.status) {
      case IterationStatus::kRelaxedObstacle:
      case IterationStatus::kRelaxedKinematics:
      case IterationStatus::kRelaxedBalance:
        relaxed += 1.0;
        break;
      case IterationStatus::kFallback:
      case IterationStatus::kIterationLimit:
      case IterationStatus::kFallen:
      case IterationStatus::kNotConverged:
        failed += 1.0;
        break;
      case IterationStatus::kSolved:
        break;
    }
  }
  metrics->qp_iterations_total = qp_total;
  metrics->qp_iterations_max = k ? qp_max : kNaN;
  metrics->qp_iterations_mean = k ? qp_total / static_cast<double>(k) : kNaN;
  metrics->relaxed_iterations = relaxed;
  metrics->failed_iterations = failed;
  const SampleStatistics statistics = describeSample(times);
  metrics->nmpc_time_mean = k ? statistics.mean : kNaN;
  metrics->nmpc_time_std = k > 1 ? statistics.std_dev : kNaN;
  metrics->nmpc_time_min = k ? statistics.min : kNaN;
  metrics->nmpc_time_max = k ? statistics.max : kNaN;
  metrics->nmpc_time_p99 = quantile(std::move(time_values), 0.99);
}

}  // namespace

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return kNaN;
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const std::size_t below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return values[below] + fraction * (values[above] - values[below]);
}

RunMetrics computeRunMetrics(const WalkingParameters& walking, const WalkRequest& request,
                             const WalkResult& walk, const ZmpErrorComparison* zmp_error,
                             VelocityReference reference) {
  const WalkTrajectory& trajectory = walk.trajectory;
  RunMetrics metrics;
  const RunSummary summary = summarizeRun(trajectory);
  metrics.success = walk.success ? 1.0 : 0.0;
  metrics.blocked = walk.blocked ? 1.0 : 0.0;
  metrics.blocked_since = walk.blocked ? walk.blocked_since : kNaN;
  metrics.progress_ratio = progressRatio(walking, trajectory);
  metrics.distance = summary.displacement;
  metrics.path_length = summary.path_length;
  metrics.steps = static_cast<double>(summary.steps);
  metrics.duration = summary.duration;
  velocityError(walking, request, trajectory, reference, &metrics);
  const SteadyTracking steady = steadyTracking(walking, request, trajectory);
  metrics.steady_vx = steady.vx;
  metrics.steady_vy = steady.vy;
  metrics.steady_omega = steady.omega;
  metrics.steady_tracking = steady.score;
  copMargin(walking, trajectory, &metrics);
  stepMargins(walking, trajectory, &metrics);
  metrics.obstacle_clearance_min = obstacleClearance(walking, request, trajectory);
  WalkCheckReport swing;
  swingFootPeaks(trajectory, swing);
  metrics.swing_speed_max = trajectory.size() >= 3 ? swing.swing_foot_speed_max : kNaN;
  metrics.swing_acceleration_max = trajectory.size() >= 3 ? swing.swing_foot_acceleration_max : kNaN;
  metrics.zmp_error_rms_before = zmp_error ? zmp_error->before.rms : kNaN;
  metrics.zmp_error_max_before = zmp_error ? zmp_error->before.max : kNaN;
  // Absent (NaN) when the filter did not run: a copy of `before` would read as a filter that
  // changed nothing.
  const bool filtered = zmp_error && zmp_error->filtered;
  metrics.zmp_error_rms_after = filtered ? zmp_error->after.rms : kNaN;
  metrics.zmp_error_max_after = filtered ? zmp_error->after.max : kNaN;
  nmpcLog(trajectory, &metrics);
  return metrics;
}

const std::vector<MetricDefinition>& runMetricTable() {
  static const std::vector<MetricDefinition> table = {
      {"success", "1", true, false, &RunMetrics::success},
      {"blocked", "1", true, false, &RunMetrics::blocked},
      {"blocked_since", "s", false, false, &RunMetrics::blocked_since},
      {"progress_ratio", "1", false, false, &RunMetrics::progress_ratio},
      {"distance", "m", false, false, &RunMetrics::distance},
      {"path_length", "m", false, false, &RunMetrics::path_length},
      {"steps", "1", true, false, &RunMetrics::steps},
      {"duration", "s", false, false, &RunMetrics::duration},
      {"velocity_error_rms", "m/s", false, false, &RunMetrics::velocity_error_rms},
      {"velocity_error_max", "m/s", false, false, &RunMetrics::velocity_error_max},
      {"steady_vx", "m/s", false, false, &RunMetrics::steady_vx},
      {"steady_vy", "m/s", false, false, &RunMetrics::steady_vy},
      {"steady_omega", "rad/s", false, false, &RunMetrics::steady_omega},
      {"steady_tracking", "1", false, false, &RunMetrics::steady_tracking},
      {"cop_margin_min", "m", false, false, &RunMetrics::cop_margin_min},
      {"cop_margin_p05", "m", false, false, &RunMetrics::cop_margin_p05},
      {"cop_margin_median", "m", false, false, &RunMetrics::cop_margin_median},
      {"cop_margin_mean", "m", false, false, &RunMetrics::cop_margin_mean},
      {"step_feasibility_margin_min", "m", false, false, &RunMetrics::step_feasibility_margin_min},
      {"yaw_bound_margin_min", "rad", false, false, &RunMetrics::yaw_bound_margin_min},
      {"obstacle_clearance_min", "m", false, false, &RunMetrics::obstacle_clearance_min},
      {"swing_speed_max", "m/s", false, false, &RunMetrics::swing_speed_max},
      {"swing_acceleration_max", "m/s^2", false, false, &RunMetrics::swing_acceleration_max},
      {"zmp_error_rms_before", "m", false, false, &RunMetrics::zmp_error_rms_before},
      {"zmp_error_max_before", "m", false, false, &RunMetrics::zmp_error_max_before},
      {"zmp_error_rms_after", "m", false, false, &RunMetrics::zmp_error_rms_after},
      {"zmp_error_max_after", "m", false, false, &RunMetrics::zmp_error_max_after},
      {"nmpc_iterations", "1", true, false, &RunMetrics::nmpc_iterations},
      {"qp_iterations_mean", "1", false, false, &RunMetrics::qp_iterations_mean},
      {"qp_iterations_max", "1", true, false, &RunMetrics::qp_iterations_max},
      {"qp_iterations_total", "1", true, false, &RunMetrics::qp_iterations_total},
      {"relaxed_iterations", "1", true, false, &RunMetrics::relaxed_iterations},
      {"failed_iterations", "1", true, false, &RunMetrics::failed_iterations},
      {"nmpc_time_mean", "s", false, true, &RunMetrics::nmpc_time_mean},
      {"nmpc_time_std", "s", false, true, &RunMetrics::nmpc_time_std},
      {"nmpc_time_min", "s", false, true, &RunMetrics::nmpc_time_min},
      {"nmpc_time_max", "s", false, true, &RunMetrics::nmpc_time_max},
      {"nmpc_time_p99", "s", false, true, &RunMetrics::nmpc_time_p99},
  };
  return table;
}

}  // namespace wpg::analysis
