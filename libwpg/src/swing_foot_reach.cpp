#include "wpg/swing_foot_reach.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wpg {

namespace {

constexpr int kDirections = SwingReach::kDirections;

// The directions' cosines and sines, computed once: swingReach asks for them for every tick
// of the rest of the swing at every NMPC iteration (a batch spent 11 % of its time in sincos).
// Two rows of plain numbers, which the loops over the directions read as packets.
struct DirectionTable {
  alignas(16) double cos[kDirections];
  alignas(16) double sin[kDirections];
  double polygon_factor;
  DirectionTable() : polygon_factor(std::cos(M_PI / (2.0 * kDirections))) {
    for (int k = 0; k < kDirections; ++k) {
      const double angle = k * (M_PI / kDirections);
      cos[k] = std::cos(angle);
      sin[k] = std::sin(angle);
    }
  }
  Eigen::Vector2d direction(int k) const { return {cos[k], sin[k]}; }
};

const DirectionTable& directionTable() {
  static const DirectionTable table;
  return table;
}

}  // namespace

Eigen::Vector2d SwingReach::direction(int k) {
  return directionTable().direction(k);
}

double SwingReach::polygonFactor() { return directionTable().polygon_factor; }

namespace {

// The running intervals of d_k . h, one per direction.
struct Intervals {
  alignas(16) double low[kDirections];
  alignas(16) double high[kDirections];
};

// lo <= gain h + offset_k <= hi as an interval of h, intersected into interval k for every
// direction k at once, offset_k = d_k . (vx, vy): one tick's speed or acceleration. The same
// operations in the same order as one direction at a time (the bounds bit for bit), written
// as loops over the directions, which the compiler turns into packets.
void intersect(const DirectionTable& table, double gain, double vx, double vy, double limit,
               Intervals& intervals) {
  if (std::abs(gain) < 1e-12) return;  // the tick does not depend on the landing
  double a[kDirections], b[kDirections];
  for (int k = 0; k < kDirections; ++k) {
    const double offset = table.cos[k] * vx + table.sin[k] * vy;
    a[k] = (-limit - offset) / gain;
    b[k] = (limit - offset) / gain;
  }
  if (gain < 0.0) {  // the ends swapped
    for (int k = 0; k < kDirections; ++k) {
      intervals.low[k] = std::max(intervals.low[k], b[k]);
      intervals.high[k] = std::min(intervals.high[k], a[k]);
    }
  } else {
    for (int k = 0; k < kDirections; ++k) {
      intervals.low[k] = std::max(intervals.low[k], a[k]);
      intervals.high[k] = std::min(intervals.high[k], b[k]);
    }
  }
}

// The terms of a block of ticks that do not depend on the direction, computed by packets
// (Eigen's arrays, on the stack: no allocation however long the swing).
constexpr int kBlockTicks = 8;
using TickArray = Eigen::Array<double, kBlockTicks, 1>;
struct TickBlock {
  TickArray speed_gain, acceleration_gain;  // of h in v(tau) and a(tau) (header)
  TickArray vx, vy, ax, ay;                 // V0(tau), A0(tau)
  TickArray speed_limit, acceleration_limit;
};

// SwingFootTrajectory::heightState's z'^2 and z''^2 at times t: its operations, by packets.
// Its dx/dt = +-2 / duration (rising, falling) is +2 / duration here: negating a factor
// negates the rounded product exactly, and only the squares are kept, so they are those of
// heightState bit for bit (the test compares the reach with one built on heightState).
void heightRatesSquared(const SwingFootTrajectory& swing, const TickArray& t, TickArray& dz2,
                        TickArray& ddz2) {
  const double duration = swing.landingTime() - swing.liftOffTime();
  if (!(duration > 0.0)) {  // heightState's flat profile
    dz2.setZero();
    ddz2.setZero();
    return;
  }
  // std::clamp(s, 0, 1) is min(max(s, 0), 1), NaN included
  const TickArray s = ((t - swing.liftOffTime()) / duration).max(0.0).min(1.0);
  const TickArray x = 2.0 * s.min(1.0 - s);
  const TickArray df = x * x * (30.0 + x * (-60.0 + 30.0 * x));
  const TickArray ddf = x * (60.0 + x * (-180.0 + 120.0 * x));
  const double dxdt = 2.0 / duration;
  const TickArray dz = swing.stepHeight() * df * dxdt;
  const TickArray ddz = swing.stepHeight() * ddf * dxdt * dxdt;
  dz2 = dz * dz;
  ddz2 = ddz * ddz;
}

}  // namespace

SwingReach swingReach(const SwingFootTrajectory& swing, double t,
                      const Eigen::Vector2d& current_target, double max_speed,
                      double max_acceleration, double tick) {
  const DirectionTable& table = directionTable();
  SwingReach reach;
  const Eigen::Vector2d p0(swing.axisState(0, t)(0), swing.axisState(1, t)(0));
  const double T = swing.landingTime() - t;
  for (int k = 0; k < kDirections; ++k)
    reach.lower(k) = reach.upper(k) = table.direction(k).dot(current_target);
  if (!(T > 0.0) || !(tick > 0.0)) return reach;

  // The quintics with h = 0 (the foot brought to rest where it is): V0, A0.
  QuinticToRest base[2];
  for (int axis = 0; axis < 2; ++axis) {
    const Eigen::Vector3d state = swing.axisState(axis, t);
    base[axis].plan(state(0), state(1), state(2), state(0), T);
  }
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Intervals intervals;
  std::fill(intervals.low, intervals.low + kDirections, -kInf);
  std::fill(intervals.high, intervals.high + kDirections, kInf);
  const int ticks = static_cast<int>(std::ceil(T / tick - 1e-9));
  const double polygon_factor = table.polygon_factor;
  TickBlock block;
  TickArray tau, dz2, ddz2;
  for (int first = 1; first < ticks; first += kBlockTicks) {
    // A whole block even past the last tick: those are computed, never used.
    for (int i = 0; i < kBlockTicks; ++i) tau(i) = (first + i) * tick;
    const TickArray s = tau / T;
    block.speed_gain = s * s * (30.0 + s * (-60.0 + 30.0 * s)) / T;
    block.acceleration_gain = s * (60.0 + s * (-180.0 + 120.0 * s)) / (T * T);
    block.vx = base[0].velocity(tau);
    block.vy = base[1].velocity(tau);
    block.ax = base[0].acceleration(tau);
    block.ay = base[1].acceleration(tau);
    heightRatesSquared(swing, tau + t, dz2, ddz2);
    // The horizontal share of each limit once the vertical rate is known, shrunk so that the
    // polygon of the directions lies inside the circle (header).
    block.speed_limit = polygon_factor * (max_speed * max_speed - dz2).max(0.0).sqrt();
    block.acceleration_limit =
        polygon_factor * (max_acceleration * max_acceleration - ddz2).max(0.0).sqrt();
    const int n = std::min(kBlockTicks, ticks - first);
    // QuinticToRest::evaluate holds the foot at rest from the end on: a tick the rounding of
    // tau puts there (ticks much finer than the swing) is at rest too.
    for (int i = n - 1; i >= 0 && tau(i) >= T; --i)
      block.vx(i) = block.vy(i) = block.ax(i) = block.ay(i) = 0.0;
    for (int i = 0; i < n; ++i) {
      if (max_speed > 0.0)
        intersect(table, block.speed_gain(i), block.vx(i), block.vy(i), block.speed_limit(i),
                  intervals);
      if (max_acceleration > 0.0)
        intersect(table, block.acceleration_gain(i), block.ax(i), block.ay(i),
                  block.acceleration_limit(i), intervals);
    }
  }
  for (int k = 0; k < kDirections; ++k) {
    double& low = intervals.low[k];
    double& high = intervals.high[k];
    const double offset = table.direction(k).dot(p0);
    const double current = reach.lower(k) - offset;  // d_k . (current target - p0)
    if (low > high) low = high = current;
    // A direction no tick bounds (a limit off, no tick before the landing): far, but finite,
    // so that the QP's rows stay numbers.
    constexpr double kFar = 1e6;  // [m]
    low = std::max(low, current - kFar);
    high = std::min(high, current + kFar);
    reach.lower(k) = std::min(low, current) + offset;
    reach.upper(k) = std::max(high, current) + offset;
  }
  return reach;
}

}  // namespace wpg
