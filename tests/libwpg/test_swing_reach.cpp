// The swing foot's reach (wpg/swing_foot_reach.hpp, swing_reach family): the landings it
// allows keep the re-planned swing foot within its speed and acceleration limits at every
// control tick, those just outside do not, the rows and their Jacobian, and a walk pushed late
// in a swing whose foot stays physical with the limits and does not without them. Also the
// swing-foot peaks of a walk (swingFootPeaks: central differences) on a known trajectory.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>

#include "nmpc_test_problems.hpp"
#include "wpg/nmpc.hpp"
#include "wpg/nmpc/builtin_families.hpp"
#include "wpg/nmpc/numdiff.hpp"
#include "wpg/swing_foot_reach.hpp"
#include "wpg/swing_foot_trajectory.hpp"
#include "wpg/walk_checks.hpp"
#include "wpg/walk_generator.hpp"

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using Eigen::VectorXd;
using wpg::SwingFootTrajectory;
using wpg::SwingReach;

constexpr double kSpeed = 2.0, kAcceleration = 50.0, kTick = 0.005;
constexpr int kSwingReachFamily = 6;  // registration order (NmpcModel's constructor)

// The foot's largest speed and acceleration (x, y, z; analytic derivatives) at the ticks of
// [t, landing], and the largest projection on a direction d_k of its horizontal velocity and
// acceleration divided by that direction's limit (the polygon's; <= 1 inside).
struct Peaks {
  double speed = 0.0, acceleration = 0.0, polygon = 0.0;
};
Peaks peaksFrom(const SwingFootTrajectory& swing, double t) {
  Peaks peaks;
  for (double tau = t; tau < swing.landingTime() - 1e-9; tau += kTick) {
    const Vector3d x = swing.axisState(0, tau), y = swing.axisState(1, tau);
    const Vector3d z = swing.heightState(tau);
    peaks.speed = std::max(peaks.speed, Vector3d(x(1), y(1), z(1)).norm());
    peaks.acceleration = std::max(peaks.acceleration, Vector3d(x(2), y(2), z(2)).norm());
    const double c = std::cos(M_PI / (2 * SwingReach::kDirections));
    const double v_limit = c * std::sqrt(kSpeed * kSpeed - z(1) * z(1));
    const double a_limit = c * std::sqrt(kAcceleration * kAcceleration - z(2) * z(2));
    for (int k = 0; k < SwingReach::kDirections; ++k) {
      const Vector2d d = SwingReach::direction(k);
      peaks.polygon = std::max({peaks.polygon, std::abs(d.x() * x(1) + d.y() * y(1)) / v_limit,
                                std::abs(d.x() * x(2) + d.y() * y(2)) / a_limit});
    }
  }
  return peaks;
}

TEST(SwingFootTrajectory, HeightStateIsTheDerivativeOfTheHeight) {
  SwingFootTrajectory swing;
  swing.start(Vector3d(0.1, 0.2, 0.0), 1.0, 1.7, 0.05);
  const double h = 1e-6;
  for (double t = 1.01; t < 1.69; t += 0.0137) {
    const Vector3d z = swing.heightState(t);
    EXPECT_DOUBLE_EQ(z(0), swing.poseAt(t)(2));
    EXPECT_NEAR(z(1), (swing.heightState(t + h)(0) - swing.heightState(t - h)(0)) / (2 * h), 1e-6);
    EXPECT_NEAR(z(2), (swing.heightState(t + h)(1) - swing.heightState(t - h)(1)) / (2 * h), 1e-4);
  }
  EXPECT_EQ(swing.heightState(0.5), Vector3d::Zero());
  EXPECT_EQ(swing.heightState(1.8), Vector3d::Zero());
}

// Random swings re-planned at each 0.1 s sample to random landings within the reach: the foot
// stays within its limits; the current landing is always within the reach; a landing 5 mm
// beyond a bound breaks the polygon at some tick (the bounds are the tightest of their form).
TEST(SwingReach, LandingsInsideKeepTheLimitsAndOutsideBreakThem) {
  std::mt19937 engine(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tight = 0, checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    SwingFootTrajectory swing;
    const double lift_off = 2.0, landing = 2.7;
    swing.start(Vector3d(0.0, 0.1, 0.0), lift_off, landing, 0.05);
    Vector2d target(0.0, 0.1);
    for (int sample = 0; sample < 7; ++sample) {
      const double t = lift_off + 0.1 * sample;
      const SwingReach reach = swingReach(swing, t, target, kSpeed, kAcceleration, kTick);
      SCOPED_TRACE(::testing::Message() << "trial " << trial << ", sample " << sample);
      for (int k = 0; k < SwingReach::kDirections; ++k) {
        const double along = SwingReach::direction(k).dot(target);
        EXPECT_LE(reach.lower(k), along + 1e-12);
        EXPECT_GE(reach.upper(k), along - 1e-12);
      }
      // Just outside one bound (along its direction, from the current target's projection
      // onto it): the projection on d_k of the foot's motion exceeds the polygon.
      const int k = static_cast<int>(unit(engine) * SwingReach::kDirections) % SwingReach::kDirections;
      const bool upper = unit(engine) < 0.5;
      const Vector2d d = SwingReach::direction(k);
      const double along = d.dot(target);
      const double beyond = (upper ? reach.upper(k) + 0.005 : reach.lower(k) - 0.005) - along;
      SwingFootTrajectory outside = swing;
      const Vector2d out = target + beyond * d;
      outside.replan(t, Vector3d(out.x(), out.y(), 0.0));
      EXPECT_GT(peaksFrom(outside, t).polygon, 1.0) << "direction " << k << (upper ? " upper" : " lower");
      ++tight;
      // A random landing inside the polygon of bounds (rejection sampling round the target).
      for (int attempt = 0; attempt < 200; ++attempt) {
        const Vector2d candidate =
            target + Vector2d(unit(engine) - 0.5, unit(engine) - 0.5) * (0.05 + 0.6 * unit(engine));
        bool inside = true;
        for (int j = 0; j < SwingReach::kDirections; ++j) {
          const double p = SwingReach::direction(j).dot(candidate);
          inside = inside && p >= reach.lower(j) && p <= reach.upper(j);
        }
        if (!inside) continue;
        target = candidate;
        break;
      }
      swing.replan(t, Vector3d(target.x(), target.y(), 0.0));
      const Peaks peaks = peaksFrom(swing, t);
      EXPECT_LE(peaks.polygon, 1.0 + 1e-9);
      EXPECT_LE(peaks.speed, kSpeed + 1e-9);
      EXPECT_LE(peaks.acceleration, kAcceleration + 1e-9);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 60 * 7);
  EXPECT_EQ(tight, 60 * 7);
}

TEST(SwingReach, RowsBoundTheLandingAlongEightDirections) {
  wpg::WalkingParameters w;
  w.max_swing_speed = kSpeed;
  w.max_swing_acceleration = kAcceleration;
  const wpg::NmpcModel model(w, 0);
  ASSERT_STREQ(model.family(kSwingReachFamily).name(), "swing_reach");
  ASSERT_EQ(model.familyRowCount(kSwingReachFamily), wpg::SwingReachRows::kRows);
  EXPECT_EQ(model.family(kSwingReachFamily).group(), wpg::RelaxationGroup::kKinematics);
  const wpg::NmpcLayout& L = model.layout();
  wpg_test::Rng rng(5);
  wpg::NmpcProblem problem =
      wpg_test::randomProblem(model, 3, wpg::FootSide::kLeft, wpg_test::FixedMode::kNone, rng);
  problem.swing_reach_bounded = true;
  for (int k = 0; k < SwingReach::kDirections; ++k) {
    problem.swing_reach_lower(k) = -0.1 * (k + 1);
    problem.swing_reach_upper(k) = 0.05 * (k + 1);
  }
  VectorXd U = wpg_test::randomU(model, problem, rng);
  U(L.stepX()) = 0.3;
  U(L.stepY()) = -0.1;
  VectorXd g(model.inequalityCount());
  wpg::evaluateConstraints(model, problem, U, g, nullptr);
  const int first = model.familyFirstRow(kSwingReachFamily);
  for (int k = 0; k < SwingReach::kDirections; ++k) {
    const double p = SwingReach::direction(k).dot(Vector2d(0.3, -0.1));
    EXPECT_NEAR(g(first + 2 * k), p - problem.swing_reach_upper(k), 1e-12) << k;
    EXPECT_NEAR(g(first + 2 * k + 1), problem.swing_reach_lower(k) - p, 1e-12) << k;
  }
  EXPECT_LE(wpg::checkConstraintJacobian(model, problem, U, kSwingReachFamily).worst, 1e-6);
  problem.swing_reach_bounded = false;
  wpg::evaluateConstraints(model, problem, U, g, nullptr);
  EXPECT_EQ(g.segment(first, 16), VectorXd::Constant(16, -1.0));
  // Off (WalkingParameters' defaults, the paper's formulation): not registered.
  EXPECT_EQ(wpg::NmpcModel(wpg::WalkingParameters(), 0).findFamily("swing_reach"), -1);
}

// swingFootPeaks on a foot moving as x = A sin(w t), z = B (1 - cos(w t)): the peaks of the
// central differences are A w sqrt(...) and the analytic ones within their O(dt^2) error.
TEST(SwingFootPeaks, MatchTheAnalyticDerivativesOfAKnownMotion) {
  wpg::WalkTrajectory tr;
  const double A = 0.2, B = 0.05, w = 6.0, dt = 0.005;
  double speed = 0.0, acceleration = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const double t = i * dt;
    tr.time.push_back(t);
    tr.left_foot.emplace_back(A * std::sin(w * t), 0.1, B * (1 - std::cos(w * t)), 0.0);
    tr.right_foot.emplace_back(0.0, -0.1, 0.0, 0.0);
    if (i > 0 && i < 400) {
      speed = std::max(speed, w * std::hypot(A * std::cos(w * t), B * std::sin(w * t)));
      acceleration = std::max(acceleration, w * w * std::hypot(A * std::sin(w * t), B * std::cos(w * t)));
    }
  }
  wpg::WalkCheckReport report;
  wpg::swingFootPeaks(tr, report);
  EXPECT_NEAR(report.swing_foot_speed_max, speed, speed * w * w * dt * dt / 6 + 1e-12);
  EXPECT_NEAR(report.swing_foot_acceleration_max, acceleration,
              acceleration * w * w * dt * dt / 12 + 1e-12);
  // The speed peaks where cos(w t) = +-1, t a multiple of pi / w.
  const double phase = std::fmod(report.swing_foot_speed_max_time, M_PI / w);
  EXPECT_LE(std::min(phase, M_PI / w - phase), dt);
}

// A push late in a swing of the walk of datasets/scenarios/push.yaml (0.2 m/s), backwards at
// lift-off + 0.5 s (phase 0.625), 150 N: recovered without the limits by a swing foot beyond
// 2 m/s; with them the foot stays within 2 m/s and 50 m/s^2 (central differences at 5 ms).
// With the limits the robot falls at 5.3 s; before that, the push step's 0.5 s swing from its
// 4.9 s landing, whose warm-start landing was planned for the step before, must keep the limits
// from its first plan on (it reached 2.2 m/s when the reach always held that landing).
TEST(SwingReach, KeepsALatePushsSwingFootPhysical) {
  wpg::WalkRequest request;
  request.duration = 6.0;
  request.reference = {{0.0, Vector3d::Zero()}, {1.0, Vector3d(0.2, 0.0, 0.0)}};
  request.pushes.push_back({3.9, Eigen::Vector2d(-150.0, 0.0), 0.1});
  request.generator.sqp_iterations = 1;
  wpg::WalkingParameters limited;
  limited.max_swing_speed = kSpeed;
  limited.max_swing_acceleration = kAcceleration;
  const wpg::WalkResult off = wpg::generateWalk(wpg::WalkingParameters(), request);
  const wpg::WalkResult on = wpg::generateWalk(limited, request);
  wpg::WalkCheckReport peaks_off, peaks_on;
  wpg::swingFootPeaks(off.trajectory, peaks_off);
  wpg::swingFootPeaks(on.trajectory, peaks_on);
  EXPECT_GT(peaks_off.swing_foot_speed_max, kSpeed);
  EXPECT_LE(peaks_on.swing_foot_speed_max, kSpeed);
  EXPECT_LE(peaks_on.swing_foot_acceleration_max, kAcceleration);
  RecordProperty("speed_off", std::to_string(peaks_off.swing_foot_speed_max));
  RecordProperty("speed_on", std::to_string(peaks_on.swing_foot_speed_max));
  RecordProperty("acceleration_off", std::to_string(peaks_off.swing_foot_acceleration_max));
  RecordProperty("acceleration_on", std::to_string(peaks_on.swing_foot_acceleration_max));
}

}  // namespace
