#include "wpg/pattern_generator.hpp"

#include <algorithm>
#include <utility>
#include <cmath>

namespace wpg {
namespace {

Eigen::Vector3d composePose(const Eigen::Vector3d& base, const Eigen::Vector3d& local) {
  const double c = std::cos(base.z()), s = std::sin(base.z());
  return {base.x() + c * local.x() - s * local.y(), base.y() + s * local.x() + c * local.y(),
          base.z() + local.z()};
}

bool isZeroCommand(const Eigen::Vector3d& command) { return command.cwiseAbs().maxCoeff() < 1e-9; }

}  // namespace

PatternGenerator::PatternGenerator(const WalkingParameters& parameters,
                                   const GeneratorSettings& settings)
    : model_(parameters, settings.max_obstacles_in_qp),
      settings_(settings),
      solver_(model_),
      problem_(model_.makeProblem()),
      velocity_history_(Eigen::Matrix<double, 2, Eigen::Dynamic>::Zero(
          2, std::max(0, parameters.velocity_window_samples - 1))) {
  reset();
}

void PatternGenerator::setObstacles(std::vector<Obstacle> obstacles) {
  obstacles_ = ObstacleSet(std::move(obstacles));  // validates; the only allocation
  problem_.obstacles = obstacles_.empty() ? nullptr : &obstacles_;
  obstacle_order_.assign(obstacles_.obstacleCount(), {0.0, 0});
  problem_.obstacle_slot.setConstant(-1);
}

// The obstacles that may constrain the previewed steps: the nearest ones (bounding circle
// grown by the margin) within obstacle_reach of the support foot, at most one per slot.
void PatternGenerator::selectObstacles() {
  const int slots = model_.layout().obstacle_slots;
  problem_.obstacle_slot.setConstant(-1);
  problem_.obstacles = obstacles_.empty() ? nullptr : &obstacles_;  // ours, wherever we live
  if (slots == 0 || obstacles_.empty() || standing_) return;
  const Eigen::Vector2d support = problem_.phase.support_pose.head<2>();
  int candidates = 0;
  for (int i = 0; i < obstacles_.obstacleCount(); ++i) {
    const Eigen::Vector3d& reach = obstacles_.reachCircle(i);
    const double gap = (reach.head<2>() - support).norm() - reach.z();
    if (gap < settings_.obstacle_reach) obstacle_order_[candidates++] = {gap, i};
  }
  const int kept = std::min(candidates, slots);
  std::partial_sort(obstacle_order_.begin(), obstacle_order_.begin() + kept,
                    obstacle_order_.begin() + candidates);
  for (int k = 0; k < kept; ++k) problem_.obstacle_slot(k) = obstacle_order_[k].second;
}

void PatternGenerator::reset(const Eigen::Vector3d& pose) {
  const double half = 0.5 * model_.parameters().initial_foot_separation;
  left_ = composePose(pose, {0.0, half, 0.0});
  right_ = composePose(pose, {0.0, -half, 0.0});
  com_x_ = Eigen::Vector3d(pose.x(), 0.0, 0.0);
  com_y_ = Eigen::Vector3d(pose.y(), 0.0, 0.0);
  standing_ = true;
  commanded_heading_ = pose.z();
  support_side_ = FootSide::kRight;
  phase_sample_ = 0;
  start_remaining_ = 0;
  zero_command_steps_ = 0;
  stop_step_ = false;
  structure_changed_ = true;
  solver_.plan().setZero();
  solver_.clearActiveSet();
  velocity_history_.setZero();
  plan_ = SamplePlan();
}

Eigen::Vector3d PatternGenerator::clampCommand(const Eigen::Vector3d& command) const {
  const WalkingParameters& w = model_.parameters();
  return {std::clamp(command.x(), -w.max_forward_velocity, w.max_forward_velocity),
          std::clamp(command.y(), -w.max_lateral_velocity, w.max_lateral_velocity),
          std::clamp(command.z(), -w.max_angular_velocity, w.max_angular_velocity)};
}

Eigen::Vector3d PatternGenerator::stepPose(int step) const {
  const NmpcLayout& L = model_.layout();
  const Eigen::VectorXd& U = solver_.plan();
  return {U(L.stepX() + step), U(L.stepY() + step), U(L.stepYaw() + step)};
}

void PatternGenerator::setStepPose(int step, const Eigen::Vector3d& pose) {
  const NmpcLayout& L = model_.layout();
  solver_.plan()(L.stepX() + step) = pose.x();
  solver_.plan()(L.stepY() + step) = pose.y();
  solver_.plan()(L.stepYaw() + step) = pose.z();
}

// Where a step of `side` would land from `previous` when following `command`: an initial
// guess for the linearization only (the NMPC chooses the step).
Eigen::Vector3d PatternGenerator::nominalStep(const Eigen::Vector3d& previous, FootSide side,
                                              const Eigen::Vector3d& command) const {
  const WalkingParameters& w = model_.parameters();
  const double T_step = w.stepDuration();
  const double lateral = 0.5 * (w.feasibility_y[0] + w.feasibility_y[2]);
  const double yaw = std::clamp(command.z() * T_step, -w.max_step_yaw_change, w.max_step_yaw_change);
  const double sign = side == FootSide::kLeft ? 1.0 : -1.0;
  return composePose(previous, {command.x() * T_step, sign * lateral + command.y() * T_step, yaw});
}

// Double support on parallel side-by-side feet: the hull of both margin-reduced soles is a
// rectangle about the point between the ankles.
void PatternGenerator::setDoubleSupport(PhaseStructure& phase) const {
  const WalkingParameters& w = model_.parameters();
  const Eigen::Vector3d mid = 0.5 * (left_ + right_);
  const double c = std::cos(mid.z()), s = std::sin(mid.z());
  const Eigen::Vector2d offset = (left_ - right_).head<2>();
  const double separation = std::abs(-s * offset.x() + c * offset.y());
  phase.support_pose = mid;
  phase.support_half_length = w.copHalfLength();
  phase.support_half_width = 0.5 * separation + w.copHalfWidth();
}

void PatternGenerator::buildProblem(const Eigen::Vector3d& command) {
  const WalkingParameters& w = model_.parameters();
  const NmpcLayout& L = model_.layout();
  const int S = w.stepSamples();
  const int nf = L.steps;
  PhaseStructure& phase = problem_.phase;
  if (standing_) {
    phase.pattern = model_.standingPattern();
    setDoubleSupport(phase);
    phase.first_step_side = FootSide::kLeft;
    for (int i = 0; i < nf; ++i) {
      phase.step_fixed(i) = 1;
      phase.fixed_step_pose.col(i) = phase.stepSide(i) == FootSide::kLeft ? left_ : right_;
    }
  } else if (start_remaining_ > 0) {
    // Starting: the first samples on both feet, then on the first support foot (previewed
    // step 1, already on the ground), then the first swing's landing (free).
    phase.pattern = start_remaining_;
    setDoubleSupport(phase);
    phase.first_step_side = otherSide(support_side_);
    phase.step_fixed.setZero();
    phase.step_fixed(0) = 1;
    phase.fixed_step_pose.col(0) = footPose(phase.first_step_side);
  } else {
    const int m = phase_sample_;
    phase.pattern = S - 1 - m;
    phase.support_pose = footPose(support_side_);
    phase.support_half_length = w.copHalfLength();
    phase.support_half_width = w.copHalfWidth();
    phase.first_step_side = otherSide(support_side_);
    phase.step_fixed.setZero();
    if (m == S - 1) {
      // The swing foot has landed: step 1 is where it stands.
      phase.step_fixed(0) = 1;
      phase.fixed_step_pose.col(0) = footPose(phase.first_step_side);
    } else if (stop_step_) {
      // Final step: side by side with the support foot, same yaw.
      const double sign = phase.first_step_side == FootSide::kLeft ? 1.0 : -1.0;
      phase.step_fixed(0) = 1;
      phase.fixed_step_pose.col(0) =
          composePose(phase.support_pose, {0.0, sign * w.stop_foot_separation, 0.0});
    }
  }
  model_.rowStepsOf(phase.pattern, phase.row_step);

  // J2 references: each step turns by T_step * omega from the one before (eq. 8's p^theta),
  // from the support foot's yaw (paper) or from the command's heading when the support foot
  // landed (heading_reference: command; fixed steps stay where they are).
  const bool command_heading = w.heading_reference == HeadingReference::kCommand;
  double previous_yaw =
      command_heading ? commanded_heading_ - phase_sample_ * w.sampling_period * command.z()
                      : phase.support_pose.z();
  for (int i = 0; i < nf; ++i) {
    const double next = previous_yaw + w.stepDuration() * command.z();
    problem_.yaw_reference(i) = phase.step_fixed(i) ? phase.fixed_step_pose(2, i) : next;
    previous_yaw = command_heading ? next : problem_.yaw_reference(i);
  }
  // J1 references: the command turned into the world frame along the heading the robot will
  // have at each sample if it follows omega: from the feet's mean yaw (the free-flyer yaw;
  // paper) or from the command's heading.
  const double heading = command_heading ? commanded_heading_ : 0.5 * (left_.z() + right_.z());
  for (int j = 0; j < L.horizon; ++j) {
    const double yaw = heading + command.z() * (j + 1) * w.sampling_period;
    const double c = std::cos(yaw), s = std::sin(yaw);
    problem_.velocity_x(j) = c * command.x() - s * command.y();
    problem_.velocity_y(j) = s * command.x() + c * command.y();
  }
  problem_.com_x = com_x_;
  problem_.com_y = com_y_;
  // J1's windowed velocity: the samples of each window already walked (newest first: the
  // current sample's velocity, then the ones before).
  const int history = static_cast<int>(velocity_history_.cols());
  for (int i = history - 1; i > 0; --i) velocity_history_.col(i) = velocity_history_.col(i - 1);
  if (history > 0) velocity_history_.col(0) << com_x_(1), com_y_(1);
  const double window = w.velocity_window_samples;
  for (int j = 0; j < L.horizon; ++j) {
    double past_x = 0.0, past_y = 0.0;
    for (int i = 0; i < history - j; ++i) {
      past_x += velocity_history_(0, i);
      past_y += velocity_history_(1, i);
    }
    problem_.velocity_past_x(j) = past_x / window;
    problem_.velocity_past_y(j) = past_y / window;
  }
  selectObstacles();
}

const MpcIterationLog& PatternGenerator::update(double time, const Eigen::Vector3d& raw_command) {
  const auto start = std::chrono::steady_clock::now();
  const WalkingParameters& w = model_.parameters();
  const int S = w.stepSamples();
  const int nf = model_.layout().steps;
  const Eigen::Vector3d command = clampCommand(raw_command);
  const bool zero = isZeroCommand(command);
  // The previous command held since the previous sample.
  if (!standing_) commanded_heading_ += command_.z() * (time - time_);
  time_ = time;
  command_ = command;

  if (start_remaining_ > 0 && zero) {
    start_remaining_ = 0;  // start cancelled: back to standing
    standing_ = true;
    structure_changed_ = true;
  }
  if (standing_) {
    if (!zero) {
      // Start: the foot that swings first is on the side of the lateral / turning motion.
      const FootSide swing_first =
          (command.y() < 0.0 || (command.y() == 0.0 && command.z() < 0.0)) ? FootSide::kRight
                                                                           : FootSide::kLeft;
      standing_ = false;
      commanded_heading_ = 0.5 * (left_.z() + right_.z());
      support_side_ = swing_first;  // as if swing_first had been the support foot ...
      phase_sample_ = S - 1;        // ... and the other foot had just landed, after
      start_remaining_ = w.start_double_support_samples - 1;  // the starting double support
      zero_command_steps_ = 0;
      stop_step_ = false;
      structure_changed_ = true;
      Eigen::Vector3d previous = footPose(otherSide(swing_first));
      setStepPose(0, previous);
      FootSide side = swing_first;
      for (int i = 1; i < nf; ++i, side = otherSide(side)) {
        previous = nominalStep(previous, side, command);
        setStepPose(i, previous);
      }
    }
  } else if (start_remaining_ == 0) {
    if (phase_sample_ == 0) {
      zero_command_steps_ = zero ? zero_command_steps_ + 1 : 0;
      stop_step_ = zero && zero_command_steps_ >= 2;
    } else if (!zero) {
      stop_step_ = false;
    }
    if (phase_sample_ == S - 1 && stop_step_ && zero) {
      standing_ = true;  // the final step has landed side by side
      stop_step_ = false;
      structure_changed_ = true;
    }
  }
  if (structure_changed_) {
    solver_.clearActiveSet();  // the rows change meaning: no warm start across it
    structure_changed_ = false;
  }

  buildProblem(command);
  last_solve_ = settings_.algorithm == GeneratorAlgorithm::kLmpc
                    ? solver_.solveLmpc(model_, problem_, settings_)
                    : solver_.solve(model_, problem_, settings_);

  const NmpcLayout& L = model_.layout();
  plan_.jerk_x = solver_.plan()(L.jerkX());
  plan_.jerk_y = solver_.plan()(L.jerkY());
  plan_.swinging = !standing_ && start_remaining_ == 0 && phase_sample_ <= S - 2;
  plan_.support = plan_.swinging ? (support_side_ == FootSide::kLeft ? SupportState::kLeft
                                                                     : SupportState::kRight)
                                 : SupportState::kDouble;
  plan_.swing_side = otherSide(support_side_);
  plan_.swing_target = stepPose(0);
  plan_.landing_time = time + (S - 1 - phase_sample_) * w.sampling_period;
  plan_.lift_off_time = time - phase_sample_ * w.sampling_period;

  log_.time = time;
  log_.qp_iterations = last_solve_.qp_iterations;
  log_.sqp_iterations = last_solve_.sqp_iterations;
  log_.status = last_solve_.status;
  log_.cost = last_solve_.cost;
  log_.slack = last_solve_.slack;
  log_.relaxed_families = last_solve_.relaxed_families;
  log_.solve_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return log_;
}

bool PatternGenerator::advance(const Eigen::Vector3d& com_x, const Eigen::Vector3d& com_y) {
  const WalkingParameters& w = model_.parameters();
  const NmpcLayout& L = model_.layout();
  const int S = w.stepSamples();
  com_x_ = com_x;
  com_y_ = com_y;
  // Shift the plan one sample (the warm start of the next real-time iteration).
  Eigen::VectorXd& U = solver_.plan();
  for (int axis = 0; axis < 2; ++axis) {
    const int o = axis == 0 ? L.jerkX() : L.jerkY();
    for (int j = 0; j + 1 < L.horizon; ++j) U(o + j) = U(o + j + 1);
  }
  bool landed = false, step_completed = false;
  if (start_remaining_ > 0) {
    --start_remaining_;  // reaching 0 means the regular phase time S-1 (step 1 on the ground)
  } else if (!standing_) {
    if (phase_sample_ == S - 2) {
      const FootSide side = otherSide(support_side_);
      foot(side) = stepPose(0);
      last_landing_.landing_time = time_ + w.sampling_period;
      last_landing_.pose = foot(side);
      last_landing_.side = side;
      landed = true;
    }
    if (phase_sample_ == S - 1) {
      // Step completed: the landed foot becomes the support, the steps move up one place.
      support_side_ = otherSide(support_side_);
      phase_sample_ = 0;
      for (int i = 0; i + 1 < L.steps; ++i) setStepPose(i, stepPose(i + 1));
      FootSide last_side = support_side_;
      for (int i = 0; i < L.steps; ++i) last_side = otherSide(last_side);
      const Eigen::Vector3d previous =
          L.steps >= 2 ? stepPose(L.steps - 2) : footPose(support_side_);
      setStepPose(L.steps - 1, nominalStep(previous, last_side, command_));
      step_completed = true;
    } else {
      ++phase_sample_;
    }
  }
  solver_.shiftActiveSet(model_, step_completed);
  return landed;
}

}  // namespace wpg
