#include "wpg/walk_trajectory.hpp"

namespace wpg {

const char* iterationStatusName(IterationStatus status) {
  switch (status) {
    case IterationStatus::kSolved: return "solved";
    case IterationStatus::kRelaxed: return "relaxed";
    case IterationStatus::kFallback: return "fallback";
    case IterationStatus::kIterationLimit: return "iteration_limit";
    case IterationStatus::kFallen: return "fallen";
    case IterationStatus::kNotConverged: return "not_converged";
  }
  return "unknown";
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
