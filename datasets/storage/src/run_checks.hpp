#pragma once
// What a run dataset says about its walk beyond the trajectory itself, computed here and only
// written by run_dataset.cpp: the invariants of the `checks` group (libwpg's walk checks, the
// footsteps against the obstacles) and the summary statistics of the control chain's timing.
#include <vector>

#include <Eigen/Core>

#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/obstacles.hpp"
#include "wpg/walk_checks.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::datasets::detail {

// The landed footsteps against the obstacles, one entry per row of WalkTrajectory::footsteps.
struct FootstepObstacleChecks {
  // The step centres against the NMPC's obstacle constraint (eq. 18-19, the margin grown by the
  // sole radius), with libwpg's exact 2-D distance: min over obstacles of
  // sd(ankle, obstacle) - margin - parameters.obstacle_foot_radius [m] (or the paper's bound,
  // parameters.obstacle_distance_form: wpg::stepCentreClearance), >= 0 when the constraint
  // holds; the obstacle of that minimum (-1 without obstacles).
  std::vector<double> step_centre_clearance;
  std::vector<int> step_centre_clearance_obstacle;
  double min_step_centre_clearance = 0.0;  // +inf without footsteps
  // Minima of the caller's sole checks (FootstepClearances), when it gave them; +inf when
  // there are no footsteps.
  double min_step_clearance = 0.0;
  double min_step_foot_distance = 0.0;
};

FootstepObstacleChecks checkFootstepsAgainstObstacles(const WalkingParameters& parameters,
                                                      const std::vector<Obstacle>& obstacles,
                                                      const WalkTrajectory& trajectory,
                                                      const FootstepClearances* clearances);

// Everything the `checks` group holds.
struct RunChecks {
  WalkCheckReport walk;  // libwpg's invariants (CoP, step feasibility, yaw bound, speed)
  bool has_obstacles = false;
  FootstepObstacleChecks footsteps;  // filled when the scenario has obstacles
};

RunChecks computeRunChecks(const Scenario& scenario, const WalkTrajectory& trajectory,
                           const FootstepClearances* clearances);

// Sample statistics of a series of wall times [s]: all 0 when it is empty (std also when it has
// one entry); std with the n - 1 denominator.
struct TimeStatistics {
  double average = 0.0;
  double std_dev = 0.0;
  double min = 0.0;
  double max = 0.0;
};

TimeStatistics timeStatistics(const Eigen::VectorXd& times);

}  // namespace wpg::datasets::detail
