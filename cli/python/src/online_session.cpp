// The online generator as Python drives it (online_session.hpp).
#include "online_session.hpp"

#include <cmath>
#include <stdexcept>

#include "engine_calls.hpp"
#include "wpg/datasets/input/input_error.hpp"

namespace wpg::python {
namespace {

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

const ControlSample& OnlineSession::step(const Eigen::Vector3d* command) {
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
  return generator_.step();
}

void OnlineSession::setObstacles(const std::string& yaml) {
  // The scenario's own reader: the same keys, checks and messages as an `obstacles:` list.
  const datasets::Scenario with = datasets::loadScenarioText(
      scenario_.resolved_yaml, "set_obstacles", {"obstacles=" + yaml}, robotsDirectory());
  generator_.setObstacles(with.request.obstacles);
  scenario_.request.obstacles = with.request.obstacles;
}

void OnlineSession::push(const Eigen::Vector2d& force, double duration) {
  if (!force.allFinite()) throw datasets::InputError("push: force: expected 2 finite numbers [N]");
  if (!std::isfinite(duration) || duration <= 0.0) {
    throw datasets::InputError("push: duration: expected a positive number of seconds");
  }
  const double period = scenario_.walking.control_period;
  push_acceleration_ = force / scenario_.request.robot_mass;
  push_ticks_ = static_cast<long>(std::ceil(duration / period - 1e-9));
}

void OnlineSession::reset(const Eigen::Vector3d& pose) {
  if (!pose.allFinite()) throw datasets::InputError("reset: pose: expected 3 finite numbers");
  generator_.reset(pose);
  push_ticks_ = 0;
}

}  // namespace wpg::python
