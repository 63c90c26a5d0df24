// The swing-foot landing bound (landing_bound family, paper Sec. III-C3 last paragraph): its
// rows and Jacobian, its data filled by the pattern generator sample after sample, and its
// effect on a walk pushed late in a swing.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "../common/paper_gait.hpp"
#include "nmpc_test_problems.hpp"
#include "wpg/nmpc.hpp"
#include "wpg/nmpc/numdiff.hpp"
#include "wpg/pattern_generator.hpp"
#include "wpg/walk_generator.hpp"

namespace {

using Eigen::Vector3d;
using Eigen::VectorXd;
using wpg::FootSide;
using wpg::NmpcModel;
using wpg::NmpcProblem;
using wpg::WalkingParameters;
using namespace wpg_test;

constexpr int kLandingFamily = 4;     // x, y (registration order, NmpcModel's constructor)
constexpr int kLandingYawFamily = 5;  // yaw

// The paper's gait (the push of HoldsBetweenConsecutiveSamplesOfAPushedWalk was placed for it;
// with the default gait that push does not make the bound act).
WalkingParameters boundOn() {
  WalkingParameters w = wpg_test::paperGait();
  w.max_landing_speed = 0.4;  // the authors' values (walking_parameters.hpp)
  w.max_landing_yaw_rate = 1.5;
  return w;
}

TEST(LandingBound, RowsBoundTheLandingAroundThePreviousOne) {
  const WalkingParameters w = boundOn();
  const NmpcModel model(w, 0);
  ASSERT_STREQ(model.family(kLandingFamily).name(), "landing_bound");
  ASSERT_STREQ(model.family(kLandingYawFamily).name(), "landing_yaw_bound");
  // Its rows follow the x, y rows: six rows in all, x, y, yaw, upper then lower.
  ASSERT_EQ(model.familyFirstRow(kLandingYawFamily), model.familyFirstRow(kLandingFamily) + 4);
  const wpg::NmpcLayout& L = model.layout();
  Rng rng(3);
  NmpcProblem problem = randomProblem(model, 3, FootSide::kLeft, FixedMode::kNone, rng);
  problem.landing_bounded = true;
  problem.previous_landing = Vector3d(0.5, -0.1, 0.2);
  problem.landing_time_left = 0.3;  // bounds 0.12 m and 0.45 rad
  VectorXd U = randomU(model, problem, rng);
  U(L.stepX()) = 0.55;
  U(L.stepY()) = -0.3;
  U(L.stepYaw()) = 0.2 - 0.5;
  const int first = model.familyFirstRow(kLandingFamily);
  VectorXd g(model.inequalityCount());
  wpg::evaluateConstraints(model, problem, U, g, nullptr);
  const VectorXd rows = g.segment(first, 6);
  const double expected[6] = {0.05 - 0.12, -0.05 - 0.12, -0.2 - 0.12,
                              0.2 - 0.12,  -0.5 - 0.45, 0.5 - 0.45};
  for (int r = 0; r < 6; ++r) EXPECT_NEAR(rows(r), expected[r], 1e-12) << "row " << r;
  for (const int family : {kLandingFamily, kLandingYawFamily}) {
    const wpg::JacobianCheck check = wpg::checkConstraintJacobian(model, problem, U, family);
    EXPECT_LE(check.worst, 1e-6) << model.family(family).name();
  }

  // Inactive: a fixed landing, no swing, or the bound switched off.
  NmpcProblem fixed = problem;
  fixed.phase.step_fixed(0) = 1;
  wpg::evaluateConstraints(model, fixed, U, g, nullptr);
  EXPECT_EQ(g.segment(first, 6), VectorXd::Constant(6, -1.0));
  NmpcProblem unbounded = problem;
  unbounded.landing_bounded = false;
  wpg::evaluateConstraints(model, unbounded, U, g, nullptr);
  EXPECT_EQ(g.segment(first, 6), VectorXd::Constant(6, -1.0));
  // x, y off: no rows of its own; yaw still on.
  WalkingParameters off = w;
  off.max_landing_speed = 0.0;
  const NmpcModel model_off(off, 0);
  EXPECT_EQ(model_off.familyRowCount(kLandingFamily), 0);
  ASSERT_EQ(model_off.familyRowCount(kLandingYawFamily), 2);
  VectorXd g_off(model_off.inequalityCount());
  wpg::evaluateConstraints(model_off, problem, U, g_off, nullptr);
  const int yaw_first = model_off.familyFirstRow(kLandingYawFamily);
  EXPECT_NEAR(g_off(yaw_first), -0.5 - 0.45, 1e-12);
  EXPECT_NEAR(g_off(yaw_first + 1), 0.5 - 0.45, 1e-12);
}

// Sample after sample of a walk pushed sideways during a swing: the generator gives the
// family the previous sample's landing and the time to touchdown, and the solved landing
// stays within the bound of it.
TEST(LandingBound, HoldsBetweenConsecutiveSamplesOfAPushedWalk) {
  const WalkingParameters w = boundOn();
  wpg::GeneratorSettings settings;
  wpg::PatternGenerator generator(w, settings);
  int bounded = 0, binding = 0;
  Vector3d previous_landing = Vector3d::Zero();
  bool previous_swinging = false, pushed = false;
  for (int k = 0; k < 60; ++k) {
    const wpg::MpcIterationLog& log = generator.update(k * w.sampling_period, Vector3d(0.2, 0, 0));
    ASSERT_EQ(log.status, wpg::IterationStatus::kSolved) << "sample " << k;
    const NmpcProblem& problem = generator.problem();
    const Vector3d landing = generator.plan().swing_target;
    if (problem.landing_bounded) {
      ++bounded;
      EXPECT_TRUE(generator.plan().swinging);
      const int m = generator.gait().phaseSample();
      // The step in force: the push makes the next step a shorter one (push_step_*).
      const int S = generator.gait().stepSamples();
      EXPECT_NEAR(problem.landing_time_left, (S - 1 - m) * w.sampling_period, 1e-12);
      if (previous_swinging && m > 0) {  // same swing: the previous sample's landing
        EXPECT_NEAR((problem.previous_landing - previous_landing).norm(), 0.0, 1e-12);
      }
      const Vector3d change = (landing - problem.previous_landing).cwiseAbs();
      const double xy = w.max_landing_speed * problem.landing_time_left;
      const double yaw = w.max_landing_yaw_rate * problem.landing_time_left;
      EXPECT_LE(change.x(), xy + 1e-9) << "sample " << k;
      EXPECT_LE(change.y(), xy + 1e-9) << "sample " << k;
      EXPECT_LE(change.z(), yaw + 1e-9) << "sample " << k;
      if (change.head<2>().maxCoeff() > xy - 1e-9) ++binding;
    }
    previous_landing = landing;
    previous_swinging = generator.plan().swinging;
    Vector3d cx = generator.comX(), cy = generator.comY();
    if (!pushed && k >= 30 && generator.gait().phaseSample() == 4) {
      cy(1) += 0.16;  // 90 N for 0.1 s on 56 kg (push.yaml), 0.2 s before touchdown
      pushed = true;
    }
    for (int i = 0; i < 20; ++i) {
      wpg::integrateJerk(cx, generator.plan().jerk_x, w.control_period);
      wpg::integrateJerk(cy, generator.plan().jerk_y, w.control_period);
    }
    generator.advance(cx, cy);
  }
  EXPECT_GT(bounded, 20);
  EXPECT_GT(binding, 0);  // the push makes the bound act
}

double peakSwingSpeed(const wpg::WalkTrajectory& t) {
  double peak = 0.0;
  for (const auto* foot : {&t.left_foot, &t.right_foot})
    for (std::size_t i = 1; i < foot->size(); ++i)
      peak = std::max(peak, ((*foot)[i].head<3>() - (*foot)[i - 1].head<3>()).norm() /
                                (t.time[i] - t.time[i - 1]));
  return peak;
}

// The walk of datasets/scenarios/push.yaml with the push 50 ms later (the landing correction
// comes closer to touchdown): recovered with and without the bound, with a slower swing foot
// with it (1.09 vs 1.21 m/s when measured).
TEST(LandingBound, LowersTheSwingFootPeakSpeedAfterALatePush) {
  wpg::WalkRequest request;
  request.duration = 6.0;
  request.reference = {{0.0, Vector3d::Zero()}, {1.0, Vector3d(0.2, 0.0, 0.0)}};
  request.pushes.push_back({3.85, Eigen::Vector2d(0.0, 90.0), 0.1});
  request.generator.sqp_iterations = 1;
  const wpg::WalkResult off = wpg::generateWalk(WalkingParameters(), request);
  const wpg::WalkResult on = wpg::generateWalk(boundOn(), request);
  ASSERT_TRUE(off.success) << off.message;
  ASSERT_TRUE(on.success) << on.message;
  const double peak_off = peakSwingSpeed(off.trajectory);
  const double peak_on = peakSwingSpeed(on.trajectory);
  EXPECT_LT(peak_on, peak_off - 0.05) << "with " << peak_on << ", without " << peak_off;
}

}  // namespace
