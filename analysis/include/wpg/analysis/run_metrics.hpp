#pragma once
// The metrics of one walk (`wpg analyze`, the columns of a batch's /batch/summary): velocity
// tracking (and steady-state command tracking), CoP margin to the support polygon, step feasibility and yaw-bound margins, obstacle
// clearance, ZMP error before/after the filter, QP iterations, relaxed/failed iterations and
// NMPC time. Each is defined once, with its unit, in datasets/METRICS.md; runMetricTable()
// lists them in that order with the same names.
#include <vector>

#include "wpg/analysis/zmp_error.hpp"
#include "wpg/walk_loop.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::analysis {

// NaN where a metric does not apply (no landed step, no obstacle, not replayed, no iteration).
struct RunMetrics {
  double success = 0.0;       // [1] 1 when the walk succeeded (WalkResult::success)
  double blocked = 0.0;       // [1] 1 when the walk ended blocked (WalkResult::blocked)
  double blocked_since = 0.0;   // [s] start of the blocked stretch; NaN when not blocked
  double progress_ratio = 0.0;  // [1] CoM displacement along the command / commanded distance
  double distance = 0.0;      // [m] horizontal CoM displacement, first to last sample
  double path_length = 0.0;   // [m] length of the horizontal CoM path
  double steps = 0.0;         // [1] landed footsteps (initial feet not counted)
  double duration = 0.0;      // [s] covered by the samples
  double velocity_error_rms = 0.0;  // [m/s] METRICS.md: gait-cycle mean velocity vs. command
  double velocity_error_max = 0.0;  // [m/s]
  double steady_vx = 0.0;     // [m/s] command_tracking.hpp: steady robot-frame CoM velocity
  double steady_vy = 0.0;     // [m/s]
  double steady_omega = 0.0;  // [rad/s] steady heading rate
  double steady_tracking = 0.0;  // [1] largest component error / its tolerance (<= 1: tracked)
  double cop_margin_min = 0.0;      // [m] least CoP distance inside the sole / double-support hull
  double cop_margin_p05 = 0.0;      // [m] 5th percentile of that distance over the samples
  double cop_margin_median = 0.0;   // [m]
  double cop_margin_mean = 0.0;     // [m]
  double step_feasibility_margin_min = 0.0;  // [m] least landed step inside its polygon (eq. 14)
  double yaw_bound_margin_min = 0.0;         // [rad] max_step_yaw_change - largest yaw change
  double obstacle_clearance_min = 0.0;       // [m] least step-centre clearance (eq. 18-19)
  double swing_speed_max = 0.0;         // [m/s] swing foot's peak speed (central differences)
  double swing_acceleration_max = 0.0;  // [m/s^2] its peak acceleration
  double zmp_error_rms_before = 0.0;  // [m] multibody ZMP vs. CoP, before the filter
  double zmp_error_max_before = 0.0;
  double zmp_error_rms_after = 0.0;   // [m] after the filter (NaN when it did not run)
  double zmp_error_max_after = 0.0;
  double nmpc_iterations = 0.0;      // [1]
  double qp_iterations_mean = 0.0;   // [1] per NMPC iteration
  double qp_iterations_max = 0.0;    // [1]
  double qp_iterations_total = 0.0;  // [1]
  double relaxed_iterations = 0.0;   // [1] statuses relaxed_obstacle/kinematics/balance
  double failed_iterations = 0.0;    // [1] statuses fallback, iteration_limit, fallen, not_converged
  double nmpc_time_mean = 0.0;       // [s] wall time per NMPC iteration (mpc/solve_time)
  double nmpc_time_std = 0.0;        // [s] sample standard deviation
  double nmpc_time_min = 0.0;
  double nmpc_time_max = 0.0;
  double nmpc_time_p99 = 0.0;        // [s] 99th percentile
};

// What the velocity metrics measure the CoM's velocity against (datasets/METRICS.md).
enum class VelocityReference {
  kSchedule,           // the request's `reference` schedule at each sample's time
  kIterationCommands,  // each NMPC iteration's command (MpcIterationLog::command): a goal walk
};

// The metrics of `walk` (its trajectory, and its verdicts success and blocked). `zmp_error`
// may be null (the walk was not replayed: the four ZMP metrics are NaN). `reference`:
// kIterationCommands for a walk to a goal (its request has no schedule; NaN velocity metrics
// when its commands are not known), else kSchedule.
RunMetrics computeRunMetrics(const WalkingParameters& walking, const WalkRequest& request,
                             const WalkResult& walk, const ZmpErrorComparison* zmp_error,
                             VelocityReference reference = VelocityReference::kSchedule);

// One row per metric: its name (the key in JSON, the column in tables), unit, whether it is a
// count, whether it is a wall time (differs from run to run of the same input), and the field.
struct MetricDefinition {
  const char* name;
  const char* unit;
  bool integer;
  bool wall_time;
  double RunMetrics::*field;
};
const std::vector<MetricDefinition>& runMetricTable();

// The q-quantile (0 <= q <= 1) of `values` with linear interpolation between the order
// statistics at position q (n - 1) (numpy's default); NaN when `values` is empty.
double quantile(std::vector<double> values, double q);

}  // namespace wpg::analysis
