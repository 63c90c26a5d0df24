#pragma once
// Physical invariants of a finished walk, measured on its trajectory alone (what a dataset
// holds): the CoP inside the support polygon, steps inside the feasibility polygon (eq. 14),
// yaw changes within the bound (eq. 16), and the speed actually achieved.
#include <Eigen/Core>

#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

struct WalkCheckReport {
  // CoP at the NMPC samples vs. the margin-reduced polygon the NMPC constrained it to (the
  // support foot's, or the hull of both feet in double support) [m]; <= 0 means inside.
  double cop_sample_violation = 0.0;
  double cop_sample_violation_time = 0.0;  // [s]
  // CoP at every control sample vs. the sole (single support) or the hull of both soles
  // (double support), without margins [m]: the excursion between NMPC samples.
  double cop_control_violation = 0.0;
  double cop_control_violation_time = 0.0;
  // Smallest distance from the CoP to the boundary of the margin-reduced polygon over all
  // control samples is not reported; the worst excursion beyond it is:
  double cop_margin_excursion = 0.0;       // [m], max over control samples, <= 0 inside
  // Steps vs. the previous step's feasibility polygon [m] (<= 0 inside), and yaw changes.
  double feasibility_violation = 0.0;
  double max_step_yaw_change = 0.0;        // [rad], largest |yaw - previous yaw|
  int landed_steps = 0;
  // Mean CoM speed along the initial heading from the second landing to the end [m/s]
  // (0 when fewer than two steps landed).
  double speed_after_two_steps = 0.0;
  // The swing foot's peaks (swingFootPeaks below): the feet's largest speed [m/s] and
  // acceleration [m/s^2], and when [s].
  double swing_foot_speed_max = 0.0;
  double swing_foot_speed_max_time = 0.0;
  double swing_foot_acceleration_max = 0.0;
  double swing_foot_acceleration_max_time = 0.0;
};

// The largest speed and acceleration of the ankles (left_foot, right_foot: x, y, z) by central
// differences at the samples i = 1..n-2: v_i = (p_{i+1} - p_{i-1}) / (t_{i+1} - t_{i-1}),
// a_i = ((p_{i+1} - p_i) / (t_{i+1} - t_i) - (p_i - p_{i-1}) / (t_i - t_{i-1})) /
// ((t_{i+1} - t_{i-1}) / 2), their norms, the larger foot's (a foot on the ground is at rest,
// so these are the swing foot's). Fills the four swing_foot_* fields of `report`.
void swingFootPeaks(const WalkTrajectory& trajectory, WalkCheckReport& report);

WalkCheckReport checkWalk(const WalkingParameters& parameters, const WalkTrajectory& trajectory);
// The footstep part of checkWalk alone (feasibility_violation, max_step_yaw_change,
// landed_steps, speed_after_two_steps; the CoP fields stay 0): what does not need a pass over
// the samples.
WalkCheckReport checkSteps(const WalkingParameters& parameters, const WalkTrajectory& trajectory);

}  // namespace wpg
