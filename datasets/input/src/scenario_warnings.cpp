// The loader's warnings (scenario_warnings.hpp).
#include "scenario_warnings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "wpg/gait_reach.hpp"

namespace wpg::datasets::detail {
namespace {

constexpr double kTurn = 2.0 * M_PI;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

// reference[i].v beyond the clamp applied before the NMPC (PatternGenerator::clampCommand):
// the walk follows the clamped value.
void commandWarnings(const Scenario& scenario, const Source& source,
                     std::vector<std::string>* warnings) {
  const WalkingParameters& w = scenario.walking;
  struct Component {
    const char* parameter;
    double limit;
    const char* unit;
  };
  const Component components[3] = {{"max_forward_velocity", w.max_forward_velocity, "m/s"},
                                   {"max_lateral_velocity", w.max_lateral_velocity, "m/s"},
                                   {"max_angular_velocity", w.max_angular_velocity, "rad/s"}};
  const double step = w.stepDuration();
  for (std::size_t i = 0; i < scenario.request.reference.size(); ++i) {
    const Eigen::Vector3d& v = scenario.request.reference[i].velocity;
    const std::string key = indexKey("reference", i) + ".v";
    bool turn_clamped = false;
    for (int c = 0; c < 3; ++c) {
      const Component& component = components[c];
      if (!(std::abs(v[c]) > component.limit)) continue;
      turn_clamped = turn_clamped || c == 2;
      const double clamped = std::copysign(component.limit, v[c]);
      warnings->push_back(source.warning(
          indexKey(key, static_cast<std::size_t>(c)),
          formatNumber(v[c]) + " " + component.unit + " is beyond walking." + component.parameter +
              " " + formatNumber(component.limit) + " " + component.unit +
              ": the command is clamped to " + formatNumber(clamped) + " " + component.unit));
    }
    // Inside the clamps, a command the steps cannot reach: no gait of the shortest steps the
    // timing allows, landing inside the feasibility polygon (gaitReach), walks it.
    const Eigen::Vector3d clamped(
        std::clamp(v[0], -w.max_forward_velocity, w.max_forward_velocity),
        std::clamp(v[1], -w.max_lateral_velocity, w.max_lateral_velocity),
        std::clamp(v[2], -w.max_angular_velocity, w.max_angular_velocity));
    const double shortest =
        (w.cadenceSingleSupport(w.cadenceCount() - 1) + w.double_support_samples) *
        w.sampling_period;
    const double turn = std::clamp(clamped.z(), -w.max_step_yaw_change / shortest,
                                   w.max_step_yaw_change / shortest);
    if (!gaitReachesCommand(clamped.head<2>(), turn, shortest, w.feasibility_x, w.feasibility_y)) {
      const double reach =
          gaitReach(clamped.head<2>(), turn, shortest, w.feasibility_x, w.feasibility_y);
      warnings->push_back(source.warning(
          key, "[" + formatNumber(v[0]) + ", " + formatNumber(v[1]) + ", " + formatNumber(v[2]) +
                   "] is beyond the reach of the gait (steps of " + number(shortest) +
                   " s inside walking.feasibility_x/y walk " +
                   std::to_string(static_cast<int>(100.0 * reach)) +
                   "% of it): the robot falls behind the command and may fall"));
    }
    // The yaw of a step is bounded (eq. 16, walking.max_step_yaw_change): a faster turn is
    // clamped to the bound per step.
    const double per_step =
        std::abs(std::clamp(v[2], -w.max_angular_velocity, w.max_angular_velocity)) * step;
    if (!turn_clamped && per_step > w.max_step_yaw_change) {
      warnings->push_back(source.warning(
          indexKey(key, 2),
          formatNumber(v[2]) + " rad/s turns " + number(per_step) + " rad per step of " +
              number(step) + " s, beyond walking.max_step_yaw_change " +
              formatNumber(w.max_step_yaw_change) + " rad: the walk turns at most " +
              number(w.max_step_yaw_change / step) + " rad/s"));
    }
  }
}

}  // namespace

std::vector<std::string> scenarioWarnings(const Scenario& scenario, double robot_com_height,
                                          const Source& source) {
  std::vector<std::string> warnings;
  commandWarnings(scenario, source, &warnings);

  // The LIPM height must be one the legs can hold: a little above the robot's own height
  // (half-sitting, knees bent) the legs no longer reach the feet, far below it the knees and
  // ankles pass their limits (measured on HRP-2: SCENARIOS.md, "Warnings").
  const double height = scenario.walking.com_height;
  const double lowest = kLowestComHeightRatio * robot_com_height;
  const double highest = kHighestComHeightRatio * robot_com_height;
  if (height < lowest || height > highest) {
    const bool centimetres = height >= 10.0 * highest;  // 81.4 for 0.814 m
    warnings.push_back(source.warning(
        "walking.com_height",
        formatNumber(height) + " m is outside the plausible CoM heights of robot '" +
            scenario.robot + "', " + number(lowest) + " to " + number(highest) + " m (" +
            number(kLowestComHeightRatio) + " to " + number(kHighestComHeightRatio) + " x its " +
            formatNumber(robot_com_height) + " m" + (centimetres ? "; a length in cm?" : "") +
            "): the walk uses " + formatNumber(height) + " m"));
  }

  if (scenario.goal.enabled && scenario.goal.goal.has_yaw &&
      std::abs(scenario.goal.goal.yaw) > kTurn) {
    const double yaw = scenario.goal.goal.yaw;
    warnings.push_back(source.warning(
        "goal.yaw", formatNumber(yaw) + " rad is more than a turn (angles are in rad; degrees? " +
                        number(yaw) + " degrees = " + number(yaw * M_PI / 180.0) +
                        " rad): the goal heading is " + number(std::remainder(yaw, kTurn)) +
                        " rad"));
  }
  const std::vector<Obstacle>& obstacles = scenario.request.obstacles;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    if (obstacles[i].type != ObstacleType::kBox || !(std::abs(obstacles[i].yaw) > kTurn)) continue;
    const double yaw = obstacles[i].yaw;
    warnings.push_back(source.warning(
        indexKey("obstacles", i) + ".yaw",
        formatNumber(yaw) + " rad is more than a turn (angles are in rad; degrees? " + number(yaw) +
            " degrees = " + number(yaw * M_PI / 180.0) + " rad): the box is turned by " +
            number(std::remainder(yaw, kTurn)) + " rad"));
  }
  if (scenario.goal.enabled && scenario.goal.goal.yaw_tolerance > M_PI) {
    warnings.push_back(source.warning(
        "goal.yaw_tolerance", formatNumber(scenario.goal.goal.yaw_tolerance) +
                                  " rad is more than half a turn (angles are in rad; degrees?): "
                                  "any heading is within it"));
  }
  return warnings;
}

}  // namespace wpg::datasets::detail
