#pragma once
// wpg's own extensions, registered by name in the registry (extension_registry.hpp) and so
// usable from scenario files (`constraints:`, `costs:`; datasets/SCENARIOS.md):
//
//   name       kind               parameters [unit]             rows / residuals
//   corridor   constraint family  left, right, cop_margin [m]   2 per CoP sample, 2 per step
//   look_at    cost term          x, y [m], weight [1/rad^2]    1 per previewed step
#include <memory>

#include "wpg/nmpc/extension_registry.hpp"

namespace wpg {

// Corridor between two walls along the world x axis, y = left and y = right (left > right):
// every previewed CoP sample and every free previewed step centre stays between them. Rows:
// per CoP sample j, z_y - (left - m) <= 0 then right + m - z_y <= 0 (m: cop_margin); then per
// previewed step i,
// F_y - left <= 0 then right - F_y <= 0 (a fixed step's rows are inactive, g = -1). Linear in
// U (z_y = Pzs c_hat_y + Pzu jerk_y, eq. 3). Relaxation group: obstacle. A wall is an
// obstacle: an infeasible QP gives it up before the feet's kinematics and the balance, and
// its slack is penalized, so the robot stops at the wall rather than step through it.
struct CorridorRows {
  static int count(int horizon, int steps) { return 2 * horizon + 2 * steps; }
  static int copRow(int sample, bool left) { return 2 * sample + (left ? 0 : 1); }
  static int stepRow(int horizon, int step, bool left) {
    return 2 * horizon + 2 * step + (left ? 0 : 1);
  }
};
// The CoP rows hold it cop_margin [m] inside the walls (the CoP between two NMPC samples bulges
// past the samples' line: 1.3 mm measured on corridor.yaml without a margin).
constexpr double kCorridorCopMargin = 0.005;
std::unique_ptr<ConstraintFamily> makeCorridorConstraint(double left, double right,
                                                         double cop_margin = kCorridorCopMargin);
// Parameters left, right and cop_margin [m]; the check refuses left - right below the robot's least step
// width (WalkingParameters::leastStepWidth, wider than its sole): no two feet fit between;
// and walls that leave either start foot no room for its first step.
ConstraintFamilySpec corridorConstraintSpec();

// Keep each previewed step's yaw towards the point (x, y): residual sqrt(weight) *
// wrap(theta_i - atan2(y - F_y,i, x - F_x,i)), so the term adds weight/2 e_i^2 to the cost
// beside J2 (weight_yaw, 100 for HRP-2). Steps nearer the point than the robot's sole length
// have no heading towards it: their residual is 0.
std::unique_ptr<CostTerm> makeLookAtCost(double x, double y, double weight);
// Parameters x, y [m] and weight [1/rad^2] (default 100); the check refuses a point nearer the
// walk's start than the robot's sole length.
CostTermSpec lookAtCostSpec();

}  // namespace wpg
