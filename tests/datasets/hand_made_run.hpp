#pragma once
// A hand-made walk result for the dataset writer's tests (no generateWalk: libwpg's NMPC is not
// needed to test what is written and read back).
#include <cstddef>

#include <Eigen/Core>

#include "wpg/walk_generator.hpp"

namespace wpg_test {

// Distinct values everywhere, so that a swapped column or a transposition shows.
inline wpg::WalkResult handMadeResult(std::size_t samples, std::size_t steps,
                                      std::size_t iterations, double offset = 0.0) {
  wpg::WalkResult result;
  wpg::WalkTrajectory& t = result.trajectory;
  for (std::size_t i = 0; i < samples; ++i) {
    const double k = static_cast<double>(i) + offset;
    t.time.push_back(0.005 * static_cast<double>(i));
    t.com.emplace_back(k + 0.1, k + 0.2, 0.814 + k * 1e-3);
    t.com_vel.emplace_back(k + 1.1, k + 1.2, k + 1.3);
    t.com_acc.emplace_back(k + 2.1, k + 2.2, k + 2.3);
    t.cop.emplace_back(k + 3.1, k + 3.2);
    t.left_foot.emplace_back(k + 4.1, k + 4.2, k + 4.3, k + 4.4);
    t.right_foot.emplace_back(k + 5.1, k + 5.2, k + 5.3, k + 5.4);
    t.free_flyer_yaw.push_back(k + 6.1);
    t.support.push_back(static_cast<wpg::SupportState>(i % 3));
  }
  for (std::size_t j = 0; j < steps; ++j) {
    wpg::Footstep step;
    step.landing_time = 0.8 * static_cast<double>(j) + offset;
    step.pose = Eigen::Vector3d(0.1 * j, j % 2 ? -0.095 : 0.095, 0.01 * j);
    step.side = j % 2 ? wpg::FootSide::kRight : wpg::FootSide::kLeft;
    t.footsteps.push_back(step);
  }
  for (std::size_t m = 0; m < iterations; ++m) {
    wpg::MpcIterationLog log;
    log.time = 0.1 * static_cast<double>(m);
    log.solve_time = 1e-3 * (1.0 + m) + offset;
    log.qp_iterations = static_cast<int>(3 + m);
    log.sqp_iterations = static_cast<int>(1 + m % 2);
    log.status = static_cast<wpg::IterationStatus>(m % 4);
    log.cost = 10.0 + m;
    log.slack[0] = m % 4 == 1 ? 0.01 : 0.0;
    log.slack[2] = m % 4 == 1 ? 0.02 + 1e-3 * m : 0.0;
    log.relaxed_families = m % 4 == 1 ? 0b101u : 0u;
    t.mpc.push_back(log);
  }
  t.constraint_families = {{"cop", "m", "balance"},
                           {"step_feasibility", "m", "kinematics"},
                           {"yaw_bound", "rad", "kinematics"},
                           {"obstacle", "m", "obstacle"}};
  result.success = true;
  result.message = "";
  return result;
}

}  // namespace wpg_test
