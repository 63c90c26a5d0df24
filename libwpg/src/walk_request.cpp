#include "wpg/walk_request.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "value_checks.hpp"

namespace wpg {

bool parseGeneratorAlgorithm(const std::string& name, GeneratorAlgorithm* out) {
  if (name == "nmpc") {
    *out = GeneratorAlgorithm::kNmpc;
  } else if (name == "lmpc") {
    *out = GeneratorAlgorithm::kLmpc;
  } else {
    return false;
  }
  return true;
}

const char* generatorAlgorithmName(GeneratorAlgorithm algorithm) {
  return algorithm == GeneratorAlgorithm::kLmpc ? "lmpc" : "nmpc";
}

Eigen::Vector3d WalkRequest::commandAt(double t) const {
  Eigen::Vector3d command = Eigen::Vector3d::Zero();
  // Commands are compared on a 1e-9 s grid so that a command at t = 1.0 applies at the NMPC
  // sample computed as 10 * 0.1.
  for (const VelocityCommand& entry : reference) {
    if (entry.t <= t + 1e-9) command = entry.velocity;
  }
  return command;
}

Eigen::Vector2d WalkRequest::pushAccelerationAt(double t) const {
  Eigen::Vector2d acceleration = Eigen::Vector2d::Zero();
  for (const Push& push : pushes) {
    if (t + 1e-9 >= push.t && t + 1e-9 < push.t + push.duration)
      acceleration += push.force / robot_mass;
  }
  return acceleration;
}

namespace {
[[noreturn]] void fail(const std::string& key, const std::string& expected, const std::string& got) {
  detail::failValue("", key, expected, got);
}
std::string str(double v) { return detail::formatValue(v); }
}  // namespace

void WalkRequest::validate() const {
  // Bounded: the walk is recorded every control period in memory (~0.3 kB a period).
  if (!std::isfinite(duration) || duration <= 0.0 || duration > kMaxWalkDuration)
    fail("duration", "a positive number of seconds, at most 3600", str(duration));
  if (!std::isfinite(robot_mass) || robot_mass <= 0.0)
    fail("mass", "a positive mass in kg", str(robot_mass));
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const std::string key = "reference[" + std::to_string(i) + "]";
    if (!std::isfinite(reference[i].t) || reference[i].t < 0.0)
      fail(key + ".t", "a time >= 0 s", str(reference[i].t));
    if (i > 0 && reference[i].t <= reference[i - 1].t)
      fail(key + ".t", "times in increasing order", str(reference[i].t));
    if (!reference[i].velocity.allFinite())
      fail(key + ".v", "three finite numbers [vx, vy, omega]", "a non-finite value");
  }
  for (std::size_t i = 0; i < pushes.size(); ++i) {
    const std::string key = "pushes[" + std::to_string(i) + "]";
    if (!std::isfinite(pushes[i].t) || pushes[i].t < 0.0)
      fail(key + ".t", "a time >= 0 s", str(pushes[i].t));
    if (!std::isfinite(pushes[i].duration) || pushes[i].duration <= 0.0)
      fail(key + ".duration", "a positive duration in s", str(pushes[i].duration));
    if (!pushes[i].force.allFinite()) fail(key + ".force", "two finite numbers [N]", "a non-finite value");
  }
  for (std::size_t i = 0; i < obstacles.size(); ++i)
    obstacles[i].validate("obstacles[" + std::to_string(i) + "]");
  generator.validate();
}

void GeneratorSettings::validate() const {
  const GeneratorSettings& g = *this;
  if (g.max_obstacles_in_qp < 0 || g.max_obstacles_in_qp > 32)
    fail("generator.max_obstacles_in_qp", "an integer in [0, 32]", str(g.max_obstacles_in_qp));
  if (!(g.obstacle_reach > 0.0) || !std::isfinite(g.obstacle_reach))
    fail("generator.obstacle_reach", "a positive distance in m", str(g.obstacle_reach));
  if (!(g.max_detour > 0.0) || !std::isfinite(g.max_detour))
    fail("generator.max_detour", "a positive distance in m", str(g.max_detour));
  // Bounded work: a sample never iterates without end.
  if (g.sqp_iterations < 0 || g.sqp_iterations > kMaxSqpIterations)
    fail("generator.sqp_iterations", "an integer in [0, 1000]", str(g.sqp_iterations));
  if (g.max_sqp_iterations < 1 || g.max_sqp_iterations > kMaxSqpIterations)
    fail("generator.max_sqp_iterations", "an integer in [1, 1000]", str(g.max_sqp_iterations));
  if (!(g.sqp_tolerance > 0.0) || !std::isfinite(g.sqp_tolerance))
    fail("generator.sqp_tolerance", "a positive number", str(g.sqp_tolerance));
  if (g.max_qp_iterations < 1 || g.max_qp_iterations > kMaxQpIterations)
    fail("generator.max_qp_iterations", "an integer in [1, 100000]", str(g.max_qp_iterations));
  if (!(g.fall_capture_distance > 0.0) || !std::isfinite(g.fall_capture_distance))
    fail("generator.fall_capture_distance", "a positive distance in m", str(g.fall_capture_distance));
  if (!(g.slack_weight > 0.0) || !std::isfinite(g.slack_weight))
    fail("generator.slack_weight", "a positive number", str(g.slack_weight));
  if (g.blocked_window_cycles < 1 || g.blocked_window_cycles > kMaxBlockedWindowCycles)
    fail("generator.blocked_window_cycles", "an integer in [1, 100] (gait cycles)",
         str(g.blocked_window_cycles));
  if (!(g.blocked_progress > 0.0 && g.blocked_progress < 1.0))
    fail("generator.blocked_progress", "a ratio in (0, 1)", str(g.blocked_progress));
}

}  // namespace wpg
