#pragma once
// The references of the NMPC cost for one sample (paper eq. 5-8): J1's world-frame velocity
// per horizon sample (and the walked part of its windowed mean velocity), J2's yaw per
// previewed step. It keeps what they need from the past: the command's heading (the integral
// of the commanded omega, heading_reference: command) and, for J1's window and sway
// (velocity_tracking), the CoM velocities of the last samples with the commands and headings
// they were planned for.
#include <Eigen/Core>

#include "wpg/nmpc.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

class ReferenceBuilder {
 public:
  explicit ReferenceBuilder(const WalkingParameters& parameters);

  // The steps from here on have the timing of `cadence` (walking.step_timing: adaptive;
  // WalkingParameters::withSingleSupport of the constructor's, whose horizon is at most
  // theirs): J2's turn per step and J1's gait cycle follow it. The sway restarts as after
  // standing: the cycle before a change of cadence is no sway to repeat. Does not allocate.
  void setCadence(const WalkingParameters& cadence);

  // Heading `yaw` [rad], no walked velocities.
  void reset(double yaw);
  // J1's window and sway start afresh: called while the robot stands or starts (a standing
  // robot has no sway to average, and the weight shift of a start is none to repeat).
  void forgetWalkedSamples();
  // The command's heading: restarted from the feet's mean yaw when a walk starts ...
  void restartHeading(double yaw) { commanded_heading_ = yaw; }
  // ... then the commanded omega [rad/s] held for `elapsed` [s].
  void integrateHeading(double omega, double elapsed) { commanded_heading_ += omega * elapsed; }
  double commandedHeading() const { return commanded_heading_; }
  // cos and sin of the heading h_j of every previewed sample at the last build (the one that
  // turns the robot-frame command into J1's world reference).
  const Eigen::VectorXd& headingCos() const { return heading_cos_; }
  const Eigen::VectorXd& headingSin() const { return heading_sin_; }
  // The heading the last build() turned the command into the world by at its sample: the
  // command's heading (heading_reference: command) or the feet's mean yaw (support_foot).
  double commandFrameHeading() const { return command_frame_heading_; }

  // Writes problem.yaw_reference, velocity_x/y (with a window: R(h_j) times the window's mean
  // of the command, plus the sway) and velocity_past_x/y for the clamped
  // robot-frame `command`, with problem.phase already filled for this sample (its fixed steps
  // keep their yaw). `phase_sample` is the gait's phase time, `feet_mean_yaw` the free-flyer
  // yaw of the feet on the ground, `com_velocity` the CoM's (x', y') at this sample, which
  // enters the walked part of the windowed velocity, `planned_velocity_x/y` the CoM velocities
  // at the horizon's samples of the previous sample's plan (the warm start), at which a
  // window's turn is taken. Does not allocate.
  void build(const Eigen::Vector3d& command, int phase_sample, double feet_mean_yaw,
             const Eigen::Vector2d& com_velocity,
             const Eigen::Ref<const Eigen::VectorXd>& planned_velocity_x,
             const Eigen::Ref<const Eigen::VectorXd>& planned_velocity_y, NmpcProblem& problem);
  // Adds the sway (velocity_tracking: with_sway) of the last build to velocity_x/y: a
  // separate call, so that the generator may turn the command's part along an obstacle's
  // border first (obstacle_linearization: command_tangent) and the sway stays as walked.
  void addSway(NmpcProblem& problem) const;

 private:
  WalkingParameters parameters_;
  // The command's heading at the current sample (heading_reference: command): the feet's
  // mean yaw when the walk started plus the integral of the commanded omega since.
  double commanded_heading_ = 0.0;
  double command_frame_heading_ = 0.0;  // commandFrameHeading()
  // The walked samples of J1's window and sway, newest first: rows 0-1 the CoM velocity
  // (x', y') at that sample, 2-3 the robot-frame command (vx, vy), 4 the heading h its
  // reference was turned by when it was planned, and 5-6 the CoM velocity in that frame,
  // R(h)^T (x', y'): it never changes once walked, so it is turned once, when the sample
  // enters the history, not at every build it stays in (31 samples with the sway).
  static constexpr int kHistoryRows = 7;
  Eigen::Matrix<double, kHistoryRows, Eigen::Dynamic> history_;
  int walked_samples_ = 0;  // columns of history_ walked since forgetWalkedSamples()
  // Scratch of a build: the cosine and sine of each previewed sample's heading h_j (each turns
  // the previous plan's velocity into the robot's frame, the reference and the sway into the
  // world's), and the lateral robot-frame velocity of the previous plan's samples.
  Eigen::VectorXd heading_cos_, heading_sin_;
  Eigen::VectorXd planned_robot_velocity_y_;
  // J1's world-frame sway per previewed sample (addSway), zero without it.
  Eigen::Matrix2Xd sway_;
  // The command and heading of the first previewed sample at the last build: those the next
  // sample's CoM velocity was planned for.
  Eigen::Vector2d pending_command_ = Eigen::Vector2d::Zero();
  double pending_heading_ = 0.0;
};

}  // namespace wpg
