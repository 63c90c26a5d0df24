// What each NMPC iteration predicts (nmpc_plan.hpp, WalkTrajectory::plans): the executed CoM
// is the first previewed sample's prediction, the landed steps are the previewed steps 0 of
// the iterations before their landing at their landing times, and the rows are counted per
// family.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstddef>

#include "wpg/walk_generator.hpp"

namespace {

using Eigen::Vector3d;

// A start, a turn and a change of speed (the adaptive step timing switches cadence).
wpg::WalkResult turningWalk(bool record_plan = true) {
  wpg::WalkRequest request;
  request.duration = 12.0;
  request.reference = {{0.0, Vector3d::Zero()},
                       {1.0, Vector3d(0.2, 0.05, 0.0)},
                       {5.0, Vector3d(0.5, 0.0, 0.2)},
                       {9.0, Vector3d(0.1, 0.0, 0.0)}};
  request.generator.record_plan = record_plan;
  return wpg::generateWalk(wpg::WalkingParameters(), request);
}

TEST(NmpcPlan, ExecutedComIsTheFirstPreviewedSample) {
  const wpg::WalkResult walk = turningWalk();
  const wpg::WalkTrajectory& tr = walk.trajectory;
  const wpg::PlanLog& plans = tr.plans;
  ASSERT_TRUE(walk.success) << walk.message;
  ASSERT_EQ(plans.size(), tr.mpc.size());
  const int N = plans.max_samples;
  const std::size_t per_iteration = tr.size() / tr.mpc.size();  // control periods, + closing
  ASSERT_EQ(per_iteration, 20u);
  double largest = 0.0;
  int shorter = 0;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    ASSERT_GT(plans.samples[i], 0);
    ASSERT_LE(plans.samples[i], N);
    shorter += plans.samples[i] < N;
    const std::size_t executed = (i + 1) * per_iteration;  // t_i + T
    ASSERT_LT(executed, tr.size());
    for (int axis = 0; axis < 2; ++axis) {
      const std::size_t row = 2 * (i * N) + axis;
      largest = std::max(largest, std::abs(plans.com_position[row] - tr.com[executed](axis)));
      largest = std::max(largest, std::abs(plans.com_velocity[row] - tr.com_vel[executed](axis)));
      largest = std::max(largest, std::abs(plans.cop[row] - tr.cop[executed](axis)));
    }
  }
  EXPECT_LE(largest, 1e-12);
  EXPECT_GT(shorter, 0) << "the adaptive step timing should have walked shorter horizons";
}

TEST(NmpcPlan, LandedStepsWereThePreviewedStepZeroAtTheirLandingTimes) {
  const wpg::WalkResult walk = turningWalk();
  const wpg::WalkTrajectory& tr = walk.trajectory;
  const wpg::PlanLog& plans = tr.plans;
  int checked = 0;
  for (const wpg::Footstep& step : tr.footsteps) {
    if (step.landing_time <= 0.0) continue;
    // The last iteration before the landing planned it.
    const auto last = static_cast<std::size_t>(std::lround(step.landing_time / 0.1)) - 1;
    ASSERT_LT(last, plans.size());
    const double* previewed = &plans.step[4 * (last * plans.steps)];
    EXPECT_NEAR(previewed[0], step.landing_time, 1e-9) << "t = " << step.landing_time;
    EXPECT_EQ(Eigen::Vector3d(previewed[1], previewed[2], previewed[3]), step.pose);
    EXPECT_EQ(plans.step_side[last * plans.steps], static_cast<std::uint8_t>(step.side));
    ++checked;
  }
  EXPECT_GT(checked, 12);
}

TEST(NmpcPlan, ActiveRowsAreCountedPerFamily) {
  const wpg::WalkResult walk = turningWalk();
  const wpg::PlanLog& plans = walk.trajectory.plans;
  ASSERT_EQ(plans.families, static_cast<int>(walk.trajectory.constraint_families.size()));
  long total = 0;
  for (const int rows : plans.active_rows) {
    EXPECT_GE(rows, 0);
    total += rows;
  }
  EXPECT_GT(total, 0);  // the CoP rows of a walk at 0.5 m/s touch their bounds
}

TEST(NmpcPlan, NotRecordedWhenOff) {
  const wpg::WalkResult on = turningWalk(true), off = turningWalk(false);
  EXPECT_TRUE(off.trajectory.plans.empty());
  ASSERT_EQ(on.trajectory.com.size(), off.trajectory.com.size());
  for (std::size_t i = 0; i < on.trajectory.com.size(); ++i)
    ASSERT_EQ(on.trajectory.com[i], off.trajectory.com[i]);  // the walk itself is the same
}

}  // namespace
