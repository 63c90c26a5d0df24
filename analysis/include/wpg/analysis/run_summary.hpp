#pragma once
// What one generated walk did, in the few numbers the `wpg run` summary prints: distance
// walked, steps, duration, NMPC iterations per status, solve times.
#include <cstddef>
#include <vector>

#include "wpg/walk_trajectory.hpp"

namespace wpg::analysis {

struct StatusCount {
  IterationStatus status = IterationStatus::kSolved;
  std::size_t count = 0;  // NMPC iterations with this status
};

struct RunSummary {
  double path_length = 0.0;   // [m] length of the horizontal CoM path
  double displacement = 0.0;  // [m] horizontal distance from the first CoM sample to the last
  std::size_t steps = 0;      // landed footsteps, the two initial feet not counted
  double duration = 0.0;      // [s] covered by the samples (walkDuration)
  std::size_t nmpc_iterations = 0;
  // The statuses that occurred, by increasing status code, each with its count (the counts
  // sum to nmpc_iterations).
  std::vector<StatusCount> status_counts;
  // [s] wall time per NMPC iteration, median and maximum over the iterations; 0 without any.
  double median_solve_time = 0.0;
  double max_solve_time = 0.0;
};

RunSummary summarizeRun(const WalkTrajectory& trajectory);

// [s] time of the last sample minus time of the first; 0 for an empty trajectory.
double walkDuration(const WalkTrajectory& trajectory);

}  // namespace wpg::analysis
