#include "wpg/reference_builder.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace wpg {

ReferenceBuilder::ReferenceBuilder(const WalkingParameters& parameters)
    : parameters_(parameters),
      velocity_history_(Eigen::Matrix<double, 2, Eigen::Dynamic>::Zero(
          2, std::max(0, parameters.velocity_window_samples - 1))) {}

void ReferenceBuilder::reset(double yaw) {
  commanded_heading_ = yaw;
  velocity_history_.setZero();
}

void ReferenceBuilder::build(const Eigen::Vector3d& command, int phase_sample,
                             double feet_mean_yaw, const Eigen::Vector2d& com_velocity,
                             NmpcProblem& problem) {
  const WalkingParameters& w = parameters_;
  const PhaseStructure& phase = problem.phase;
  const int nf = static_cast<int>(problem.yaw_reference.size());
  const int horizon = static_cast<int>(problem.velocity_x.size());
  assert(phase.step_fixed.size() == nf && problem.velocity_past_x.size() == horizon);

  // J2 references: each step turns by T_step * omega from the one before (eq. 8's p^theta),
  // from the support foot's yaw (paper) or from the command's heading when the support foot
  // landed (heading_reference: command; fixed steps stay where they are).
  const bool command_heading = w.heading_reference == HeadingReference::kCommand;
  double previous_yaw =
      command_heading ? commanded_heading_ - phase_sample * w.sampling_period * command.z()
                      : phase.support_pose.z();
  for (int i = 0; i < nf; ++i) {
    const double next = previous_yaw + w.stepDuration() * command.z();
    problem.yaw_reference(i) = phase.step_fixed(i) ? phase.fixed_step_pose(2, i) : next;
    previous_yaw = command_heading ? next : problem.yaw_reference(i);
  }
  // J1 references: the command turned into the world frame along the heading the robot will
  // have at each sample if it follows omega: from the feet's mean yaw (the free-flyer yaw;
  // paper) or from the command's heading.
  const double heading = command_heading ? commanded_heading_ : feet_mean_yaw;
  for (int j = 0; j < horizon; ++j) {
    const double yaw = heading + command.z() * (j + 1) * w.sampling_period;
    const double c = std::cos(yaw), s = std::sin(yaw);
    problem.velocity_x(j) = c * command.x() - s * command.y();
    problem.velocity_y(j) = s * command.x() + c * command.y();
  }
  // J1's windowed velocity: the samples of each window already walked (newest first: the
  // current sample's velocity, then the ones before).
  const int history = static_cast<int>(velocity_history_.cols());
  for (int i = history - 1; i > 0; --i) velocity_history_.col(i) = velocity_history_.col(i - 1);
  if (history > 0) velocity_history_.col(0) = com_velocity;
  const double window = w.velocity_window_samples;
  for (int j = 0; j < horizon; ++j) {
    double past_x = 0.0, past_y = 0.0;
    for (int i = 0; i < history - j; ++i) {
      past_x += velocity_history_(0, i);
      past_y += velocity_history_(1, i);
    }
    problem.velocity_past_x(j) = past_x / window;
    problem.velocity_past_y(j) = past_y / window;
  }
}

}  // namespace wpg
