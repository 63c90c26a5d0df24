// swingReach (wpg/swing_foot_reach.hpp) against a straightforward implementation kept here:
// one direction, one tick and one limit at a time, through the public quintic and height
// profile. swingReach is written for speed (the NMPC asks for it at every iteration of a
// swing); its bounds must stay those of the plain form bit for bit, or the walks change.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "wpg/swing_foot_reach.hpp"
#include "wpg/swing_foot_trajectory.hpp"

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using wpg::QuinticToRest;
using wpg::SwingFootTrajectory;
using wpg::SwingReach;

// The header's derivation as written: per tick tau of [0, T) and direction k, the interval of
// d_k . h that keeps |d_k . v(tau)| and |d_k . a(tau)| within the polygon's limits.
void intersectOne(double gain, double offset, double limit, double& low, double& high) {
  if (std::abs(gain) < 1e-12) return;
  double a = (-limit - offset) / gain, b = (limit - offset) / gain;
  if (gain < 0.0) std::swap(a, b);
  low = std::max(low, a);
  high = std::min(high, b);
}

double horizontalLimitOne(double limit, double vertical) {
  return SwingReach::polygonFactor() * std::sqrt(std::max(limit * limit - vertical * vertical, 0.0));
}

SwingReach referenceReach(const SwingFootTrajectory& swing, double t, const Vector2d& current_target,
                          double max_speed, double max_acceleration, double tick) {
  SwingReach reach;
  const Vector2d p0(swing.axisState(0, t)(0), swing.axisState(1, t)(0));
  const double T = swing.landingTime() - t;
  for (int k = 0; k < SwingReach::kDirections; ++k)
    reach.lower(k) = reach.upper(k) = SwingReach::direction(k).dot(current_target);
  if (!(T > 0.0) || !(tick > 0.0)) return reach;
  QuinticToRest base[2];
  for (int axis = 0; axis < 2; ++axis) {
    const Vector3d state = swing.axisState(axis, t);
    base[axis].plan(state(0), state(1), state(2), state(0), T);
  }
  const int ticks = static_cast<int>(std::ceil(T / tick - 1e-9));
  for (int k = 0; k < SwingReach::kDirections; ++k) {
    const Vector2d d = SwingReach::direction(k);
    double low = -std::numeric_limits<double>::infinity();
    double high = std::numeric_limits<double>::infinity();
    for (int j = 1; j < ticks; ++j) {
      const double tau = j * tick, s = tau / T;
      const Vector3d x = base[0].evaluate(tau), y = base[1].evaluate(tau);
      const Vector3d z = swing.heightState(t + tau);
      if (max_speed > 0.0)
        intersectOne(s * s * (30.0 + s * (-60.0 + 30.0 * s)) / T, d.x() * x(1) + d.y() * y(1),
                     horizontalLimitOne(max_speed, z(1)), low, high);
      if (max_acceleration > 0.0)
        intersectOne(s * (60.0 + s * (-180.0 + 120.0 * s)) / (T * T), d.x() * x(2) + d.y() * y(2),
                     horizontalLimitOne(max_acceleration, z(2)), low, high);
    }
    const double offset = d.dot(p0);
    const double current = reach.lower(k) - offset;
    if (low > high) low = high = current;
    low = std::max(low, current - 1e6);
    high = std::min(high, current + 1e6);
    reach.lower(k) = std::min(low, current) + offset;
    reach.upper(k) = std::max(high, current) + offset;
  }
  return reach;
}

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Random swings (duration, step height, start pose), re-planned to random landings at random
// times, asked for their reach at random times (before lift-off and after the landing too)
// under random limits (either one off now and then) and ticks.
TEST(SwingReach, MatchesTheReferenceBitForBitOnRandomSwings) {
  std::mt19937 engine(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto between = [&](double a, double b) { return a + (b - a) * unit(engine); };
  const double ticks[] = {0.005, 0.005, 0.005, 0.001, 0.01, 0.0137, 0.5};
  int compared = 0, bounded = 0;
  for (int trial = 0; trial < 400; ++trial) {
    SwingFootTrajectory swing;
    const double lift_off = between(0.0, 5.0), landing = lift_off + between(0.2, 1.2);
    swing.start(Vector3d(between(-1, 1), between(-1, 1), between(-1, 1)), lift_off, landing,
                between(0.0, 0.25));
    Vector2d target = swing.poseAt(lift_off).head<2>();
    double t = lift_off;
    for (int sample = 0; sample < 8; ++sample) {
      t += between(-0.02, 0.15);
      // down to limits the height profile alone exceeds (no horizontal share left)
      const double max_speed = unit(engine) < 0.1 ? 0.0 : between(0.2, 4.0);
      const double max_acceleration = unit(engine) < 0.1 ? 0.0 : between(2.0, 80.0);
      const double tick = ticks[static_cast<int>(unit(engine) * 7) % 7];
      const SwingReach fast = swingReach(swing, t, target, max_speed, max_acceleration, tick);
      const SwingReach plain = referenceReach(swing, t, target, max_speed, max_acceleration, tick);
      SCOPED_TRACE(::testing::Message() << "trial " << trial << ", sample " << sample);
      for (int k = 0; k < SwingReach::kDirections; ++k) {
        EXPECT_EQ(bits(fast.lower(k)), bits(plain.lower(k))) << fast.lower(k) << " " << plain.lower(k);
        EXPECT_EQ(bits(fast.upper(k)), bits(plain.upper(k))) << fast.upper(k) << " " << plain.upper(k);
        bounded += plain.upper(k) - plain.lower(k) < 1.0;
      }
      ++compared;
      // The next plan: a landing up to 0.3 m away (often outside the reach: the swing is
      // pushed to states no limit would allow, which the bounds must follow all the same).
      target += Vector2d(between(-0.3, 0.3), between(-0.3, 0.3));
      if (t < landing) swing.replan(std::max(t, lift_off), Vector3d(target.x(), target.y(), 0.0));
    }
  }
  EXPECT_EQ(compared, 400 * 8);
  EXPECT_GT(bounded, compared);  // most directions are bounded, not only the far fallback
}

}  // namespace
