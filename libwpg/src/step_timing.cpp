#include "wpg/step_timing.hpp"

#include <cmath>

#include "wpg/gait_reach.hpp"

namespace wpg {

CadenceChoice::CadenceChoice(const WalkingParameters& parameters) : parameters_(parameters) {}

bool CadenceChoice::reaches(const Eigen::Vector3d& command, int single_support) const {
  const WalkingParameters& w = parameters_;
  const double step_duration = (single_support + w.double_support_samples) * w.sampling_period;
  // The yaw bound (eq. 16) caps the turn of a step; the reach takes each step's turn as given.
  if (std::abs(command.z()) * step_duration > w.max_step_yaw_change) return false;
  return gaitReach(command.head<2>(), command.z(), step_duration, w.feasibility_x,
                   w.feasibility_y, /*regular=*/true) >= 1.0;
}

int CadenceChoice::choose(const Eigen::Vector3d& command) {
  const WalkingParameters& w = parameters_;
  if (command == command_) return cadence_;
  command_ = command;
  cadence_ = 0;
  // A zero velocity (standing, stepping or turning in place) keeps the paper's steps.
  if (w.cadenceCount() == 1 || command.head<2>().cwiseAbs().maxCoeff() < 1e-12) return cadence_;
  const int last = w.cadenceCount() - 1;
  while (cadence_ < last && !reaches(command, w.cadenceSingleSupport(cadence_))) ++cadence_;
  return cadence_;
}

}  // namespace wpg
