#include "wpg/online_walking_generator.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace wpg {
namespace {

// Public entry points: a vector of `size` finite entries, else std::invalid_argument saying
// what was expected and what came.
void requireFiniteVector(const char* what, const Eigen::Ref<const Eigen::VectorXd>& value,
                         Eigen::Index size, const char* expected) {
  if (value.size() != size) {
    throw std::invalid_argument(std::string("OnlineWalkingGenerator::") + what + ": expected " +
                                std::to_string(size) + " entries " + expected + ", got " +
                                std::to_string(value.size()));
  }
  if (!value.allFinite()) {
    throw std::invalid_argument(std::string("OnlineWalkingGenerator::") + what + ": expected " +
                                "finite values " + expected + ", got a non-finite value");
  }
}

const WalkingParameters& validated(const WalkingParameters& parameters,
                                   const GeneratorSettings& settings) {
  parameters.validate();
  settings.validate();
  return parameters;
}

}  // namespace

OnlineWalkingGenerator::OnlineWalkingGenerator(const WalkingParameters& parameters,
                                               const GeneratorSettings& settings,
                                               const ConstraintFamilies& extra_families)
    : settings_(settings),
      generator_(validated(parameters, settings), settings, extra_families),
      sub_samples_(static_cast<int>(std::lround(parameters.sampling_period / parameters.control_period))),
      height_over_gravity_(parameters.com_height / parameters.gravity),
      omega0_(std::sqrt(parameters.gravity / parameters.com_height)) {
  reset();
}

void OnlineWalkingGenerator::reset(const Eigen::Ref<const Eigen::VectorXd>& pose) {
  requireFiniteVector("reset", pose, 3, "(x [m], y [m], yaw [rad])");
  generator_.reset(Eigen::Vector3d(pose(0), pose(1), pose(2)));
  com_x_ = generator_.comX();
  com_y_ = generator_.comY();
  swing_started_ = false;
  sample_index_ = 0;
  sub_sample_ = 0;
  command_.setZero();
  push_.setZero();
  landed_ = fallen_ = false;
  capture_distance_ = 0.0;
  last_iteration_ = MpcIterationLog();
  sample_ = ControlSample();
}

void OnlineWalkingGenerator::setCommand(const Eigen::Ref<const Eigen::VectorXd>& command) {
  requireFiniteVector("setCommand", command, 3, "(vx [m/s], vy [m/s], omega [rad/s])");
  command_ << command(0), command(1), command(2);
}

void OnlineWalkingGenerator::setObstacles(std::vector<Obstacle> obstacles) {
  generator_.setObstacles(std::move(obstacles));
}


void OnlineWalkingGenerator::setPushAcceleration(
    const Eigen::Ref<const Eigen::VectorXd>& acceleration) {
  requireFiniteVector("setPushAcceleration", acceleration, 2, "(x, y [m/s^2])");
  push_ << acceleration(0), acceleration(1);
}

void OnlineWalkingGenerator::reinitializeCom(const Eigen::Ref<const Eigen::VectorXd>& com_x,
                                             const Eigen::Ref<const Eigen::VectorXd>& com_y) {
  requireFiniteVector("reinitializeCom", com_x, 3, "(x, x', x'')");
  requireFiniteVector("reinitializeCom", com_y, 3, "(y, y', y'')");
  if (!atSamplingInstant())
    throw std::logic_error("OnlineWalkingGenerator::reinitializeCom: expected a sampling "
                           "instant (the NMPC re-plans from the new state), got time " +
                           std::to_string(time()) + " s inside a sampling period");
  com_x_ = com_x;
  com_y_ = com_y;
  generator_.setComState(com_x_, com_y_);
}

void OnlineWalkingGenerator::previewReference(int ticks, WalkTrajectory& out) const {
  if (atSamplingInstant())
    throw std::logic_error("OnlineWalkingGenerator::previewReference: at a sampling instant "
                           "the coming NMPC iteration has not run yet (call it after that "
                           "step())");
  const WalkingParameters& w = parameters();
  const PatternGenerator& pg = generator_;
  const NmpcLayout& L = pg.model().layout();
  const Eigen::VectorXd& U = pg.solver().plan();
  out.time.clear();
  out.com.clear();
  out.com_vel.clear();
  out.com_acc.clear();
  out.cop.clear();
  out.left_foot.clear();
  out.right_foot.clear();
  out.free_flyer_yaw.clear();
  out.support.clear();
  // A copy of the phase bookkeeping, the swing polynomial and the CoM, advanced as step()
  // and PatternGenerator::advance() would, with the plan's later jerks and steps instead of
  // new NMPC solutions (shiftPlan's shift as index offsets).
  GaitScheduler gait = pg.gait();
  SwingFootTrajectory swing = swing_;
  Eigen::Vector3d cx = com_x_, cy = com_y_;
  long sample = sample_index_;
  int sub = sub_sample_;
  int jerk_offset = 0, step_offset = 0;
  bool swinging = pg.plan().swinging;
  FootSide swing_side = pg.plan().swing_side;
  const Eigen::Vector3d command = pg.clampCommand(command_);
  const auto planned_step = [&](int i) -> Eigen::Vector3d {
    if (i < L.steps) return pg.plannedStep(i);
    // Past the plan's steps (a window longer than the horizon): nominal steps.
    Eigen::Vector3d previous = pg.plannedStep(L.steps - 1);
    FootSide side = otherSide(gait.supportSide());
    for (int k = L.steps; k <= i; ++k, side = otherSide(side))
      previous = nominalStep(w, previous, side, command);
    return previous;
  };
  for (int j = 0; j < ticks; ++j) {
    const double t = sample * w.sampling_period + sub * w.control_period;
    const double h = w.com_height;
    out.time.push_back(t);
    out.com.emplace_back(cx(0), cy(0), h);
    out.com_vel.emplace_back(cx(1), cy(1), 0.0);
    out.com_acc.emplace_back(cx(2), cy(2), 0.0);
    out.cop.emplace_back(cx(0) - height_over_gravity_ * cx(2), cy(0) - height_over_gravity_ * cy(2));
    const Eigen::Vector3d& l = gait.footPose(FootSide::kLeft);
    const Eigen::Vector3d& r = gait.footPose(FootSide::kRight);
    Eigen::Vector4d left(l.x(), l.y(), 0.0, l.z()), right(r.x(), r.y(), 0.0, r.z());
    if (swinging) (swing_side == FootSide::kLeft ? left : right) = swing.poseAt(t);
    out.left_foot.push_back(left);
    out.right_foot.push_back(right);
    out.free_flyer_yaw.push_back(0.5 * (left(3) + right(3)));
    out.support.push_back(gait.supportState());
    const int jerk = std::min(jerk_offset, L.horizon - 1);
    integrateJerk(cx, U(L.jerkX() + jerk), w.control_period, 0.0);
    integrateJerk(cy, U(L.jerkY() + jerk), w.control_period, 0.0);
    if (++sub < sub_samples_) continue;
    // The end of a sampling period, then the start of the next one (without its NMPC).
    sub = 0;
    ++sample;
    const double start = sample * w.sampling_period;
    if (gait.endSample(planned_step(step_offset), start).step_completed) ++step_offset;
    ++jerk_offset;
    const bool was_swinging = swinging;
    gait.beginSample(command, Eigen::Vector2d(cx(0) + cx(1) / omega0_, cy(0) + cy(1) / omega0_));
    swinging = gait.swinging();
    if (!swinging) continue;
    swing_side = otherSide(gait.supportSide());
    const int m = gait.phaseSample();
    if (!was_swinging) {  // a new swing: its polynomial from the lift-off pose (runNmpcSample)
      swing.start(gait.footPose(swing_side), start - (m - gait.liftOffSample()) * w.sampling_period,
                  start + (gait.stepSamples() - 1 - m) * w.sampling_period, w.step_height);
    }
    swing.replan(start, planned_step(step_offset));
  }
}

double OnlineWalkingGenerator::time() const {
  const WalkingParameters& w = parameters();
  return sample_index_ * w.sampling_period + sub_sample_ * w.control_period;
}

// The sampling instant t: fall check, NMPC, swing-foot polynomials re-planned to the new
// landing target.
void OnlineWalkingGenerator::runNmpcSample(double t) {
  // Fall: the capture point (where the CoM comes to rest over a fixed CoP) out of reach.
  const Eigen::Vector2d capture(com_x_(0) + com_x_(1) / omega0_, com_y_(0) + com_y_(1) / omega0_);
  capture_distance_ =
      std::min((capture - generator_.footPose(FootSide::kLeft).head<2>()).norm(),
               (capture - generator_.footPose(FootSide::kRight).head<2>()).norm());
  if (!(capture_distance_ <= settings_.fall_capture_distance)) {
    fallen_ = true;
    last_iteration_ = MpcIterationLog();
    last_iteration_.time = t;
    last_iteration_.status = IterationStatus::kFallen;
    return;
  }
  last_iteration_ = generator_.update(t, command_, swing_started_ ? &swing_ : nullptr);
  const PatternGenerator::SamplePlan& plan = generator_.plan();
  if (plan.swinging) {
    if (!swing_started_) {
      swing_.start(generator_.footPose(plan.swing_side), plan.lift_off_time, plan.landing_time,
                   parameters().step_height);
      swing_started_ = true;
    }
    swing_.replan(t, plan.swing_target);
  } else {
    swing_started_ = false;
  }
}

void OnlineWalkingGenerator::fillSample(double t) {
  const PatternGenerator::SamplePlan& plan = generator_.plan();
  const double h = parameters().com_height;
  sample_.time = t;
  sample_.com_position << com_x_(0), com_y_(0), h;
  sample_.com_velocity << com_x_(1), com_y_(1), 0.0;
  sample_.com_acceleration << com_x_(2) + push_.x(), com_y_(2) + push_.y(), 0.0;
  sample_.cop << com_x_(0) - height_over_gravity_ * com_x_(2),
      com_y_(0) - height_over_gravity_ * com_y_(2);
  const Eigen::Vector3d& l = generator_.footPose(FootSide::kLeft);
  const Eigen::Vector3d& r = generator_.footPose(FootSide::kRight);
  sample_.left_foot << l.x(), l.y(), 0.0, l.z();
  sample_.right_foot << r.x(), r.y(), 0.0, r.z();
  if (plan.swinging) {
    assert(swing_started_);
    (plan.swing_side == FootSide::kLeft ? sample_.left_foot : sample_.right_foot) = swing_.poseAt(t);
  }
  sample_.free_flyer_yaw = 0.5 * (sample_.left_foot(3) + sample_.right_foot(3));
  sample_.support = plan.support;
}

const ControlSample& OnlineWalkingGenerator::currentSample() {
  fillSample(time());
  sample_.nmpc_sample = false;
  return sample_;
}

const ControlSample& OnlineWalkingGenerator::step() {
  assert(sub_sample_ >= 0 && sub_sample_ < sub_samples_);
  landed_ = false;
  if (fallen_) return currentSample();
  const double t = time();
  const bool sampling_instant = atSamplingInstant();
  if (sampling_instant) {
    runNmpcSample(t);
    if (fallen_) return currentSample();
  }
  fillSample(t);
  sample_.nmpc_sample = sampling_instant;
  const PatternGenerator::SamplePlan& plan = generator_.plan();
  const double dt = parameters().control_period;
  integrateJerk(com_x_, plan.jerk_x, dt, push_.x());
  integrateJerk(com_y_, plan.jerk_y, dt, push_.y());
  push_.setZero();  // the push was for this period only
  if (++sub_sample_ == sub_samples_) {
    landed_ = generator_.advance(com_x_, com_y_);
    sub_sample_ = 0;
    ++sample_index_;
  }
  return sample_;
}

}  // namespace wpg
