#include "wpg/reference_builder.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <Eigen/Geometry>

namespace wpg {
namespace {

Eigen::Matrix2d rotation(double angle) {
  return Eigen::Rotation2Dd(angle).toRotationMatrix();
}

// Walked samples J1 needs: K - 1 for the window of the first previewed sample and, with the
// sway, the window and the gait cycle C that end one cycle before it.
int historyLength(const WalkingParameters& w) {
  const int K = w.trackedVelocityWindow(), C = 2 * w.stepSamples();
  const bool sway = w.velocity_tracking == VelocityTracking::kWithSway;
  return std::max(K - 1, sway ? C + std::max(K, C) - 1 : 0);
}

}  // namespace

ReferenceBuilder::ReferenceBuilder(const WalkingParameters& parameters)
    : parameters_(parameters),
      history_(Eigen::Matrix<double, kHistoryRows, Eigen::Dynamic>::Zero(
          kHistoryRows, historyLength(parameters))),
      robot_velocity_(Eigen::Matrix2Xd::Zero(2, history_.cols() + parameters.horizon_length)),
      sway_(Eigen::Matrix2Xd::Zero(2, parameters.horizon_length)) {}

void ReferenceBuilder::reset(double yaw) {
  commanded_heading_ = yaw;
  forgetWalkedSamples();
  pending_command_.setZero();
  pending_heading_ = yaw;
}

void ReferenceBuilder::forgetWalkedSamples() {
  history_.setZero();
  walked_samples_ = 0;
}

void ReferenceBuilder::build(const Eigen::Vector3d& command, int phase_sample,
                             double feet_mean_yaw, const Eigen::Vector2d& com_velocity,
                             const Eigen::Ref<const Eigen::VectorXd>& planned_velocity_x,
                             const Eigen::Ref<const Eigen::VectorXd>& planned_velocity_y,
                             NmpcProblem& problem) {
  const WalkingParameters& w = parameters_;
  const PhaseStructure& phase = problem.phase;
  const int nf = static_cast<int>(problem.yaw_reference.size());
  const int horizon = static_cast<int>(problem.velocity_x.size());
  assert(phase.step_fixed.size() == nf && problem.velocity_past_x.size() == horizon &&
         planned_velocity_x.size() == horizon && planned_velocity_y.size() == horizon);

  // J2 references: each step turns by T_step * omega from the one before (eq. 8's p^theta),
  // from the support foot's yaw (paper) or from the command's heading (heading_reference:
  // command; fixed steps stay where they are). With the command's heading a step's yaw is the
  // heading at the middle of its time on the ground (its landing + half of single support
  // and two double supports): the robot's yaw, the mean of the feet's, then follows the
  // commanded heading on average instead of lagging it by omega times that half (0.09 rad at
  // 0.2 rad/s for HRP-2's steps), and the command is walked in the robot's frame, not askew.
  const bool command_heading = w.heading_reference == HeadingReference::kCommand;
  const double stance_middle =
      0.5 * (w.single_support_samples + 2 * w.double_support_samples) * w.sampling_period;
  double previous_yaw =
      command_heading
          ? commanded_heading_ + (stance_middle - phase_sample * w.sampling_period) * command.z()
          : phase.support_pose.z();
  for (int i = 0; i < nf; ++i) {
    const double next = previous_yaw + w.stepDuration() * command.z();
    problem.yaw_reference(i) = phase.step_fixed(i) ? phase.fixed_step_pose(2, i) : next;
    previous_yaw = command_heading ? next : problem.yaw_reference(i);
  }

  // J1 references: the command turned into the world frame along the heading h_j the robot
  // will have at each sample if it follows omega: from the feet's mean yaw (the free-flyer
  // yaw; paper) or from the command's heading.
  const double heading = command_heading ? commanded_heading_ : feet_mean_yaw;
  const auto sample_heading = [&](int j) {
    return heading + command.z() * (j + 1) * w.sampling_period;
  };
  const Eigen::Vector2d v = command.head<2>();

  // The walked samples (newest first): the current sample's CoM velocity, with the command
  // and heading it was planned for at the previous sample, then the ones before.
  const int history = static_cast<int>(history_.cols());
  for (int i = history - 1; i > 0; --i) history_.col(i) = history_.col(i - 1);
  if (history > 0) history_.col(0) << com_velocity, pending_command_, pending_heading_;
  walked_samples_ = std::min(walked_samples_ + 1, history);
  pending_command_ = v;
  pending_heading_ = sample_heading(0);

  const int K = w.trackedVelocityWindow();
  const bool sway = w.velocity_tracking == VelocityTracking::kWithSway;
  sway_.setZero();
  if (K == 1 && !sway) {  // the paper's instantaneous velocity, eq. (5)
    for (int j = 0; j < horizon; ++j) {
      const Eigen::Vector2d reference = rotation(sample_heading(j)) * v;
      problem.velocity_x(j) = reference.x();
      problem.velocity_y(j) = reference.y();
    }
    problem.velocity_past_x.setZero();
    problem.velocity_past_y.setZero();
    return;
  }

  // Robot-frame velocities u_i = R(h_i)^T c'_i, column history - 1 - m for the walked sample
  // m (oldest first), then the previewed samples of the previous plan.
  for (int m = 0; m < history; ++m) {
    robot_velocity_.col(history - 1 - m) =
        rotation(history_(4, m)).transpose() * history_.block<2, 1>(0, m);
  }
  for (int i = 0; i < horizon; ++i) {
    const Eigen::Vector2d planned(planned_velocity_x(i), planned_velocity_y(i));
    robot_velocity_.col(history + i) = rotation(sample_heading(i)).transpose() * planned;
  }
  const auto robot_mean_y = [&](int last, int count) {  // sample index: -1 = newest walked
    double sum = 0.0;  // the samples before the oldest walked one count as 0
    for (int i = std::max(last - count + 1, -history); i <= last; ++i)
      sum += robot_velocity_(1, history + i);
    return sum / count;
  };

  // Window K: J1 tracks the mean over the K samples i ending at j of the velocity error in
  // the robot's frame, (1/K) sum_i (R(h_i)^T c'_i - v_i), turned by R(h_j) into the world:
  //   (1/K) sum_i R(h_j - h_i) c'_i  -  R(h_j) (1/K) sum_i v_i.
  // Over whole steps the CoM's sway cancels in the robot's frame, not in the world's when the
  // robot turns (the sway turns with it). The Hessian keeps the mean of the unturned
  // velocities, the same for every command: the turns (R - I) of the previewed velocities are
  // taken at the previous sample's plan (`planned_velocity`), those of the walked ones exact.
  const int C = 2 * w.stepSamples();
  const double window = K;
  for (int j = 0; j < horizon; ++j) {
    const double h_j = sample_heading(j);
    Eigen::Vector2d walked = Eigen::Vector2d::Zero(), commands = Eigen::Vector2d::Zero();
    for (int m = 0; m < K - 1 - j; ++m) {
      walked += rotation(h_j - history_(4, m)) * history_.block<2, 1>(0, m);
      commands += history_.block<2, 1>(2, m);
    }
    for (int i = std::max(0, j + 1 - K); i <= j; ++i) {
      const Eigen::Vector2d planned(planned_velocity_x(i), planned_velocity_y(i));
      walked += (rotation(h_j - sample_heading(i)) - Eigen::Matrix2d::Identity()) * planned;
      commands += v;
    }
    const Eigen::Vector2d reference = rotation(h_j) * commands / window;
    Eigen::Vector2d lateral = Eigen::Vector2d::Zero();
    // The sway: the left and right steps carry the CoM to alternate sides, so the window's
    // lateral mean alternates about the cycle's mean; the target takes that alternation as the
    // robot walked it one gait cycle C earlier (a periodic gait repeats it), so that only the
    // cycle's mean and changes of the sway are charged. Not before that cycle was walked
    // (forgetWalkedSamples: the start's weight shift is no sway to repeat).
    if (sway && walked_samples_ == history)
      lateral.y() = robot_mean_y(j - C, K) - robot_mean_y(j - C, C);
    sway_.col(j) = rotation(h_j) * lateral;
    problem.velocity_past_x(j) = walked.x() / window;
    problem.velocity_past_y(j) = walked.y() / window;
    problem.velocity_x(j) = reference.x();
    problem.velocity_y(j) = reference.y();
  }
}

void ReferenceBuilder::addSway(NmpcProblem& problem) const {
  if (parameters_.velocity_tracking != VelocityTracking::kWithSway) return;
  problem.velocity_x += sway_.row(0).transpose();
  problem.velocity_y += sway_.row(1).transpose();
}

}  // namespace wpg
