#pragma once
// The adaptive step timing's choice (walking.step_timing: adaptive; docs/command_tracking.md,
// "Step timing"): which cadence, i.e. single support, the next steps take for a command. The
// paper's steps (Sec. V-A: 0.7 s single + 0.1 s double support for HRP-2) walk every command
// a regular two-step gait of that timing reaches inside the step feasibility polygon (eq. 14);
// a command beyond it (HRP-2 walks at most 0.125 m/s sideways with 0.8 s steps) is walked
// with the slowest shorter step that reaches it. The PatternGenerator asks at every sample and
// the gait scheduler applies the answer at the next landing (gait_scheduler.hpp).
#include <Eigen/Core>

#include "wpg/walking_parameters.hpp"

namespace wpg {

class CadenceChoice {
 public:
  explicit CadenceChoice(const WalkingParameters& parameters);

  // The cadence c (WalkingParameters::cadenceSingleSupport(c) samples of single support; 0
  // the parameters' own, the slowest) for the clamped robot-frame `command` [vx, vy, omega]:
  // the slowest whose regular gait (gaitReach, equal steps forward) reaches it, lambda >= 1,
  // turning at most max_step_yaw_change per step; the fastest when none does. Always 0 with
  // fixed timing or a zero velocity (standing, stepping or turning in place). Recomputed only
  // when the command changes (a few microseconds); does not allocate.
  int choose(const Eigen::Vector3d& command);

  // Whether steps of `single_support` samples reach `command` (as choose() decides).
  bool reaches(const Eigen::Vector3d& command, int single_support) const;

 private:
  WalkingParameters parameters_;
  Eigen::Vector3d command_ = Eigen::Vector3d::Zero();
  int cadence_ = 0;
};

}  // namespace wpg
