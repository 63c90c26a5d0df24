#pragma once
// The checks a run dataset holds (its `checks` group, datasets/SCHEMA.md): libwpg's walk checks
// (the invariants of the walk) and the landed footsteps against the obstacles. Computed from the
// walk by the writer (run_dataset.cpp), and by whoever wants them without a file (the engine's
// run result). Not to be confused with the input checks (datasets/input: InputError), libwpg's
// walk checks alone (wpg/walk_checks.hpp) and a stored run's consistency with its scenario
// (stored_run_consistency.hpp).
#include <vector>

#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/obstacles.hpp"
#include "wpg/walk_checks.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::datasets {

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
struct DatasetChecks {
  WalkCheckReport walk;  // libwpg's invariants (CoP, step feasibility, yaw bound, speed)
  bool has_obstacles = false;
  FootstepObstacleChecks footsteps;  // filled when the scenario has obstacles
};

// `clearances`: the FCL world's sole clearances (may be null: the step centres only).
DatasetChecks computeDatasetChecks(const Scenario& scenario, const WalkTrajectory& trajectory,
                                   const FootstepClearances* clearances);

}  // namespace wpg::datasets
