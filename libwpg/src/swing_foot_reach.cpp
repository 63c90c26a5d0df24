#include "wpg/swing_foot_reach.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace wpg {

namespace {

// The directions' cosines and sines, computed once: swingReach asks for them for every tick
// of the rest of the swing at every NMPC iteration (a batch spent 11 % of its time in sincos).
struct DirectionTable {
  std::array<Eigen::Vector2d, SwingReach::kDirections> d;
  double polygon_factor;
  DirectionTable() : polygon_factor(std::cos(M_PI / (2.0 * SwingReach::kDirections))) {
    for (int k = 0; k < SwingReach::kDirections; ++k) {
      const double angle = k * (M_PI / SwingReach::kDirections);
      d[static_cast<std::size_t>(k)] = Eigen::Vector2d(std::cos(angle), std::sin(angle));
    }
  }
};

const DirectionTable& directionTable() {
  static const DirectionTable table;
  return table;
}

}  // namespace

Eigen::Vector2d SwingReach::direction(int k) {
  return directionTable().d[static_cast<std::size_t>(k)];
}

double SwingReach::polygonFactor() { return directionTable().polygon_factor; }

namespace {

// The horizontal share of a limit on the foot's 3-D vector once its vertical part is known,
// shrunk (polygon_factor) so that the polygon of the directions lies inside the circle
// (header).
double horizontalLimit(double polygon_factor, double limit, double vertical) {
  return polygon_factor * std::sqrt(std::max(limit * limit - vertical * vertical, 0.0));
}

// Whether a tick's gain makes it depend on the landing (else intersect() would learn nothing).
bool bounds(double gain) { return !(std::abs(gain) < 1e-12); }

// lo <= gain h + offset <= hi as an interval of h, intersected into [low, high]; bounds(gain).
void intersect(double gain, double offset, double limit, double& low, double& high) {
  double a = (-limit - offset) / gain, b = (limit - offset) / gain;
  if (gain < 0.0) std::swap(a, b);
  low = std::max(low, a);
  high = std::min(high, b);
}

}  // namespace

SwingReach swingReach(const SwingFootTrajectory& swing, double t,
                      const Eigen::Vector2d& current_target, double max_speed,
                      double max_acceleration, double tick) {
  // The table itself, not direction(k): this loop asks for it 16 times per tick of the rest
  // of the swing at every NMPC iteration, and each call checked the static's guard.
  const DirectionTable& table = directionTable();
  const auto& directions = table.d;
  SwingReach reach;
  const Eigen::Vector2d p0(swing.axisState(0, t)(0), swing.axisState(1, t)(0));
  const double T = swing.landingTime() - t;
  for (int k = 0; k < SwingReach::kDirections; ++k)
    reach.lower(k) = reach.upper(k) = directions[static_cast<std::size_t>(k)].dot(current_target);
  if (!(T > 0.0) || !(tick > 0.0)) return reach;

  // The quintics with h = 0 (the foot brought to rest where it is): V0, A0.
  QuinticToRest base[2];
  for (int axis = 0; axis < 2; ++axis) {
    const Eigen::Vector3d state = swing.axisState(axis, t);
    base[axis].plan(state(0), state(1), state(2), state(0), T);
  }
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double low[SwingReach::kDirections], high[SwingReach::kDirections];
  std::fill(low, low + SwingReach::kDirections, -kInf);
  std::fill(high, high + SwingReach::kDirections, kInf);
  const int ticks = static_cast<int>(std::ceil(T / tick - 1e-9));
  for (int j = 1; j < ticks; ++j) {
    const double tau = j * tick, s = tau / T;
    const double speed_gain = s * s * (30.0 + s * (-60.0 + 30.0 * s)) / T;
    const double acceleration_gain = s * (60.0 + s * (-180.0 + 120.0 * s)) / (T * T);
    const Eigen::Vector3d x = base[0].evaluate(tau), y = base[1].evaluate(tau);
    const Eigen::Vector3d z = swing.heightState(t + tau);
    const double speed_limit = horizontalLimit(table.polygon_factor, max_speed, z(1));
    const double acceleration_limit =
        horizontalLimit(table.polygon_factor, max_acceleration, z(2));
    const bool speed_bounds = max_speed > 0.0 && bounds(speed_gain);
    const bool acceleration_bounds = max_acceleration > 0.0 && bounds(acceleration_gain);
    for (int k = 0; k < SwingReach::kDirections; ++k) {
      const Eigen::Vector2d& d = directions[static_cast<std::size_t>(k)];
      if (speed_bounds)
        intersect(speed_gain, d.x() * x(1) + d.y() * y(1), speed_limit, low[k], high[k]);
      if (acceleration_bounds)
        intersect(acceleration_gain, d.x() * x(2) + d.y() * y(2), acceleration_limit, low[k],
                  high[k]);
    }
  }
  for (int k = 0; k < SwingReach::kDirections; ++k) {
    const double offset = directions[static_cast<std::size_t>(k)].dot(p0);
    const double current = reach.lower(k) - offset;  // d_k . (current target - p0)
    if (low[k] > high[k]) low[k] = high[k] = current;
    // A direction no tick bounds (a limit off, no tick before the landing): far, but finite,
    // so that the QP's rows stay numbers.
    constexpr double kFar = 1e6;  // [m]
    low[k] = std::max(low[k], current - kFar);
    high[k] = std::min(high[k], current + kFar);
    reach.lower(k) = std::min(low[k], current) + offset;
    reach.upper(k) = std::max(high[k], current) + offset;
  }
  return reach;
}

}  // namespace wpg
