#pragma once
// The online generator as Python drives it: libwpg's OnlineWalkingGenerator built from a
// scenario (its walking parameters, generator settings, obstacles and robot mass), one control
// period per step(), with the command, the obstacles and pushes given between steps.
#include <string>

#include <Eigen/Core>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/online_walking_generator.hpp"

namespace wpg::python {

class OnlineSession {
 public:
  // Throws datasets::InputError when the scenario's parameters do not validate.
  explicit OnlineSession(datasets::Scenario scenario);

  // One control period; the command (robot frame vx, vy, omega), when given, replaces the
  // current one from the next NMPC sample on (OnlineWalkingGenerator::setCommand).
  const ControlSample& step(const Eigen::Vector3d* command);

  // `yaml` is a YAML (or JSON) list of obstacles in the scenario's form (datasets/SCENARIOS.md);
  // InputError naming `obstacles[i].key` when one is wrong, the generator left unchanged.
  void setObstacles(const std::string& yaml);

  // A horizontal force [N] on the CoM for `duration` [s] from the next step on, converted to an
  // acceleration with the scenario's robot_mass as the scenario's pushes are.
  void push(const Eigen::Vector2d& force, double duration);

  // Standing again at `pose` (x, y, yaw), time 0, zero command, no push; obstacles kept.
  void reset(const Eigen::Vector3d& pose);

  const OnlineWalkingGenerator& generator() const { return generator_; }
  const datasets::Scenario& scenario() const { return scenario_; }

 private:
  datasets::Scenario scenario_;
  OnlineWalkingGenerator generator_;
  Eigen::Vector2d push_acceleration_ = Eigen::Vector2d::Zero();
  long push_ticks_ = 0;  // control periods the push still acts on
};

}  // namespace wpg::python
