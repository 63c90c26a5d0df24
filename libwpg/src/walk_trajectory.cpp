#include "wpg/walk_trajectory.hpp"

#include <algorithm>

namespace wpg {

const char* iterationStatusName(IterationStatus status) {
  switch (status) {
    case IterationStatus::kSolved: return "solved";
    case IterationStatus::kRelaxedObstacle: return "relaxed_obstacle";
    case IterationStatus::kFallback: return "fallback";
    case IterationStatus::kIterationLimit: return "iteration_limit";
    case IterationStatus::kFallen: return "fallen";
    case IterationStatus::kNotConverged: return "not_converged";
    case IterationStatus::kRelaxedKinematics: return "relaxed_kinematics";
    case IterationStatus::kRelaxedBalance: return "relaxed_balance";
  }
  return "unknown";
}

bool iterationStatusFailsWalk(IterationStatus status) {
  return status != IterationStatus::kSolved && status != IterationStatus::kRelaxedObstacle;
}

double MpcIterationLog::maxSlack() const {
  double largest = 0.0;
  for (double s : slack) largest = std::max(largest, s);
  return largest;
}

void WalkTrajectory::reserve(std::size_t samples, std::size_t iterations) {
  time.reserve(samples);
  com.reserve(samples);
  com_vel.reserve(samples);
  com_acc.reserve(samples);
  cop.reserve(samples);
  left_foot.reserve(samples);
  right_foot.reserve(samples);
  free_flyer_yaw.reserve(samples);
  support.reserve(samples);
  mpc.reserve(iterations);
}

}  // namespace wpg
