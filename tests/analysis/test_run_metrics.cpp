// computeRunMetrics on hand-made trajectories whose metrics are known in closed form, the
// quantile's interpolation, and the metric table (names unique, every field listed once).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "wpg/analysis/run_metrics.hpp"

using wpg::IterationStatus;
using wpg::analysis::computeRunMetrics;
using wpg::analysis::quantile;
using wpg::analysis::RunMetrics;

namespace {

// Standing on the left foot (ankle at the origin, yaw 0) for `samples` control periods while
// the CoM moves at `velocity` along x; CoP at `cop`.
wpg::WalkTrajectory straightLine(std::size_t samples, double velocity, const Eigen::Vector2d& cop,
                                 double period) {
  wpg::WalkTrajectory t;
  for (std::size_t i = 0; i < samples; ++i) {
    const double time = period * static_cast<double>(i);
    t.time.push_back(time);
    t.com.emplace_back(velocity * time, 0.0, 0.814);
    t.com_vel.emplace_back(velocity, 0.0, 0.0);
    t.com_acc.emplace_back(0.0, 0.0, 0.0);
    t.cop.push_back(cop);
    t.left_foot.emplace_back(0.0, 0.0, 0.0, 0.0);
    t.right_foot.emplace_back(0.0, -0.19, 0.1, 0.0);
    t.free_flyer_yaw.push_back(0.0);
    t.support.push_back(wpg::SupportState::kLeft);
  }
  return t;
}

// The result of a walk with this trajectory and verdict.
wpg::WalkResult walkResult(wpg::WalkTrajectory t, bool success = true) {
  wpg::WalkResult result;
  result.trajectory = std::move(t);
  result.success = success;
  return result;
}

}  // namespace

TEST(RunMetrics, QuantileInterpolatesBetweenOrderStatistics) {
  EXPECT_DOUBLE_EQ(quantile({3.0, 1.0, 2.0, 4.0}, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(quantile({3.0, 1.0, 2.0, 4.0}, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile({3.0, 1.0, 2.0, 4.0}, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(quantile({0.0, 10.0}, 0.99), 9.9);
  EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
}

TEST(RunMetrics, HandMadeWalk) {
  wpg::WalkingParameters w;
  wpg::WalkRequest request;
  request.reference = {{0.0, Eigen::Vector3d(0.25, 0.0, 0.0)}};
  const double v = 0.2;
  // CoP 0.02 m in front of the ankle, 0.01 m to the left: the nearest sole edge is the side,
  // foot_width / 2 - 0.01 away
  wpg::WalkTrajectory t = straightLine(1000, v, Eigen::Vector2d(0.02, 0.01), w.control_period);
  const int statuses[] = {0, 0, 1, 2, 6, 0, 3};
  for (int k = 0; k < 7; ++k) {
    wpg::MpcIterationLog log;
    log.status = static_cast<IterationStatus>(statuses[k]);
    log.qp_iterations = k + 1;
    log.solve_time = 1e-5 * (k + 1);
    t.mpc.push_back(log);
  }
  const RunMetrics m = computeRunMetrics(w, request, walkResult(t, false), nullptr);
  EXPECT_EQ(m.success, 0.0);
  EXPECT_NEAR(m.distance, v * 999 * w.control_period, 1e-12);
  // the CoM's mean velocity is v, the reference 0.25: error 0.05 at every sample
  EXPECT_NEAR(m.velocity_error_rms, 0.05, 1e-12);
  EXPECT_NEAR(m.velocity_error_max, 0.05, 1e-12);
  const double side = 0.5 * w.foot_width - 0.01;
  EXPECT_NEAR(m.cop_margin_min, side, 1e-12);
  EXPECT_NEAR(m.cop_margin_median, side, 1e-12);
  EXPECT_NEAR(m.cop_margin_mean, side, 1e-12);
  EXPECT_TRUE(std::isnan(m.step_feasibility_margin_min));  // no landed step
  EXPECT_TRUE(std::isnan(m.obstacle_clearance_min));        // no obstacle
  EXPECT_EQ(m.swing_speed_max, 0.0);                         // the feet stand still
  EXPECT_EQ(m.swing_acceleration_max, 0.0);
  EXPECT_TRUE(std::isnan(m.zmp_error_rms_before));          // not replayed
  EXPECT_EQ(m.nmpc_iterations, 7.0);
  EXPECT_DOUBLE_EQ(m.qp_iterations_total, 28.0);
  EXPECT_DOUBLE_EQ(m.qp_iterations_mean, 4.0);
  EXPECT_DOUBLE_EQ(m.qp_iterations_max, 7.0);
  EXPECT_EQ(m.relaxed_iterations, 2.0);  // codes 1 and 6
  EXPECT_EQ(m.failed_iterations, 2.0);   // codes 2 and 3
  EXPECT_NEAR(m.nmpc_time_mean, 4e-5, 1e-15);
  EXPECT_NEAR(m.nmpc_time_min, 1e-5, 1e-15);
  EXPECT_NEAR(m.nmpc_time_max, 7e-5, 1e-15);
  EXPECT_NEAR(m.nmpc_time_p99, 1e-5 * (6.0 + 0.94), 1e-15);  // position 0.99 * 6 = 5.94
  EXPECT_NEAR(m.nmpc_time_std, 1e-5 * std::sqrt(28.0 / 6.0), 1e-15);
}

TEST(RunMetrics, VelocityErrorLeavesOutTheStartAndFollowsIterationCommands) {
  wpg::WalkingParameters w;  // gait cycle W = 2 x 0.8 s = 320 samples of 5 ms
  const std::size_t window = 320;
  ASSERT_EQ(static_cast<std::size_t>(std::lround(2.0 * w.stepDuration() / w.control_period)),
            window);
  // One NMPC iteration every 0.1 s, commanding 0.2 m/s along x from 1 s on; the CoM starts
  // 0.8 s later (the lag of a start from rest), then walks the command, 7 s in all.
  const auto walk = [&](std::size_t samples) {
    wpg::WalkTrajectory t = straightLine(samples, 0.0, Eigen::Vector2d::Zero(), w.control_period);
    for (std::size_t i = 360; i < t.size(); ++i) {
      t.com[i].x() = 0.2 * (t.time[i] - 1.8);
      t.com_vel[i].x() = 0.2;
    }
    for (int k = 0; k < 70; ++k) {
      wpg::MpcIterationLog log;
      log.time = 0.1 * k;
      log.command = Eigen::Vector3d(k < 10 ? 0.0 : 0.2, 0.0, 0.0);
      t.mpc.push_back(log);
    }
    return t;
  };
  const auto commanded = wpg::analysis::VelocityReference::kIterationCommands;
  const wpg::WalkRequest goal_walk;  // no schedule: a walk to a goal
  wpg::WalkTrajectory t = walk(1400);
  const RunMetrics m = computeRunMetrics(w, goal_walk, walkResult(t), nullptr, commanded);
  // The windows begin one cycle after the first command (1 s + 1.6 s) or later: the CoM walks
  // the command in all of them. Those that began earlier had errors up to 0.1 (the lag).
  EXPECT_NEAR(m.velocity_error_rms, 0.0, 1e-12);
  EXPECT_NEAR(m.velocity_error_max, 0.0, 1e-12);
  // The same walk on the request's schedule (none: zero): the CoM's 0.2 m/s is the error.
  const RunMetrics scheduled = computeRunMetrics(w, goal_walk, walkResult(t), nullptr);
  EXPECT_NEAR(scheduled.velocity_error_max, 0.2, 1e-12);
  // A command that changes mid-walk is measured as it was given: 0.3 m/s from 5 s on, which
  // the CoM does not follow, an error ramping up to 0.1 over one cycle.
  for (std::size_t k = 50; k < t.mpc.size(); ++k) t.mpc[k].command.x() = 0.3;
  const RunMetrics changed = computeRunMetrics(w, goal_walk, walkResult(t), nullptr, commanded);
  EXPECT_NEAR(changed.velocity_error_max, 0.1, 1e-12);
  EXPECT_GT(changed.velocity_error_rms, 0.01);
  // Commands not known (a file that does not store them): NaN, never a guess.
  t.mpc[3].command.setConstant(std::numeric_limits<double>::quiet_NaN());
  const RunMetrics unknown = computeRunMetrics(w, goal_walk, walkResult(t), nullptr, commanded);
  EXPECT_TRUE(std::isnan(unknown.velocity_error_rms));
  EXPECT_TRUE(std::isnan(unknown.velocity_error_max));
  // Too short to hold a window after the start (3.5 s < 1 s + 2 cycles): NaN.
  EXPECT_TRUE(std::isnan(computeRunMetrics(w, goal_walk, walkResult(walk(700)), nullptr, commanded)
                             .velocity_error_rms));
}

TEST(RunMetrics, StepsObstaclesAndZmpError) {
  wpg::WalkingParameters w;
  wpg::WalkRequest request;
  wpg::Obstacle circle;
  circle.type = wpg::ObstacleType::kCircle;
  circle.center = Eigen::Vector2d(1.0, 0.0);
  circle.radius = 0.2;
  circle.margin = 0.05;
  request.obstacles = {circle};
  wpg::WalkTrajectory t = straightLine(10, 0.0, Eigen::Vector2d::Zero(), w.control_period);
  const auto step = [](double time, double x, double y, double yaw, wpg::FootSide side) {
    wpg::Footstep f;
    f.landing_time = time;
    f.pose = Eigen::Vector3d(x, y, yaw);
    f.side = side;
    return f;
  };
  t.footsteps = {step(0.0, 0.0, 0.095, 0.0, wpg::FootSide::kLeft),
                 step(0.0, 0.0, -0.095, 0.0, wpg::FootSide::kRight),
                 // 0.1 m ahead, 0.25 m to the left of the right foot, turned by 0.03 rad
                 step(0.8, 0.1, 0.155, 0.03, wpg::FootSide::kLeft)};
  wpg::analysis::ZmpErrorComparison zmp;
  zmp.filtered = true;
  zmp.before = {0.02, 0.05};
  zmp.after = {0.004, 0.01};
  const RunMetrics m = computeRunMetrics(w, request, walkResult(t), &zmp);
  EXPECT_NEAR(m.yaw_bound_margin_min, w.max_step_yaw_change - 0.03, 1e-15);
  // (0.1, 0.25) in the left feasibility polygon (eq. 14): its nearest edge is y = 0.2, 0.05 m
  // away (the others are 0.089 m and more)
  EXPECT_NEAR(m.step_feasibility_margin_min, 0.05, 1e-12);
  // the nearest step to the circle is the last: |(0.1, 0.155) - (1, 0)| - R - margin - foot radius
  EXPECT_NEAR(m.obstacle_clearance_min,
              std::hypot(0.9, 0.155) - 0.2 - 0.05 - w.obstacle_foot_radius, 1e-12);
  EXPECT_DOUBLE_EQ(m.zmp_error_rms_before, 0.02);
  EXPECT_DOUBLE_EQ(m.zmp_error_max_after, 0.01);
  // Replayed, never filtered: no error after the filter (absent, not a copy of before).
  zmp.filtered = false;
  zmp.after = zmp.before;
  const RunMetrics replayed = computeRunMetrics(w, request, walkResult(t), &zmp);
  EXPECT_DOUBLE_EQ(replayed.zmp_error_rms_before, 0.02);
  EXPECT_TRUE(std::isnan(replayed.zmp_error_rms_after));
  EXPECT_TRUE(std::isnan(replayed.zmp_error_max_after));
}

// progress_ratio (METRICS.md): the CoM's displacement along the commanded world velocity of
// each NMPC row, over the commanded distance, over the rows with a linear command whose next
// sampling instant is a sample of the walk.
TEST(RunMetrics, ProgressRatioOfAStraightAndOfABlockedWalk) {
  wpg::WalkingParameters w;  // T = 0.1 s, 5 ms samples: 20 samples a row
  // 10 s at 0.2 m/s along x, commanded (0.2, 0) from the first row on: every period walks its
  // command.
  wpg::WalkTrajectory t = straightLine(2001, 0.2, Eigen::Vector2d::Zero(), w.control_period);
  for (int k = 0; k < 100; ++k) {
    wpg::MpcIterationLog log;
    log.time = 0.1 * k;
    log.commanded_velocity = Eigen::Vector2d(0.2, 0.0);
    t.mpc.push_back(log);
  }
  EXPECT_NEAR(computeRunMetrics(w, {}, walkResult(t), nullptr).progress_ratio, 1.0, 1e-12);
  // Standing still for the first second (no command in rows 0-9): those rows do not count.
  for (int k = 0; k < 10; ++k) t.mpc[k].commanded_velocity.setZero();
  for (std::size_t i = 0; i < t.size(); ++i) t.com[i].x() = std::max(0.0, 0.2 * (t.time[i] - 1.0));
  EXPECT_NEAR(computeRunMetrics(w, {}, walkResult(t), nullptr).progress_ratio, 1.0, 1e-12);
  // Blocked at x = 0.3 m from 2.5 s on: 0.3 m walked of the 1.8 m commanded from 1 s to 10 s.
  for (std::size_t i = 0; i < t.size(); ++i) t.com[i].x() = std::min(t.com[i].x(), 0.3);
  EXPECT_NEAR(computeRunMetrics(w, {}, walkResult(t), nullptr).progress_ratio, 0.3 / 1.8, 1e-12);
  // A command across the motion: no progress along it; sideways commanded, x walked.
  for (wpg::MpcIterationLog& log : t.mpc) {
    if (log.commanded_velocity.norm() > 0.0) log.commanded_velocity = Eigen::Vector2d(0.0, 0.2);
  }
  EXPECT_NEAR(computeRunMetrics(w, {}, walkResult(t), nullptr).progress_ratio, 0.0, 1e-12);
  // No linear command at all (turning on the spot): it does not apply.
  for (wpg::MpcIterationLog& log : t.mpc) log.commanded_velocity.setZero();
  EXPECT_TRUE(std::isnan(computeRunMetrics(w, {}, walkResult(t), nullptr).progress_ratio));
  // Not stored (a file written before it was): NaN, never a guess.
  t.mpc[5].commanded_velocity.setConstant(std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isnan(computeRunMetrics(w, {}, walkResult(t), nullptr).progress_ratio));
}

TEST(RunMetrics, BlockedAndSinceFromTheVerdict) {
  wpg::WalkingParameters w;
  wpg::WalkResult walk =
      walkResult(straightLine(10, 0.0, Eigen::Vector2d::Zero(), w.control_period));
  RunMetrics m = computeRunMetrics(w, {}, walk, nullptr);
  EXPECT_EQ(m.blocked, 0.0);
  EXPECT_TRUE(std::isnan(m.blocked_since));  // does not apply
  walk.success = false;
  walk.blocked = true;
  walk.blocked_since = 12.3;
  m = computeRunMetrics(w, {}, walk, nullptr);
  EXPECT_EQ(m.success, 0.0);
  EXPECT_EQ(m.blocked, 1.0);
  EXPECT_EQ(m.blocked_since, 12.3);
}

TEST(RunMetrics, TableListsEveryFieldOnceWithAUnit) {
  std::set<std::string> names;
  std::set<std::ptrdiff_t> offsets;  // of each field in a RunMetrics
  RunMetrics metrics;
  const auto* base = reinterpret_cast<const char*>(&metrics);
  for (const auto& metric : wpg::analysis::runMetricTable()) {
    EXPECT_TRUE(names.insert(metric.name).second) << metric.name;
    const auto* field = reinterpret_cast<const char*>(&(metrics.*metric.field));
    EXPECT_TRUE(offsets.insert(field - base).second) << metric.name;
    EXPECT_FALSE(std::string(metric.unit).empty()) << metric.name;
  }
  EXPECT_EQ(offsets.size() * sizeof(double), sizeof(RunMetrics));
}
