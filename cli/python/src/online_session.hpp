#pragma once
// The online generator as Python drives it: libwpg's OnlineWalkingGenerator built from a
// scenario (its walking parameters, generator settings, obstacles and robot mass), one control
// period per step(), with the command, the obstacles and pushes given between steps.
#include <mutex>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/online_walking_generator.hpp"

namespace wpg::python {

// One control period's outcome, copied out under the session's lock.
struct OnlineStep {
  ControlSample sample;
  // What the NMPC of this step predicted (nmpc_plan.hpp), at NMPC samples only.
  std::optional<NmpcPlan> plan;
  IterationStatus status = IterationStatus::kSolved;
  bool fallen = false, landed = false;
};

// Safe to share between threads: every call takes the session's own lock, so that one call
// (a step, a reset, a push) is done whole before another begins. The lock costs ~20 ns against
// the 5 ms of a control period; the Python bindings release the GIL while they wait for it.
class OnlineSession {
 public:
  // Throws datasets::InputError when the scenario's parameters do not validate.
  explicit OnlineSession(datasets::Scenario scenario);

  // One control period; the command (robot frame vx, vy, omega), when given, replaces the
  // current one from the next NMPC sample on (OnlineWalkingGenerator::setCommand).
  OnlineStep step(const Eigen::Vector3d* command);

  // `steps` control periods with `command`, under one lock; their wall time [s].
  double runSteps(const Eigen::Vector3d& command, int steps);

  // `yaml` is a YAML (or JSON) list of obstacles in the scenario's form (datasets/SCENARIOS.md);
  // InputError naming `obstacles[i].key` when one is wrong, the generator left unchanged.
  void setObstacles(const std::string& yaml);

  // A horizontal force [N] on the CoM for `duration` [s] from the next step on, converted to an
  // acceleration with the scenario's robot_mass as the scenario's pushes are. InputError, the
  // push before kept, unless the force is at most kMaxPushForce and the duration positive and
  // at most the longest walk (kMaxControlPeriods control periods).
  void push(const Eigen::Vector2d& force, double duration);

  // Standing again at `pose` (x, y, yaw), time 0, zero command, no push; obstacles kept.
  // InputError, nothing changed, unless x, y and yaw are at most kMaxLength in magnitude.
  void reset(const Eigen::Vector3d& pose);

  double time() const;
  Eigen::Vector3d command() const;
  double controlPeriod() const { return scenario_.walking.control_period; }

 private:
  mutable std::mutex mutex_;
  datasets::Scenario scenario_;
  OnlineWalkingGenerator generator_;
  Eigen::Vector2d push_acceleration_ = Eigen::Vector2d::Zero();
  long push_ticks_ = 0;  // control periods the push still acts on

  OnlineStep stepLocked(const Eigen::Vector3d* command);
};

}  // namespace wpg::python
