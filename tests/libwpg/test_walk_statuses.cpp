// What each NMPC status does to a walk (iterationStatusFailsWalk, WalkResult::success; `wpg
// run` exits 1 when success is false, tests/cli): failures forced with families that cannot
// hold (tests/libwpg/test_constraint_families.hpp) and with a QP iteration cap, checked on the
// recorded status, the slack per family, the executed plan, `success` and the message.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <memory>
#include <string>

#include "../common/paper_gait.hpp"
#include "test_constraint_families.hpp"
#include "wpg/online_walking_generator.hpp"
#include "wpg/walk_generator.hpp"

namespace {

using wpg::IterationStatus;
using wpg::RelaxationGroup;

wpg::WalkRequest walkForward(double duration = 4.0) {
  wpg::WalkRequest request;
  request.duration = duration;
  request.reference.push_back({0.0, Eigen::Vector3d(0.2, 0.0, 0.0)});
  return request;
}

TEST(WalkStatuses, WhichStatusesFailTheWalk) {
  EXPECT_FALSE(wpg::iterationStatusFailsWalk(IterationStatus::kSolved));
  EXPECT_FALSE(wpg::iterationStatusFailsWalk(IterationStatus::kRelaxedObstacle));
  for (IterationStatus status :
       {IterationStatus::kFallback, IterationStatus::kIterationLimit, IterationStatus::kFallen,
        IterationStatus::kNotConverged, IterationStatus::kRelaxedKinematics,
        IterationStatus::kRelaxedBalance})
    EXPECT_TRUE(wpg::iterationStatusFailsWalk(status)) << wpg::iterationStatusName(status);
}

struct Forced {
  RelaxationGroup group;
  IterationStatus status;
  bool success;
};

class WalkWithFamilyThatCannotHold : public ::testing::TestWithParam<Forced> {};

// Every iteration is infeasible: its status names the group that gave way, the family's slack
// is exactly its violation (1 m) and nothing else was relaxed; the walk goes on and fails
// unless only an obstacle row gave way.
TEST_P(WalkWithFamilyThatCannotHold, StatusSlackSuccess) {
  const Forced forced = GetParam();
  const wpg::WalkResult walk =
      wpg::generateWalk(wpg::WalkingParameters(), walkForward(),
                        {std::make_shared<wpg_test::NeverHolds>(forced.group)});
  const wpg::WalkTrajectory& t = walk.trajectory;
  ASSERT_EQ(t.constraint_families.size(), 7u);
  EXPECT_EQ(t.constraint_families[6].name, "never_holds");
  EXPECT_EQ(t.constraint_families[6].group, wpg::relaxationGroupName(forced.group));
  ASSERT_EQ(t.mpc.size(), 40u);  // the walk is complete
  for (const wpg::MpcIterationLog& log : t.mpc) {
    EXPECT_EQ(log.status, forced.status) << "t = " << log.time;
    EXPECT_EQ(log.relaxed_families, 1u << 6) << "t = " << log.time;
    EXPECT_NEAR(log.slack[6], 1.0, 1e-9);
    for (int k = 0; k < 6; ++k) EXPECT_LE(log.slack[k], 1e-12) << t.constraint_families[k].name;
  }
  EXPECT_EQ(walk.success, forced.success);
  if (!forced.success) {
    EXPECT_NE(walk.message.find(wpg::iterationStatusName(forced.status)), std::string::npos)
        << walk.message;
  } else {
    EXPECT_TRUE(walk.message.empty()) << walk.message;
  }
  // The paper's rows held: the robot walked on (0.2 m/s, 4 s, the first 1.6 s starting).
  EXPECT_GT(t.com.back().x(), 0.3);
}

INSTANTIATE_TEST_SUITE_P(
    Groups, WalkWithFamilyThatCannotHold,
    ::testing::Values(Forced{RelaxationGroup::kObstacle, IterationStatus::kRelaxedObstacle, true},
                      Forced{RelaxationGroup::kKinematics, IterationStatus::kRelaxedKinematics,
                             false},
                      Forced{RelaxationGroup::kBalance, IterationStatus::kRelaxedBalance, false}),
    [](const ::testing::TestParamInfo<Forced>& info) {
      return std::string(wpg::relaxationGroupName(info.param.group));
    });

// A capped QP: its iterate is not executed; the plan of that sample is the previous plan
// shifted by one sample (what the solver held on entry), and the walk fails.
TEST(WalkStatuses, CappedQpExecutesTheShiftedPlan) {
  // The paper's gait: some of its QPs need more than two working-set updates.
  const wpg::WalkingParameters w = wpg_test::paperGait();
  wpg::GeneratorSettings settings;
  settings.max_qp_iterations = 2;
  wpg::PatternGenerator generator(w, settings);
  const Eigen::Vector3d forward(0.2, 0.0, 0.0);
  int capped = 0;
  for (int k = 0; k < 60; ++k) {
    const Eigen::VectorXd shifted = generator.solver().plan();
    const wpg::MpcIterationLog& log = generator.update(k * w.sampling_period, forward);
    if (log.status == IterationStatus::kIterationLimit) {
      ++capped;
      EXPECT_EQ((generator.solver().plan() - shifted).cwiseAbs().maxCoeff(), 0.0) << k;
      const int jerk_x = generator.model().layout().jerkX();
      EXPECT_EQ(generator.plan().jerk_x, shifted(jerk_x)) << k;
    } else {
      EXPECT_EQ(log.status, IterationStatus::kSolved) << k;
    }
    Eigen::Vector3d cx = generator.comX(), cy = generator.comY();
    for (int i = 0; i < 20; ++i) {
      wpg::integrateJerk(cx, generator.plan().jerk_x, w.control_period);
      wpg::integrateJerk(cy, generator.plan().jerk_y, w.control_period);
    }
    generator.advance(cx, cy);
  }
  EXPECT_GT(capped, 0);

  wpg::WalkRequest request = walkForward();
  request.generator.max_qp_iterations = 2;
  const wpg::WalkResult walk = wpg::generateWalk(w, request);
  EXPECT_FALSE(walk.success);
  EXPECT_NE(walk.message.find("iteration_limit"), std::string::npos) << walk.message;
}

// SQP to convergence that stops at max_sqp_iterations is not a plain success either.
TEST(WalkStatuses, UnconvergedSqpFailsTheWalk) {
  wpg::WalkRequest request = walkForward(2.0);
  request.generator.sqp_iterations = 0;
  request.generator.max_sqp_iterations = 1;
  request.generator.sqp_tolerance = 1e-14;
  const wpg::WalkResult walk = wpg::generateWalk(wpg::WalkingParameters(), request);
  bool unconverged = false;
  for (const wpg::MpcIterationLog& log : walk.trajectory.mpc)
    unconverged = unconverged || log.status == IterationStatus::kNotConverged;
  ASSERT_TRUE(unconverged);
  EXPECT_FALSE(walk.success);
  EXPECT_NE(walk.message.find("not_converged"), std::string::npos) << walk.message;
}

}  // namespace
