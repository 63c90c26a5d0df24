// The online generator as Python drives it (online_session.hpp).
#include "online_session.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "engine_calls.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/input_limits.hpp"
#include "wpg/walk_loop.hpp"

namespace wpg::python {
namespace {

// A number as %g writes it (1e+17, 3600, 0.05), as the messages of bad arguments give it.
std::string shortest(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// "(a, b, c)"
std::string numbers(const double* values, int count) {
  std::string text = "(";
  for (int i = 0; i < count; ++i) text += (i ? ", " : "") + shortest(values[i]);
  return text + ")";
}

OnlineWalkingGenerator makeGenerator(const datasets::Scenario& scenario) {
  try {
    scenario.walking.validate();
    return OnlineWalkingGenerator(scenario.walking, scenario.request.generator);
  } catch (const std::invalid_argument& e) {
    throw datasets::InputError(scenario.source_path + ": " + e.what());
  }
}

}  // namespace

OnlineSession::OnlineSession(datasets::Scenario scenario)
    : scenario_(std::move(scenario)), generator_(makeGenerator(scenario_)) {
  if (!scenario_.request.obstacles.empty()) generator_.setObstacles(scenario_.request.obstacles);
}

OnlineStep OnlineSession::step(const Eigen::Vector3d* command) {
  const std::lock_guard<std::mutex> lock(mutex_);
  return stepLocked(command);
}

double OnlineSession::runSteps(const Eigen::Vector3d& command, int steps) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < steps; ++i) stepLocked(&command);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

OnlineStep OnlineSession::stepLocked(const Eigen::Vector3d* command) {
  if (command) {
    if (!command->allFinite()) {
      throw datasets::InputError("command: expected 3 finite numbers (vx m/s, vy m/s, omega rad/s)");
    }
    generator_.setCommand(*command);
  }
  if (push_ticks_ > 0) {
    generator_.setPushAcceleration(push_acceleration_);
    --push_ticks_;
  }
  OnlineStep result;
  result.sample = generator_.step();
  result.status = generator_.lastIteration().status;
  result.fallen = generator_.fallen();
  result.landed = generator_.landed();
  if (result.sample.nmpc_sample && !result.fallen) {
    result.plan.emplace();
    generator_.patternGenerator().previewPlan(*result.plan);
  }
  return result;
}

double OnlineSession::time() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return generator_.time();
}

Eigen::Vector3d OnlineSession::command() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return generator_.command();
}

void OnlineSession::setObstacles(const std::string& yaml) {
  // The scenario's own reader: the same keys, checks and messages as an `obstacles:` list.
  const std::lock_guard<std::mutex> lock(mutex_);
  const datasets::Scenario with = datasets::loadScenarioText(
      resolvedScenarioText(scenario_), "set_obstacles", {"obstacles=" + yaml}, robotsDirectory());
  generator_.setObstacles(with.request.obstacles);
  scenario_.request.obstacles = with.request.obstacles;
}

void OnlineSession::push(const Eigen::Vector2d& force, double duration) {
  if (!force.allFinite() || force.cwiseAbs().maxCoeff() > datasets::kMaxPushForce) {
    throw datasets::InputError("push: force: expected 2 finite numbers of at most " +
                               shortest(datasets::kMaxPushForce) + " N in magnitude, got " +
                               numbers(force.data(), 2));
  }
  const double period = scenario_.walking.control_period;
  const double longest = kMaxControlPeriods * period;
  if (!(duration > 0.0 && duration <= longest)) {
    throw datasets::InputError("push: duration: expected a positive number of seconds, at most " +
                               shortest(longest) + " (the longest walk), got " +
                               shortest(duration));
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  push_acceleration_ = force / scenario_.request.robot_mass;
  push_ticks_ = static_cast<long>(std::ceil(duration / period - 1e-9));
}

void OnlineSession::reset(const Eigen::Vector3d& pose) {
  if (!pose.allFinite() || pose.cwiseAbs().maxCoeff() > datasets::kMaxLength) {
    throw datasets::InputError("reset: pose: expected (x, y, yaw) with x and y of at most " +
                               shortest(datasets::kMaxLength) + " m and yaw of at most " +
                               shortest(datasets::kMaxLength) + " rad in magnitude, got " +
                               numbers(pose.data(), 3));
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  generator_.reset(pose);
  push_ticks_ = 0;
}

}  // namespace wpg::python
