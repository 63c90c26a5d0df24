#pragma once
// Swing foot interpolation at the control period (paper Sec. III-A: "polynomials of fifth
// order to retrieve 3D trajectories for the feet"). Horizontal position and yaw: a quintic
// re-planned at every NMPC sample from the foot's current position, velocity and
// acceleration to the latest planned landing, arriving with zero velocity and acceleration.
// Height: fifth-order polynomials too, as the paper says: a quintic rest-to-rest rise
// h (10 x^3 - 15 x^4 + 6 x^5), x = 2 s, over the first half of the swing (s = swing time
// fraction) and its mirror image down over the second: the step height at mid-swing, zero
// velocity and acceleration at lift-off, apex and touch-down (C2 throughout). Until
// 2026-11 this was one degree-6 curve h 64 s^3 (1 - s)^3, with the same apex and end
// conditions; the paper uses fifth-order polynomials.
#include <algorithm>

#include <Eigen/Core>

namespace wpg {

// p(t) on [0, duration] with p, p', p'' given at 0 and p(duration) = target, zero p', p''.
class QuinticToRest {
 public:
  void plan(double position, double velocity, double acceleration, double target, double duration);
  // Value, first and second derivative at time t in [0, duration] (clamped).
  Eigen::Vector3d evaluate(double t) const;
  // evaluate()'s first and second derivative at t in [0, duration), without its branches,
  // for one time or for an Eigen array of times (the swing reach asks for them at every
  // control tick of the rest of a swing: a block of ticks is a few packets), the same
  // operations either way.
  template <class Time>
  Time velocity(const Time& t) const {
    return c_[1] + t * (2 * c_[2] + t * (3 * c_[3] + t * (4 * c_[4] + t * 5 * c_[5])));
  }
  template <class Time>
  Time acceleration(const Time& t) const {
    return 2 * c_[2] + t * (6 * c_[3] + t * (12 * c_[4] + t * 20 * c_[5]));
  }

 private:
  double c_[6] = {0, 0, 0, 0, 0, 0};
  double duration_ = 0.0;
  double target_ = 0.0;  // p1: returned exactly at the end (the polynomial's rounding is not)
};

class SwingFootTrajectory {
 public:
  // Foot on the ground at `pose` (x, y, yaw), at rest.
  void start(const Eigen::Vector3d& pose, double lift_off_time, double landing_time,
             double step_height);
  // Re-plans from the state at time t towards `target` (landing at the landing time).
  void replan(double t, const Eigen::Vector3d& target);
  // x, y, z (sole height above the ground), yaw at time t.
  Eigen::Vector4d poseAt(double t) const;
  // Position, velocity and acceleration of axis 0 = x, 1 = y, 2 = yaw at time t (the plan in
  // force, which replan(t, same target) would continue unchanged).
  Eigen::Vector3d axisState(int axis, double t) const { return axes_[axis].evaluate(t - plan_time_); }
  // Height z, z', z'' at time t (the rise-and-fall profile above). swingReach repeats its
  // operations for z'^2 and z''^2 by packets (swing_foot_reach.cpp): change both together.
  Eigen::Vector3d heightState(double t) const;
  double liftOffTime() const { return lift_off_time_; }
  double landingTime() const { return landing_time_; }
  double stepHeight() const { return step_height_; }

 private:
  QuinticToRest axes_[3];  // x, y, yaw
  double plan_time_ = 0.0, lift_off_time_ = 0.0, landing_time_ = 0.0, step_height_ = 0.0;
};

// Inline: the control tick asks for the feet's poses alone (poseAt, every 5 ms), which then
// skips the rates.
inline Eigen::Vector3d QuinticToRest::evaluate(double t) const {
  // At the end (and after): the target itself, at rest, so that the foot lands exactly where
  // the landing is reported (the Horner sum at T differs from p1 by rounding).
  if (t >= duration_) return {target_, 0.0, 0.0};
  t = std::max(t, 0.0);
  const double p = c_[0] + t * (c_[1] + t * (c_[2] + t * (c_[3] + t * (c_[4] + t * c_[5]))));
  return {p, velocity(t), acceleration(t)};
}

inline Eigen::Vector3d SwingFootTrajectory::heightState(double t) const {
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

}  // namespace wpg
