// What J1 tracks (WalkingParameters::velocity_tracking): the paper's instantaneous velocity
// (eq. 5), a window's mean, or that velocity against a command holding the sway walked one gait
// cycle earlier (the default, with a window of 1: the instantaneous velocity). The references are checked against a synthetic periodic walk, the cost's
// quadratic form against its evaluation, and the walks against the command.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "wpg/nmpc.hpp"
#include "wpg/reference_builder.hpp"
#include "wpg/walk_generator.hpp"

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using Eigen::VectorXd;

Eigen::Matrix2d rotation(double angle) {
  return (Eigen::Matrix2d() << std::cos(angle), -std::sin(angle), std::sin(angle),
          std::cos(angle)).finished();
}

TEST(VelocityWindow, ParsesItsNames) {
  wpg::VelocityTracking t = wpg::VelocityTracking::kWindow;
  EXPECT_TRUE(wpg::parseVelocityTracking("instantaneous", &t));
  EXPECT_EQ(t, wpg::VelocityTracking::kInstantaneous);
  EXPECT_TRUE(wpg::parseVelocityTracking("with_sway", &t));
  EXPECT_EQ(t, wpg::VelocityTracking::kWithSway);
  EXPECT_TRUE(wpg::parseVelocityTracking("window", &t));
  EXPECT_EQ(t, wpg::VelocityTracking::kWindow);
  EXPECT_FALSE(wpg::parseVelocityTracking("step", &t));
  for (auto v : {wpg::VelocityTracking::kInstantaneous, wpg::VelocityTracking::kWindow,
                 wpg::VelocityTracking::kWithSway}) {
    ASSERT_TRUE(wpg::parseVelocityTracking(wpg::velocityTrackingName(v), &t));
    EXPECT_EQ(t, v);
  }
  // The default follows commands; the paper's J1 is one key away.
  EXPECT_EQ(wpg::WalkingParameters().velocity_tracking, wpg::VelocityTracking::kWithSway);
  EXPECT_EQ(wpg::WalkingParameters().velocity_window_samples, 1);
}

TEST(VelocityWindow, InstantaneousIsThePapersVelocityWhateverTheWindow) {
  wpg::WalkingParameters w;
  w.velocity_window_samples = 4;
  w.velocity_tracking = wpg::VelocityTracking::kInstantaneous;
  const wpg::NmpcModel model{w};
  EXPECT_EQ(model.trackedVelocityJerk(), model.prediction().velocity_jerk);
  EXPECT_EQ(model.trackedVelocityState(), model.prediction().velocity_state);
  // The default's Hessian is the paper's (a window of 1) ...
  const wpg::NmpcModel standard{wpg::WalkingParameters()};
  EXPECT_EQ(standard.trackedVelocityJerk(), model.prediction().velocity_jerk);
  // ... and a window's rows are means of K predicted velocities.
  w.velocity_tracking = wpg::VelocityTracking::kWithSway;
  const wpg::NmpcModel window{w};
  const int K = 4;
  for (int j = 0; j < w.horizon_length; ++j) {
    Eigen::RowVectorXd mean = Eigen::RowVectorXd::Zero(w.horizon_length);
    for (int i = std::max(0, j - K + 1); i <= j; ++i) mean += model.prediction().velocity_jerk.row(i);
    EXPECT_LT((window.trackedVelocityJerk().row(j) - mean / K).norm(), 1e-15) << j;
  }
}

TEST(VelocityWindow, QuadraticFormMatchesTheCostWithAWalkedHistory) {
  wpg::WalkingParameters parameters;
  parameters.velocity_window_samples = 8;
  const wpg::NmpcModel model(parameters);
  wpg::NmpcProblem problem = model.makeProblem();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = model.layout().variableCount();
  for (int pattern = 0; pattern < model.patternCount(); ++pattern) {
    problem.phase.pattern = pattern;
    model.rowStepsOf(pattern, problem.phase.row_step);
    problem.phase.support_pose = Eigen::Vector3d(u(rng), u(rng), u(rng));
    problem.com_x = Eigen::Vector3d(u(rng), u(rng), u(rng));
    problem.com_y = Eigen::Vector3d(u(rng), u(rng), u(rng));
    for (Eigen::VectorXd* v : {&problem.velocity_x, &problem.velocity_y, &problem.velocity_past_x,
                               &problem.velocity_past_y})
      *v = Eigen::VectorXd::NullaryExpr(v->size(), [&] { return u(rng); });
    problem.yaw_reference.setRandom();
    problem.phase.fixed_step_pose.setRandom();
    Eigen::VectorXd gradient(n);
    wpg::buildCostGradient(model, problem, gradient);
    const Eigen::MatrixXd& Q = model.hessian(pattern);
    double constant = 0.0;
    for (int trial = 0; trial < 4; ++trial) {
      const Eigen::VectorXd U = Eigen::VectorXd::NullaryExpr(n, [&] { return u(rng); });
      const double difference =
          wpg::evaluateCost(model, problem, U) - (0.5 * U.dot(Q * U) + gradient.dot(U));
      if (trial == 0) constant = difference;
      EXPECT_NEAR(difference, constant, 1e-9 * std::max(1.0, std::abs(constant)))
          << "pattern " << pattern;
    }
  }
}

// A synthetic periodic walk fed to the ReferenceBuilder sample by sample: in the robot's frame
// the CoM velocity is the command v + offset plus a forward oscillation of the window's period
// and a lateral sway of one gait cycle's (two steps), the robot turning at omega. J1's
// residual of each previewed sample, (window's mean of the velocity) + past - reference, with
// the previewed velocities the walk's own (the previous plan = the walk), is then returned for
// the last sample.
struct SyntheticWalk {
  double omega = 0.0;
  Vector2d v{0.05, 0.1};
  Vector2d offset = Vector2d::Zero();  // robot-frame mean velocity - command
  double forward_sway = 0.08, lateral_sway = 0.25;  // amplitudes [m/s]
};

Eigen::Matrix2Xd residuals(const wpg::WalkingParameters& w, const SyntheticWalk& s) {
  const wpg::NmpcModel model(w);
  wpg::NmpcProblem problem = model.makeProblem();
  problem.phase.pattern = 3;
  model.rowStepsOf(3, problem.phase.row_step);
  wpg::ReferenceBuilder builder(w);
  const double T = w.sampling_period, h0 = 0.3;
  builder.reset(h0);
  const int K = w.velocity_window_samples, C = 2 * w.stepSamples(), N = w.horizon_length;
  const auto heading = [&](int n) { return h0 + s.omega * n * T; };
  const auto velocity = [&](int n) -> Vector2d {  // world-frame CoM velocity at sample n
    // (a one-sample window averages no forward oscillation: none then)
    const double forward = K > 1 ? s.forward_sway : 0.0;
    const Vector2d sway(forward * std::sin(2.0 * M_PI * n / K + 0.4),
                        s.lateral_sway * std::sin(2.0 * M_PI * n / C + 1.1));
    return rotation(heading(n)) * (s.v + s.offset + sway);
  };
  const Vector3d command(s.v.x(), s.v.y(), s.omega);
  VectorXd planned_x(N), planned_y(N);
  const int last = 5 * C;
  for (int k = 0; k <= last; ++k) {
    for (int i = 0; i < N; ++i) {
      planned_x(i) = velocity(k + i + 1).x();
      planned_y(i) = velocity(k + i + 1).y();
    }
    builder.build(command, 0, 0.0, velocity(k), planned_x, planned_y, problem);
    builder.addSway(problem);
    builder.integrateHeading(s.omega, T);
  }
  const int window = w.trackedVelocityWindow();
  Eigen::Matrix2Xd r(2, N);
  for (int j = 0; j < N; ++j) {
    Vector2d mean = Vector2d::Zero();
    for (int i = std::max(0, j - window + 1); i <= j; ++i) mean += velocity(last + i + 1);
    r.col(j) = mean / window + Vector2d(problem.velocity_past_x(j), problem.velocity_past_y(j)) -
               Vector2d(problem.velocity_x(j), problem.velocity_y(j));
  }
  return r;
}

TEST(VelocityWindow, WithSwayChargesNeitherTheSwayNorTheTurnOfAPeriodicWalk) {
  wpg::WalkingParameters w;  // with_sway, command heading
  for (int window : {1, 4})
  for (double omega : {0.0, 0.2, -0.15}) {
    w.velocity_window_samples = window;
    SCOPED_TRACE(window);
    SyntheticWalk s;
    s.omega = omega;
    EXPECT_LT(residuals(w, s).cwiseAbs().maxCoeff(), 1e-12) << "omega " << omega;
    // A mean velocity off the command is charged, in full, at every previewed sample.
    s.offset = Vector2d(-0.02, 0.03);
    const Eigen::Matrix2Xd r = residuals(w, s);
    for (int j = 0; j < r.cols(); ++j) {
      const double h_j = 0.3 + omega * (5 * 16 + j + 1) * w.sampling_period;
      const Vector2d expected = rotation(h_j) * s.offset;
      EXPECT_LT((r.col(j) - expected).norm(), 1e-12) << "omega " << omega << ", sample " << j;
    }
  }
}

TEST(VelocityWindow, WithoutTheSwayTheWindowChargesTheLateralSway) {
  wpg::WalkingParameters w;
  w.velocity_tracking = wpg::VelocityTracking::kWindow;
  w.velocity_window_samples = 4;
  SyntheticWalk s;
  // The forward oscillation (the window's period) cancels in the window; the lateral sway (two
  // steps') not: its mean over 4 of 16 samples reaches 0.23 m/s for an amplitude of 0.25.
  EXPECT_GT(residuals(w, s).row(1).cwiseAbs().maxCoeff(), 0.1);
  s.lateral_sway = 0.0;
  EXPECT_LT(residuals(w, s).cwiseAbs().maxCoeff(), 1e-12);
  // The paper's instantaneous velocity charges both.
  w.velocity_tracking = wpg::VelocityTracking::kInstantaneous;
  EXPECT_GT(residuals(w, s).row(0).cwiseAbs().maxCoeff(), 0.07);
}

// Steady-state lateral speed: the mean over whole gait cycles, from t_from to the end.
double lateralSpeed(const wpg::WalkTrajectory& t, double t_from) {
  std::size_t a = 0;
  while (t.time[a] < t_from) ++a;
  const double cycle = 1.6;
  const int cycles = static_cast<int>((t.time.back() - t.time[a]) / cycle);
  std::size_t b = a;
  while (t.time[b] < t.time[a] + cycles * cycle - 1e-9) ++b;
  return (t.com[b].y() - t.com[a].y()) / (t.time[b] - t.time[a]);
}

TEST(VelocityWindow, TheDefaultWalksSidewaysAtTheCommandThePapersJ1DoesNot) {
  auto sideways = [](wpg::VelocityTracking tracking) {
    wpg::WalkingParameters parameters;
    parameters.velocity_tracking = tracking;
    if (tracking == wpg::VelocityTracking::kWindow) parameters.velocity_window_samples = 4;
    wpg::WalkRequest request;
    request.duration = 20.0;
    request.reference = {{0.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d(0.0, 0.1, 0.0)}};
    const wpg::WalkResult result = wpg::generateWalk(parameters, request);
    // Stepping in place at a twentieth of the command, the paper's J1 (and the short window)
    // end blocked (wpg/progress_monitor.hpp); nothing else fails any of the three walks.
    EXPECT_EQ(result.blocked, tracking != wpg::VelocityTracking::kWithSway) << result.message;
    EXPECT_TRUE(result.success || result.message.rfind("the robot is blocked: ", 0) == 0)
        << result.message;
    return lateralSpeed(result.trajectory, 8.0);
  };
  const double paper = sideways(wpg::VelocityTracking::kInstantaneous);
  const double window = sideways(wpg::VelocityTracking::kWindow);
  const double standard = sideways(wpg::VelocityTracking::kWithSway);
  RecordProperty("lateral_speed_instantaneous", std::to_string(paper));
  RecordProperty("lateral_speed_window", std::to_string(window));
  RecordProperty("lateral_speed_with_sway", std::to_string(standard));
  EXPECT_LT(paper, 0.015);               // measured 0.005 m/s of the 0.1 commanded
  EXPECT_LT(window, 0.03);               // measured 0.006
  EXPECT_NEAR(standard, 0.1, 0.01);      // measured 0.101
}

}  // namespace
