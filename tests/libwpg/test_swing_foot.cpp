// Tests of the swing-foot interpolation: the quintic to rest and the swing trajectory with
// re-planning at every NMPC sample.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>

#include "wpg/swing_foot_trajectory.hpp"

namespace {

using Eigen::Vector3d;
using Eigen::Vector4d;
using wpg::QuinticToRest;
using wpg::SwingFootTrajectory;

TEST(QuinticToRest, SatisfiesItsSixBoundaryConditions) {
  std::mt19937 engine(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> duration(0.05, 1.5);
  for (int trial = 0; trial < 500; ++trial) {
    const double p0 = u(engine), v0 = 2 * u(engine), a0 = 10 * u(engine), p1 = u(engine);
    const double T = duration(engine);
    QuinticToRest q;
    q.plan(p0, v0, a0, p1, T);
    const Vector3d start = q.evaluate(0.0);
    const Vector3d end = q.evaluate(T);
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " T=" << T);
    EXPECT_NEAR(start(0), p0, 1e-9);
    EXPECT_NEAR(start(1), v0, 1e-9);
    EXPECT_NEAR(start(2), a0, 1e-9);
    EXPECT_NEAR(end(0), p1, 1e-9);
    EXPECT_NEAR(end(1), 0.0, 1e-9);
    EXPECT_NEAR(end(2), 0.0, 1e-9);
    // The derivatives are those of the position (central differences at an inner time).
    const double t = 0.37 * T, h = 1e-5;
    const Vector3d mid = q.evaluate(t);
    EXPECT_NEAR(mid(1), (q.evaluate(t + h)(0) - q.evaluate(t - h)(0)) / (2 * h), 1e-6 * (1 + std::abs(mid(1))));
    EXPECT_NEAR(mid(2), (q.evaluate(t + h)(1) - q.evaluate(t - h)(1)) / (2 * h), 1e-5 * (1 + std::abs(mid(2))));
    // Clamped outside [0, T]: at rest on the target after T.
    const Vector3d after = q.evaluate(T + 0.5);
    EXPECT_NEAR(after(0), p1, 1e-9);
    EXPECT_NEAR(after(1), 0.0, 1e-9);
    EXPECT_NEAR(after(2), 0.0, 1e-9);
  }
}

TEST(QuinticToRest, ZeroDurationJumpsToTarget) {
  QuinticToRest q;
  q.plan(0.3, 1.0, 2.0, -0.4, 0.0);
  const Vector3d v = q.evaluate(0.0);
  EXPECT_DOUBLE_EQ(v(0), -0.4);
  EXPECT_DOUBLE_EQ(v(1), 0.0);
  EXPECT_DOUBLE_EQ(v(2), 0.0);
}

TEST(QuinticToRest, RestToRestIsMonotonic) {
  QuinticToRest q;
  q.plan(0.0, 0.0, 0.0, 0.25, 0.7);
  double previous = -1.0;
  for (int k = 0; k <= 700; ++k) {
    const double p = q.evaluate(k * 0.001)(0);
    EXPECT_GE(p, previous - 1e-15);
    EXPECT_GE(p, -1e-15);
    EXPECT_LE(p, 0.25 + 1e-15);
    previous = p;
  }
  EXPECT_NEAR(q.evaluate(0.35)(0), 0.125, 1e-12);  // symmetric profile: half way at half time
}

// Central-difference derivative of component k of poseAt.
double rate(const SwingFootTrajectory& s, double t, int k, double h = 1e-6) {
  return (s.poseAt(t + h)(k) - s.poseAt(t - h)(k)) / (2 * h);
}

TEST(SwingFootTrajectory, HeightProfile) {
  const Vector3d lift(0.1, -0.095, 0.2);
  const double t0 = 1.0, t1 = 1.7, height = 0.05;
  SwingFootTrajectory swing;
  swing.start(lift, t0, t1, height);
  swing.replan(t0, Vector3d(0.3, -0.1, 0.25));
  EXPECT_NEAR(swing.poseAt(t0)(2), 0.0, 1e-15);
  EXPECT_NEAR(swing.poseAt(t1)(2), 0.0, 1e-15);
  EXPECT_NEAR(swing.poseAt(0.5 * (t0 + t1))(2), height, 1e-12);
  // fifth-order rise and fall (paper Sec. III-A): at a quarter of the swing the quintic
  // rest-to-rest profile is at half the height (the former degree-6 curve: 27/64 of it)
  EXPECT_NEAR(swing.poseAt(t0 + 0.25 * (t1 - t0))(2), 0.5 * height, 1e-12);
  EXPECT_NEAR(swing.poseAt(t0 + 0.75 * (t1 - t0))(2), 0.5 * height, 1e-12);
  // Zero vertical velocity at lift-off and landing (one-sided differences, inside the swing).
  const double h = 1e-4;
  EXPECT_NEAR((swing.poseAt(t0 + h)(2) - swing.poseAt(t0)(2)) / h, 0.0, 1e-6);
  EXPECT_NEAR((swing.poseAt(t1)(2) - swing.poseAt(t1 - h)(2)) / h, 0.0, 1e-6);
  // Zero vertical velocity at the apex; height never negative nor above the step height.
  EXPECT_NEAR(rate(swing, 0.5 * (t0 + t1), 2), 0.0, 1e-8);
  // ... and zero vertical acceleration there (each quintic ends at rest: C2 at the apex)
  const double apex = 0.5 * (t0 + t1), d = 1e-4;
  EXPECT_NEAR((swing.poseAt(apex + d)(2) - 2 * swing.poseAt(apex)(2) + swing.poseAt(apex - d)(2)) /
                  (d * d),
              0.0, 1e-2);  // the former curve: -2.4 m/s^2
  for (int k = 0; k <= 140; ++k) {
    const double z = swing.poseAt(t0 + k * 0.005)(2);
    EXPECT_GE(z, 0.0);
    EXPECT_LE(z, height + 1e-12);
  }
  // On the ground before lift-off and after landing.
  EXPECT_EQ(swing.poseAt(t0 - 0.1)(2), 0.0);
  EXPECT_EQ(swing.poseAt(t1 + 0.1)(2), 0.0);
}

TEST(SwingFootTrajectory, LiftsOffAtRestFromTheStartPose) {
  const Vector3d lift(0.1, -0.095, 0.2);
  const Vector3d target(0.3, -0.1, 0.25);
  SwingFootTrajectory swing;
  swing.start(lift, 2.0, 2.7, 0.05);
  swing.replan(2.0, target);
  const Vector4d p = swing.poseAt(2.0);
  EXPECT_NEAR(p(0), lift(0), 1e-12);
  EXPECT_NEAR(p(1), lift(1), 1e-12);
  EXPECT_NEAR(p(3), lift(2), 1e-12);
  const double h = 1e-4;
  for (int k : {0, 1, 3})
    EXPECT_NEAR((swing.poseAt(2.0 + h)(k) - swing.poseAt(2.0)(k)) / h, 0.0, 1e-5) << k;
  const Vector4d end = swing.poseAt(2.7);
  EXPECT_NEAR(end(0), target(0), 1e-9);
  EXPECT_NEAR(end(1), target(1), 1e-9);
  EXPECT_NEAR(end(3), target(2), 1e-9);
}

TEST(SwingFootTrajectory, ReplanningIsContinuousAndLandsOnTheNewTarget) {
  std::mt19937 engine(5);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  const double t0 = 0.8, t1 = 1.5, T = 0.1;
  SwingFootTrajectory swing;
  const Vector3d lift(0.0, 0.095, 0.0);
  swing.start(lift, t0, t1, 0.05);
  Vector3d target(0.2, 0.1, 0.1);
  swing.replan(t0, target);
  // Re-plan at every NMPC sample with a moving target, as the walk generator does.
  for (int k = 1; k <= 6; ++k) {
    const double t = t0 + k * T;
    const SwingFootTrajectory before = swing;
    target += Vector3d(u(engine), u(engine), u(engine));
    swing.replan(t, target);
    SCOPED_TRACE(::testing::Message() << "replan at t = " << t);
    const Vector4d p_before = before.poseAt(t), p_after = swing.poseAt(t);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(p_after(c), p_before(c), 1e-12) << "component " << c;
    // Velocity: the old plan's derivative at t against the new plan's forward derivative.
    // (second-order one-sided differences for the new plan, which starts at t).
    const double h = 1e-6;
    for (int c : {0, 1, 3}) {
      const double v_before = rate(before, t, c);
      const double v_after = (-3 * swing.poseAt(t)(c) + 4 * swing.poseAt(t + h)(c) -
                              swing.poseAt(t + 2 * h)(c)) / (2 * h);
      EXPECT_NEAR(v_after, v_before, 1e-6 * (1.0 + std::abs(v_before))) << "component " << c;
    }
    // Acceleration continuity too (the quintic starts from the current acceleration).
    const double H = 1e-4;
    for (int c : {0, 1, 3}) {
      const double a_before =
          (before.poseAt(t + H)(c) - 2 * before.poseAt(t)(c) + before.poseAt(t - H)(c)) / (H * H);
      const double a_after = (2 * swing.poseAt(t)(c) - 5 * swing.poseAt(t + H)(c) +
                              4 * swing.poseAt(t + 2 * H)(c) - swing.poseAt(t + 3 * H)(c)) /
                             (H * H);
      EXPECT_NEAR(a_after, a_before, 1e-2 * (1.0 + std::abs(a_before))) << "component " << c;
    }
    // A replan does not change the height profile.
    EXPECT_EQ(swing.poseAt(t + 0.05)(2), before.poseAt(t + 0.05)(2));
  }
  // Lands exactly on the last target, at rest.
  const Vector4d land = swing.poseAt(t1);
  EXPECT_NEAR(land(0), target(0), 1e-9);
  EXPECT_NEAR(land(1), target(1), 1e-9);
  EXPECT_NEAR(land(2), 0.0, 1e-12);
  EXPECT_NEAR(land(3), target(2), 1e-9);
  const double h = 1e-6;
  for (int c : {0, 1, 3})
    EXPECT_NEAR((swing.poseAt(t1)(c) - swing.poseAt(t1 - h)(c)) / h, 0.0, 1e-4) << c;
  const Vector4d after = swing.poseAt(t1 + 0.3);
  EXPECT_NEAR((after - land).norm(), 0.0, 1e-9);
}

TEST(SwingFootTrajectory, ReplanAtLandingTimeSnapsToTarget) {
  SwingFootTrajectory swing;
  swing.start(Vector3d(0, 0, 0), 0.0, 0.7, 0.05);
  swing.replan(0.0, Vector3d(0.2, 0.0, 0.0));
  swing.replan(0.7, Vector3d(0.25, 0.01, 0.05));
  const Vector4d p = swing.poseAt(0.7);
  EXPECT_NEAR(p(0), 0.25, 1e-12);
  EXPECT_NEAR(p(1), 0.01, 1e-12);
  EXPECT_NEAR(p(3), 0.05, 1e-12);
}

}  // namespace
