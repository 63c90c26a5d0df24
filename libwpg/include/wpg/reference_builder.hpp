#pragma once
// The references of the NMPC cost for one sample (paper eq. 5-8): J1's world-frame velocity
// per horizon sample (and the walked part of its windowed mean velocity), J2's yaw per
// previewed step. It keeps what they need from the past: the command's heading (the integral
// of the commanded omega, heading_reference: command) and the CoM velocities of the last
// velocity_window_samples - 1 samples.
#include <Eigen/Core>

#include "wpg/nmpc.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

class ReferenceBuilder {
 public:
  explicit ReferenceBuilder(const WalkingParameters& parameters);

  // Heading `yaw` [rad], no walked velocities.
  void reset(double yaw);
  // The command's heading: restarted from the feet's mean yaw when a walk starts ...
  void restartHeading(double yaw) { commanded_heading_ = yaw; }
  // ... then the commanded omega [rad/s] held for `elapsed` [s].
  void integrateHeading(double omega, double elapsed) { commanded_heading_ += omega * elapsed; }
  double commandedHeading() const { return commanded_heading_; }

  // Writes problem.yaw_reference, velocity_x/y and velocity_past_x/y for the clamped
  // robot-frame `command`, with problem.phase already filled for this sample (its fixed steps
  // keep their yaw). `phase_sample` is the gait's phase time, `feet_mean_yaw` the free-flyer
  // yaw of the feet on the ground, `com_velocity` the CoM's (x', y') at this sample, which
  // enters the walked part of the windowed velocity. Does not allocate.
  void build(const Eigen::Vector3d& command, int phase_sample, double feet_mean_yaw,
             const Eigen::Vector2d& com_velocity, NmpcProblem& problem);

 private:
  WalkingParameters parameters_;
  // The command's heading at the current sample (heading_reference: command): the feet's
  // mean yaw when the walk started plus the integral of the commanded omega since.
  double commanded_heading_ = 0.0;
  // CoM velocities (x; y) at the current and previous samples, newest first: the walked part
  // of J1's windowed velocity (velocity_window_samples - 1 columns).
  Eigen::Matrix<double, 2, Eigen::Dynamic> velocity_history_;
};

}  // namespace wpg
