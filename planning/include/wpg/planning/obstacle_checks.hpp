#pragma once
// After a run: every landed footstep checked with FCL against every obstacle. Two
// numbers per step, because the NMPC and the robot see obstacles differently:
//  - the step centre (ankle) against the obstacle grown by its margin and by the sole radius
//    obstacle_foot_radius: the constraint the NMPC enforces (eq. 18-19 generalized:
//    d(f) - m - obstacle_foot_radius >= 0; with obstacle_distance_form paper, eq. (18) as
//    written: |f - c| - sqrt(R^2 + m^2) >= 0 for a circle, d(f) - m >= 0 otherwise:
//    wpg::stepCentreClearance), so it must never be negative;
//  - the sole rectangle against the obstacle grown by its margin: what the foot really
//    occupies. With obstacle_foot_radius below the sole's half diagonal (0.129 m for HRP-2;
//    the paper's point footsteps: 0) it can be negative while the centre constraint holds; and
//    against the obstacle itself (margin not counted), which is negative only when the foot
//    touches the obstacle.
// The columns match the dataset's /runs/<name>/checks/step_* (datasets/SCHEMA.md), so that the
// caller passes them to wpg::datasets::writeRunDataset as they are.
#include <vector>

#include "wpg/planning/world.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::planning {

// One entry per row of WalkTrajectory::footsteps (the two initial feet included). In a world
// without obstacles the distances are +infinity and the indices -1.
struct FootstepObstacleReport {
  // min over obstacles of signed_distance(sole rectangle, obstacle) - margin [m]
  std::vector<double> clearance;
  std::vector<int> clearance_obstacle;  // the obstacle of that minimum
  // min over obstacles of signed_distance(sole rectangle, obstacle) [m], margin not counted
  std::vector<double> foot_distance;
  // min over obstacles of signed_distance(ankle point, obstacle) - margin -
  // parameters.obstacle_foot_radius [m] (the paper's bound instead with obstacle_distance_form
  // paper: wpg::stepCentreClearance): the margin of the NMPC's constraint on the step centre,
  // >= 0 when it holds
  std::vector<double> centre_clearance;
  std::vector<int> centre_clearance_obstacle;

  // Summaries (the same minima over all steps; +infinity and -1 when there is nothing).
  double min_clearance = 0.0;
  int min_clearance_step = -1;
  double min_foot_distance = 0.0;
  int min_foot_distance_step = -1;
  double min_centre_clearance = 0.0;
  int min_centre_clearance_step = -1;
};

// The sole is parameters.foot_length x parameters.foot_width, centred on the ankle.
FootstepObstacleReport checkFootsteps(const World& world, const wpg::WalkingParameters& parameters,
                                      const wpg::WalkTrajectory& trajectory);

}  // namespace wpg::planning
