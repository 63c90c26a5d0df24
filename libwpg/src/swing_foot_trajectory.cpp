#include "wpg/swing_foot_trajectory.hpp"

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

Eigen::Vector4d SwingFootTrajectory::poseAt(double t) const {
  return {axes_[0].evaluate(t - plan_time_)(0), axes_[1].evaluate(t - plan_time_)(0),
          heightState(t)(0), axes_[2].evaluate(t - plan_time_)(0)};
}

}  // namespace wpg
