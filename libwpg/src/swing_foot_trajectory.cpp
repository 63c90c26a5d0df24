#include "wpg/swing_foot_trajectory.hpp"

#include <algorithm>

namespace wpg {

void QuinticToRest::plan(double p0, double v0, double a0, double p1, double T) {
  duration_ = T;
  target_ = p1;
  c_[0] = p0;
  c_[1] = v0;
  c_[2] = 0.5 * a0;
  if (T <= 0.0) {
    c_[0] = p1;
    c_[1] = c_[2] = c_[3] = c_[4] = c_[5] = 0.0;
    return;
  }
  // Remaining coefficients from p(T) = p1, p'(T) = 0, p''(T) = 0.
  const double T2 = T * T, T3 = T2 * T, T4 = T3 * T, T5 = T4 * T;
  const double h = p1 - p0;
  c_[3] = (20.0 * h - (12.0 * v0 * T) - (3.0 * a0 * T2)) / (2.0 * T3);
  c_[4] = (-30.0 * h + (16.0 * v0 * T) + (3.0 * a0 * T2)) / (2.0 * T4);
  c_[5] = (12.0 * h - (6.0 * v0 * T) - (a0 * T2)) / (2.0 * T5);
}

Eigen::Vector3d QuinticToRest::evaluate(double t) const {
  // At the end (and after): the target itself, at rest, so that the foot lands exactly where
  // the landing is reported (the Horner sum at T differs from p1 by rounding).
  if (t >= duration_) return {target_, 0.0, 0.0};
  t = std::max(t, 0.0);
  const double p = c_[0] + t * (c_[1] + t * (c_[2] + t * (c_[3] + t * (c_[4] + t * c_[5]))));
  return {p, velocity(t), acceleration(t)};
}

void SwingFootTrajectory::start(const Eigen::Vector3d& pose, double lift_off_time,
                                double landing_time, double step_height) {
  lift_off_time_ = lift_off_time;
  landing_time_ = landing_time;
  step_height_ = step_height;
  plan_time_ = lift_off_time;
  for (int k = 0; k < 3; ++k) axes_[k].plan(pose(k), 0.0, 0.0, pose(k), landing_time - lift_off_time);
}

void SwingFootTrajectory::replan(double t, const Eigen::Vector3d& target) {
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d state = axes_[k].evaluate(t - plan_time_);
    axes_[k].plan(state(0), state(1), state(2), target(k), landing_time_ - t);
  }
  plan_time_ = t;
}

Eigen::Vector3d SwingFootTrajectory::heightState(double t) const {
  const double duration = landing_time_ - lift_off_time_;
  if (!(duration > 0.0)) return Eigen::Vector3d::Zero();
  const double s = std::clamp((t - lift_off_time_) / duration, 0.0, 1.0);
  // eq. of the header: the quintic rest-to-rest profile f(x) on each half of the swing,
  // x = 2 min(s, 1 - s), so dx/dt = +-2 / duration
  const bool rising = s <= 0.5;
  const double x = 2.0 * std::min(s, 1.0 - s);
  const double df = x * x * (30.0 + x * (-60.0 + 30.0 * x));
  const double ddf = x * (60.0 + x * (-180.0 + 120.0 * x));
  const double dxdt = (rising ? 2.0 : -2.0) / duration;
  // z: the order of the products the regression references were written with
  const double z = step_height_ * x * x * x * (10.0 + x * (-15.0 + 6.0 * x));
  return {z, step_height_ * df * dxdt, step_height_ * ddf * dxdt * dxdt};
}

Eigen::Vector4d SwingFootTrajectory::poseAt(double t) const {
  return {axes_[0].evaluate(t - plan_time_)(0), axes_[1].evaluate(t - plan_time_)(0),
          heightState(t)(0), axes_[2].evaluate(t - plan_time_)(0)};
}

}  // namespace wpg
