// Eigen's own malloc guard around a warmed-up NMPC iteration (none may allocate). The guard is
// an eigen_assert, compiled out in Release: this executable builds libwpg's sources again
// with assertions on and EIGEN_RUNTIME_NO_MALLOC, so any Eigen heap allocation inside the
// guarded loop aborts the test. (tests/libwpg/test_nmpc_allocation.cpp counts every malloc
// of the Release library as well.)
#ifndef EIGEN_RUNTIME_NO_MALLOC
#error "this test must be compiled with EIGEN_RUNTIME_NO_MALLOC"
#endif
#ifdef NDEBUG
#error "this test must be compiled with assertions on"
#endif

#include <gtest/gtest.h>

#include "wpg/lipm_prediction.hpp"
#include "wpg/pattern_generator.hpp"

namespace {

void walk(wpg::GeneratorAlgorithm algorithm, const Eigen::Vector3d& command) {
  wpg::WalkingParameters parameters;
  parameters.max_step_yaw_change = 0.17;
  wpg::GeneratorSettings settings;
  settings.algorithm = algorithm;
  const std::vector<wpg::Obstacle> obstacles = [] {
    wpg::Obstacle circle;
    circle.center = Eigen::Vector2d(3.0, 1.0);
    circle.radius = 0.2;
    circle.margin = 0.2;
    wpg::Obstacle box;
    box.type = wpg::ObstacleType::kBox;
    box.center = Eigen::Vector2d(2.5, -1.0);
    box.size = Eigen::Vector2d(0.3, 0.4);
    box.margin = 0.1;
    return std::vector<wpg::Obstacle>{circle, box};
  }();
  wpg::PatternGenerator generator(parameters, settings);
  generator.setObstacles(obstacles);
  Eigen::Vector3d com_x = generator.comX(), com_y = generator.comY();
  auto sample = [&](int k) {
    generator.update(k * parameters.sampling_period, command);
    for (int i = 0; i < 20; ++i) {
      wpg::integrateJerk(com_x, generator.plan().jerk_x, parameters.control_period);
      wpg::integrateJerk(com_y, generator.plan().jerk_y, parameters.control_period);
    }
    generator.advance(com_x, com_y);
  };
  int k = 0;
  for (; k < 30; ++k) sample(k);  // start, reach steady walking (every buffer touched)
  Eigen::internal::set_is_malloc_allowed(false);
  for (; k < 70; ++k) sample(k);  // five steps: every phase pattern
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(generator.lastSolve().status, wpg::IterationStatus::kSolved);
}

TEST(EigenMallocGuard, NmpcIterationsDoNotAllocate) {
  walk(wpg::GeneratorAlgorithm::kNmpc, {0.2, 0.0, 0.0});
  walk(wpg::GeneratorAlgorithm::kNmpc, {0.2, 0.0, 0.2});
}

TEST(EigenMallocGuard, LmpcIterationsDoNotAllocate) {
  walk(wpg::GeneratorAlgorithm::kLmpc, {0.2, 0.0, 0.2});
}

TEST(EigenMallocGuard, TheGuardIsArmed) {
  // A death test that an Eigen allocation under the guard does abort: proves the check runs.
  EXPECT_DEATH(
      {
        Eigen::internal::set_is_malloc_allowed(false);
        Eigen::VectorXd v(100);
        v.setZero();
      },
      "");
}

}  // namespace
