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

// The same matrix as rotation(angle) from its cosine and sine (Rotation2D's layout).
Eigen::Matrix2d rotation(double cos_angle, double sin_angle) {
  Eigen::Matrix2d R;
  R << cos_angle, -sin_angle, sin_angle, cos_angle;
  return R;
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
      heading_cos_(Eigen::VectorXd::Zero(parameters.horizon_length)),
      heading_sin_(Eigen::VectorXd::Zero(parameters.horizon_length)),
      planned_robot_velocity_y_(Eigen::VectorXd::Zero(parameters.horizon_length)),
      sway_(Eigen::Matrix2Xd::Zero(2, parameters.horizon_length)) {}

void ReferenceBuilder::setCadence(const WalkingParameters& cadence) {
  assert(historyLength(cadence) <= history_.cols() && cadence.horizon_length <= sway_.cols());
  parameters_ = cadence;
  forgetWalkedSamples();
}

void ReferenceBuilder::reset(double yaw) {
  commanded_heading_ = yaw;
  command_frame_heading_ = yaw;
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
  command_frame_heading_ = heading;
  const auto sample_heading = [&](int j) {
    return heading + command.z() * (j + 1) * w.sampling_period;
  };
  const Eigen::Vector2d v = command.head<2>();
  // R(h_j) of every previewed sample, from one cosine and sine each: the previous plan's
  // velocity, the reference and the sway are turned by the same heading.
  for (int j = 0; j < horizon; ++j) {
    const double h_j = sample_heading(j);
    heading_cos_(j) = std::cos(h_j);
    heading_sin_(j) = std::sin(h_j);
  }

  // The walked samples (newest first): the current sample's CoM velocity, with the command
  // and heading it was planned for at the previous sample, then the ones before.
  const int history = static_cast<int>(history_.cols());
  for (int i = history - 1; i > 0; --i) history_.col(i) = history_.col(i - 1);
  if (history > 0) {
    history_.col(0) << com_velocity, pending_command_, pending_heading_,
        rotation(pending_heading_).transpose() * com_velocity;
  }
  walked_samples_ = std::min(walked_samples_ + 1, history);
  pending_command_ = v;
  pending_heading_ = sample_heading(0);

  const int K = w.trackedVelocityWindow();
  const bool sway = w.velocity_tracking == VelocityTracking::kWithSway;
  sway_.setZero();
  if (K == 1 && !sway) {  // the paper's instantaneous velocity, eq. (5)
    for (int j = 0; j < horizon; ++j) {
      const Eigen::Vector2d reference = rotation(heading_cos_(j), heading_sin_(j)) * v;
      problem.velocity_x(j) = reference.x();
      problem.velocity_y(j) = reference.y();
    }
    problem.velocity_past_x.setZero();
    problem.velocity_past_y.setZero();
    return;
  }

  // Robot-frame velocities u_i = R(h_i)^T c'_i: of the walked samples in history_ (rows 5-6),
  // of the previewed samples of the previous plan here.
  for (int i = 0; i < horizon; ++i) {
    const Eigen::Vector2d planned(planned_velocity_x(i), planned_velocity_y(i));
    planned_robot_velocity_y_(i) =
        (rotation(heading_cos_(i), heading_sin_(i)).transpose() * planned).y();
  }
  const auto robot_mean_y = [&](int last, int count) {  // sample index: -1 = newest walked
    double sum = 0.0;  // the samples before the oldest walked one count as 0
    for (int i = std::max(last - count + 1, -history); i <= last; ++i)
      sum += i < 0 ? history_(6, -1 - i) : planned_robot_velocity_y_(i);
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
    const Eigen::Matrix2d turn_j = rotation(heading_cos_(j), heading_sin_(j));  // R(h_j)
    Eigen::Vector2d walked = Eigen::Vector2d::Zero(), commands = Eigen::Vector2d::Zero();
    for (int m = 0; m < K - 1 - j; ++m) {
      walked += rotation(h_j - history_(4, m)) * history_.block<2, 1>(0, m);
      commands += history_.block<2, 1>(2, m);
    }
    for (int i = std::max(0, j + 1 - K); i <= j; ++i) {
      commands += v;
      // No turn (i = j, or a straight walk): R - I = 0 adds zeros, the sum stays as it is.
      const double turn = h_j - sample_heading(i);
      if (turn == 0.0) continue;
      const Eigen::Vector2d planned(planned_velocity_x(i), planned_velocity_y(i));
      walked += (rotation(turn) - Eigen::Matrix2d::Identity()) * planned;
    }
    const Eigen::Vector2d reference = turn_j * commands / window;
    Eigen::Vector2d lateral = Eigen::Vector2d::Zero();
    // The sway: the left and right steps carry the CoM to alternate sides, so the window's
    // lateral mean alternates about the cycle's mean; the target takes that alternation as the
    // robot walked it one gait cycle C earlier (a periodic gait repeats it), so that only the
    // cycle's mean and changes of the sway are charged. Not before that cycle was walked
    // (forgetWalkedSamples: the start's weight shift is no sway to repeat; nor is the cycle
    // before a change of step timing, setCadence).
    if (sway && walked_samples_ >= historyLength(w))
      lateral.y() = robot_mean_y(j - C, K) - robot_mean_y(j - C, C);
    sway_.col(j) = turn_j * lateral;
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
