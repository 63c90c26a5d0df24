#pragma once
// The walking parameters of the walks to a goal in the planning tests: J1 on the mean CoM
// velocity of an 8-sample window, the references relative to the commanded heading and the
// authors' yaw bound (0.17 rad).
#include "wpg/walking_parameters.hpp"

namespace wpg_test {

inline wpg::WalkingParameters goalWalking() {
  wpg::WalkingParameters parameters;
  parameters.velocity_window_samples = 8;
  parameters.heading_reference = wpg::HeadingReference::kCommand;
  parameters.max_step_yaw_change = 0.17;
  return parameters;
}

}  // namespace wpg_test
