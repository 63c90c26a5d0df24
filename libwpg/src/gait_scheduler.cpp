#include "wpg/gait_scheduler.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace wpg {
namespace {

bool isZeroCommand(const Eigen::Vector3d& command) { return command.cwiseAbs().maxCoeff() < 1e-9; }

}  // namespace

Eigen::Vector3d composePose(const Eigen::Vector3d& base, const Eigen::Vector3d& local) {
  const double c = std::cos(base.z()), s = std::sin(base.z());
  return {base.x() + c * local.x() - s * local.y(), base.y() + s * local.x() + c * local.y(),
          base.z() + local.z()};
}

Eigen::Vector3d nominalStep(const WalkingParameters& w, const Eigen::Vector3d& previous,
                            FootSide side, const Eigen::Vector3d& command) {
  const double T_step = w.stepDuration();
  const double lateral = 0.5 * (w.feasibility_y[0] + w.feasibility_y[2]);
  const double yaw = std::clamp(command.z() * T_step, -w.max_step_yaw_change, w.max_step_yaw_change);
  const double sign = side == FootSide::kLeft ? 1.0 : -1.0;
  return composePose(previous, {command.x() * T_step, sign * lateral + command.y() * T_step, yaw});
}

GaitScheduler::GaitScheduler(const WalkingParameters& parameters)
    : parameters_(parameters),
      samples_per_step_(parameters.stepSamples()),
      requested_samples_(parameters.stepSamples()) {
  reset(Eigen::Vector3d::Zero());
}

void GaitScheduler::reset(const Eigen::Vector3d& pose) {
  const double half = 0.5 * parameters_.initial_foot_separation;
  left_ = composePose(pose, {0.0, half, 0.0});
  right_ = composePose(pose, {0.0, -half, 0.0});
  last_landing_ = Footstep();
  samples_per_step_ = requested_samples_ = parameters_.stepSamples();
  standing_ = true;
  support_side_ = FootSide::kRight;
  phase_sample_ = 0;
  start_remaining_ = 0;
  zero_command_steps_ = 0;
  stop_step_ = false;
  push_start_ = false;
  short_first_swing_ = false;
  lift_off_sample_ = 0;
  swing_landed_ = false;
  structure_changed_ = true;
}

GaitScheduler::SampleStart GaitScheduler::beginSample(const Eigen::Vector3d& command,
                                                      const Eigen::Vector2d& capture_point) {
  bool cadence_changed = false;
  if (standing_ && requested_samples_ != samples_per_step_) {
    samples_per_step_ = requested_samples_;  // standing: no phase time to carry over
    structure_changed_ = cadence_changed = true;
  }
  const int S = samples_per_step_;
  const bool zero = isZeroCommand(command);
  // A zero command halts the walk only when the gait stops on it.
  const bool halt = zero && parameters_.zero_command == ZeroCommandGait::kStop;
  SampleStart start;
  if (start_remaining_ > 0 && halt && !push_start_) {
    start_remaining_ = 0;  // start cancelled: back to standing
    standing_ = true;
    structure_changed_ = true;
  }
  if (standing_) {
    const bool pushed = parameters_.standing_push_response == StandingPushResponse::kStep &&
                        outsideStandingSupport(capture_point);
    if (!halt || pushed) {
      FootSide swing_first = FootSide::kLeft;
      if (!zero) {
        // The foot that swings first is on the side of the lateral / turning motion.
        if (command.y() < 0.0 || (command.y() == 0.0 && command.z() < 0.0))
          swing_first = FootSide::kRight;
      } else if (pushed) {
        // The foot on the side the capture point went to steps out under it (ties: left).
        const Eigen::Vector3d mid = 0.5 * (left_ + right_);
        const Eigen::Vector2d offset = capture_point - mid.head<2>();
        const double lateral = -std::sin(mid.z()) * offset.x() + std::cos(mid.z()) * offset.y();
        if (lateral < 0.0) swing_first = FootSide::kRight;
      }
      const bool push_start = pushed && halt;  // a non-zero command starts as it always does
      standing_ = false;
      support_side_ = swing_first;  // as if swing_first had been the support foot ...
      phase_sample_ = S - 1;        // ... and the other foot had just landed, after
      start_remaining_ = (pushed ? parameters_.push_start_double_support_samples
                                 : parameters_.start_double_support_samples) -
                         1;  // the starting double support
      zero_command_steps_ = 0;
      stop_step_ = false;
      push_start_ = push_start;
      short_first_swing_ = pushed;
      structure_changed_ = true;
      start.started = true;
      start.first_swing = swing_first;
    }
  } else if (start_remaining_ == 0) {
    if (phase_sample_ == lift_off_sample_) {
      zero_command_steps_ = halt ? zero_command_steps_ + 1 : 0;
      stop_step_ = halt && zero_command_steps_ >= 2;
    } else if (!halt) {
      stop_step_ = false;
    }
    if (phase_sample_ == S - 1 && stop_step_ && halt) {
      standing_ = true;  // the final step has landed side by side
      stop_step_ = false;
      push_start_ = false;
      structure_changed_ = true;
    }
  }
  if (atLanding() && requested_samples_ != samples_per_step_) {
    // The landed step is fixed and the next steps take the new timing from their lift-off.
    samples_per_step_ = requested_samples_;
    phase_sample_ = samples_per_step_ - 1;
    lift_off_sample_ = 0;
    structure_changed_ = cadence_changed = true;
  }
  start.cadence_changed = cadence_changed;
  start.structure_changed = structure_changed_;
  structure_changed_ = false;
  return start;
}

bool GaitScheduler::outsideStandingSupport(const Eigen::Vector2d& capture_point) const {
  const StandingRectangle rectangle = standingRectangle();
  const double c = std::cos(rectangle.centre.z()), s = std::sin(rectangle.centre.z());
  const Eigen::Vector2d d = capture_point - rectangle.centre.head<2>();
  return std::abs(c * d.x() + s * d.y()) > rectangle.half_length ||
         std::abs(-s * d.x() + c * d.y()) > rectangle.half_width;
}

double GaitScheduler::captureOffsetTowardsLiftingFoot(const Eigen::Vector2d& capture_point) const {
  // At a landing the support side is still the step's: the foot that lifts next. The landed
  // foot is the other one; its lateral axis (-sin yaw, cos yaw) points to its left.
  const Eigen::Vector3d& landed = footPose(otherSide(support_side_));
  const double towards_lifting = support_side_ == FootSide::kLeft ? 1.0 : -1.0;
  const Eigen::Vector2d d = capture_point - landed.head<2>();
  return towards_lifting * (-std::sin(landed.z()) * d.x() + std::cos(landed.z()) * d.y());
}

SupportState GaitScheduler::supportState() const {
  if (!swinging()) return SupportState::kDouble;
  return support_side_ == FootSide::kLeft ? SupportState::kLeft : SupportState::kRight;
}

// Double support on parallel side-by-side feet: the hull of both margin-reduced soles is a
// rectangle about the point between the ankles.
GaitScheduler::StandingRectangle GaitScheduler::standingRectangle() const {
  const WalkingParameters& w = parameters_;
  const Eigen::Vector3d mid = 0.5 * (left_ + right_);
  const double c = std::cos(mid.z()), s = std::sin(mid.z());
  const Eigen::Vector2d offset = (left_ - right_).head<2>();
  const double separation = std::abs(-s * offset.x() + c * offset.y());
  return {mid, w.copHalfLength(), 0.5 * separation + w.copHalfWidth()};
}

void GaitScheduler::setDoubleSupport(PhaseStructure& phase) const {
  const StandingRectangle rectangle = standingRectangle();
  phase.support_pose = rectangle.centre;
  phase.support_half_length = rectangle.half_length;
  phase.support_half_width = rectangle.half_width;
}

void GaitScheduler::fillPhase(const NmpcModel& model, PhaseStructure& phase) const {
  const WalkingParameters& w = parameters_;
  const int S = samples_per_step_;
  const int nf = model.layout().steps;
  assert(model.parameters().stepSamples() == S);
  assert(phase.step_fixed.size() == nf && phase.fixed_step_pose.cols() == nf);
  if (standing_) {
    phase.pattern = model.standingPattern();
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
  model.rowStepsOf(phase.pattern, phase.row_step);
}

GaitScheduler::SampleEnd GaitScheduler::endSample(const Eigen::Vector3d& planned_landing,
                                                  double end_time) {
  const int S = samples_per_step_;
  SampleEnd end;
  if (start_remaining_ > 0) {
    --start_remaining_;  // reaching 0 means the regular phase time S-1 (step 1 on the ground)
  } else if (!standing_) {
    if (phase_sample_ == S - 2) {
      const FootSide side = otherSide(support_side_);
      foot(side) = planned_landing;
      last_landing_.landing_time = end_time;
      last_landing_.lift_off_time =
          end_time - (S - 1 - lift_off_sample_) * parameters_.sampling_period;
      last_landing_.pose = planned_landing;
      last_landing_.side = side;
      swing_landed_ = true;
      end.landed = true;
    }
    if (phase_sample_ == S - 1) {
      // Step completed: the landed foot becomes the support. The first swing after a push
      // start lifts off later in the step (a swing of push_step_swing_samples).
      support_side_ = otherSide(support_side_);
      lift_off_sample_ =
          short_first_swing_ ? S - 1 - std::min(parameters_.push_step_swing_samples, S - 1) : 0;
      short_first_swing_ = false;
      swing_landed_ = false;
      phase_sample_ = lift_off_sample_;
      end.step_completed = true;
    } else {
      ++phase_sample_;
    }
  }
  return end;
}

}  // namespace wpg
