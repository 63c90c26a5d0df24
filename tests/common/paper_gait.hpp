#pragma once
// The paper's literal gait cost and yaw bound, for tests whose situation was built with them
// (a problem that needs several Gauss-Newton iterations, a cold QP that needs more than two
// working-set updates, a push that makes the landing bound act). The defaults differ since
// today's (docs/formulation.md, "Straight walks and turning").
#include "wpg/walking_parameters.hpp"

namespace wpg_test {

// `w` with the yaw bound of the paper's text (0.05 rad, Sec. III-C), J1 on the instantaneous
// CoM velocity (eq. 5), J2 weighted by alpha (Sec. III-B) and the J1/J2 references chained
// from the support foot (eq. 8).
inline wpg::WalkingParameters paperGait(wpg::WalkingParameters w = wpg::WalkingParameters()) {
  w.max_step_yaw_change = 0.05;
  w.velocity_tracking = wpg::VelocityTracking::kInstantaneous;
  w.weight_yaw = w.weight_velocity;
  w.heading_reference = wpg::HeadingReference::kSupportFoot;
  return w;
}

}  // namespace wpg_test
