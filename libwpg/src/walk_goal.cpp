#include "wpg/walk_goal.hpp"

#include <cmath>

#include "value_checks.hpp"

namespace wpg {
namespace {

void requirePositive(double value, const std::string& key, const std::string& expected) {
  detail::requireValue(std::isfinite(value) && value > 0.0, "", key, expected, value);
}

}  // namespace

void GoalRequest::validate() const {
  if (!enabled) return;
  if (!goal.position.allFinite())
    detail::failValue("", "goal.position", "[x, y] in m (2 finite numbers)", "a non-finite value");
  detail::requireValue(std::isfinite(goal.yaw), "", "goal.yaw", "an angle in rad", goal.yaw);
  requirePositive(goal.tolerance, "goal.tolerance", "a positive distance in m");
  requirePositive(goal.yaw_tolerance, "goal.yaw_tolerance", "a positive angle in rad");
  detail::requireValue(std::isfinite(planner.time_limit) && planner.time_limit > 0.0 &&
                           planner.time_limit <= kMaxPlannerTimeLimit,
                       "", "planner.time_limit", "a positive time in s, at most 600",
                       planner.time_limit);
  detail::requireValue(planner.max_iterations > 0, "", "planner.max_iterations",
                       "a positive number of iterations", planner.max_iterations);
  detail::requireValue(std::isfinite(planner.robot_radius) && planner.robot_radius >= 0.0, "",
                       "planner.robot_radius", "a radius >= 0 in m (0: from the robot)",
                       planner.robot_radius);
  requirePositive(planner.replan_distance, "planner.replan_distance", "a positive distance in m");
  detail::requireValue(std::isfinite(planner.sensing_range) && planner.sensing_range >= 0.0, "",
                       "planner.sensing_range", "a distance >= 0 in m", planner.sensing_range);
  requirePositive(planner.lookahead, "planner.lookahead", "a positive distance in m");
  if (planner.has_bounds) {
    const Eigen::Vector4d& b = planner.bounds;
    if (!b.allFinite() || !(b[1] > b[0]) || !(b[3] > b[2])) {
      detail::failValue("", "planner.bounds", "[x_min, x_max, y_min, y_max] with min < max",
                        "[" + detail::formatValue(b[0]) + ", " + detail::formatValue(b[1]) + ", " +
                            detail::formatValue(b[2]) + ", " + detail::formatValue(b[3]) + "]");
    }
  }
}

double defaultRobotRadius(double stance_width, double foot_length, double foot_width) {
  return 0.5 * stance_width + 0.5 * std::hypot(foot_length, foot_width);
}

}  // namespace wpg
