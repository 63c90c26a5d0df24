#pragma once
// The landings the swing foot can still reach with a bounded speed and acceleration (wpg's
// swing_reach family, a physical form of the landing bound of Sec. III-C3).
//
// At an NMPC sample t the swing foot (swing_foot_trajectory.hpp) is at p0 with velocity v0 and
// acceleration a0 (x, y); the replan of this sample joins it to the new landing F by a quintic
// that arrives at rest at the landing time, T = landing - t from now. With s = tau / T, that
// quintic's velocity and acceleration are affine in h = F - p0:
//     v(tau) = V0(tau) + h (30 s^2 - 60 s^3 + 30 s^4) / T,
//     a(tau) = A0(tau) + h (60 s - 180 s^2 + 120 s^3) / T^2,
// V0, A0 those of the quintic with h = 0. The foot's speed |(v_x, v_y, z')| <= max_speed and
// acceleration |(a_x, a_y, z'')| <= max_acceleration at every control tick tau of [0, T] (z
// from the height profile, which does not depend on F) are therefore kept by the 16-gon
// |d_k . v| <= cos(pi/16) sqrt(max_speed^2 - z'^2) for the eight directions d_k = (cos k pi/8,
// sin k pi/8), inscribed in that circle (an octagon of four directions, cos(pi/8) = 0.92, cost
// late pushes 8 % of the foot's reach), likewise for a: per direction k an interval of d_k . h,
// the intersection over
// the ticks, i.e. lower_k <= d_k . F <= upper_k. The landing of the previous sample (the plan
// the foot follows now) continues the same polynomial, which met the limits when it was
// planned: it is always inside (added when rounding leaves it out), so the rows never make the
// QP infeasible on their own. Before a swing's first plan the foot heads for no landing yet:
// the caller gives its lift-off pose, which a resting foot always reaches.
#include <Eigen/Core>

#include "wpg/swing_foot_trajectory.hpp"

namespace wpg {

struct SwingReach {
  static constexpr int kDirections = 8;
  using Bounds = Eigen::Matrix<double, kDirections, 1>;
  static Eigen::Vector2d direction(int k);  // (cos k pi/8, sin k pi/8)
  // The share of a limit that each direction may use: the polygon of the directions inside
  // the circle of the limit.
  static double polygonFactor();  // cos(pi / (2 kDirections))
  Bounds lower = Bounds::Zero(), upper = Bounds::Zero();  // [m]
};

// The reach of `swing` re-planned at time t (before the landing time) towards a landing
// (x, y), the foot's limits max_speed [m/s] and max_acceleration [m/s^2] (0: that limit off)
// checked every `tick` seconds; `current_target` = the landing the foot heads for now.
SwingReach swingReach(const SwingFootTrajectory& swing, double t,
                      const Eigen::Vector2d& current_target, double max_speed,
                      double max_acceleration, double tick);

}  // namespace wpg
