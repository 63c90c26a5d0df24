// Tests of OnlineWalkingGenerator, the per-control-period API: continuity of the CoM and the
// feet between control periods (across NMPC samples and landings), landings where reported,
// commands and obstacles given mid-walk, the push of one period, the fall, and the checks of
// every public entry point.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "wpg/online_walking_generator.hpp"
#include "wpg/walk_generator.hpp"

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using Eigen::Vector4d;
using Eigen::VectorXd;
using wpg::ControlSample;
using wpg::FootSide;
using wpg::GeneratorSettings;
using wpg::OnlineWalkingGenerator;
using wpg::WalkingParameters;

constexpr int kSubSamples = 20;  // 0.1 s / 5 ms

// Runs `periods` control periods and keeps every sample.
std::vector<ControlSample> run(OnlineWalkingGenerator& generator, int periods) {
  std::vector<ControlSample> samples;
  for (int i = 0; i < periods; ++i) samples.push_back(generator.step());
  return samples;
}

std::string what(const std::function<void()>& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(OnlineWalkingGenerator, StartsStandingAtTheResetPose) {
  OnlineWalkingGenerator generator{WalkingParameters(), GeneratorSettings()};
  generator.reset(Vector3d(1.0, -2.0, 0.5));
  EXPECT_DOUBLE_EQ(generator.time(), 0.0);
  EXPECT_TRUE(generator.atSamplingInstant());
  const ControlSample& s = generator.step();
  EXPECT_TRUE(s.nmpc_sample);
  EXPECT_EQ(s.support, wpg::SupportState::kDouble);
  EXPECT_NEAR(s.com_position.x(), 1.0, 1e-12);
  EXPECT_NEAR(s.com_position.y(), -2.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.com_position.z(), WalkingParameters().com_height);
  // The ankles 0.19 m apart across the yaw 0.5, the free flyer between them.
  const Vector2d across(-std::sin(0.5), std::cos(0.5));
  EXPECT_NEAR((s.left_foot.head<2>() - Vector2d(1.0, -2.0) - 0.095 * across).norm(), 0.0, 1e-12);
  EXPECT_NEAR((s.right_foot.head<2>() - Vector2d(1.0, -2.0) + 0.095 * across).norm(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.free_flyer_yaw, 0.5);
  EXPECT_FALSE(generator.step().nmpc_sample);
  EXPECT_NEAR(generator.time(), 0.01, 1e-12);
}

// generateWalk is a loop over the online API: the same command gives the same numbers.
TEST(OnlineWalkingGenerator, GivesWhatGenerateWalkRecords) {
  wpg::WalkRequest request;
  request.duration = 4.0;
  request.reference = {{0.0, Vector3d(0.2, 0.0, 0.1)}};
  const wpg::WalkResult walk = wpg::generateWalk(WalkingParameters(), request);
  ASSERT_TRUE(walk.success) << walk.message;
  OnlineWalkingGenerator generator(WalkingParameters(), request.generator);
  generator.setCommand(Vector3d(0.2, 0.0, 0.1));
  for (std::size_t i = 0; i + 1 < walk.trajectory.size(); ++i) {
    const ControlSample& s = generator.step();
    ASSERT_EQ(s.time, walk.trajectory.time[i]);
    ASSERT_EQ(s.com_position, walk.trajectory.com[i]) << "t = " << s.time;
    ASSERT_EQ(s.left_foot, walk.trajectory.left_foot[i]) << "t = " << s.time;
    ASSERT_EQ(s.right_foot, walk.trajectory.right_foot[i]) << "t = " << s.time;
  }
}

// CoM and feet between consecutive control periods: bounded first and second differences
// everywhere, in particular across NMPC samples (re-planned swing polynomials) and landings.
TEST(OnlineWalkingGenerator, CoMAndFeetAreContinuousBetweenControlPeriods) {
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  OnlineWalkingGenerator generator(w, GeneratorSettings());
  generator.setCommand(Vector3d(0.3, 0.05, 0.15));
  const double dt = w.control_period;
  std::vector<ControlSample> s = run(generator, 8 * kSubSamples * 8);  // 6.4 s, 7 steps
  int landings = 0;
  double max_foot_speed = 0.0, max_foot_acceleration = 0.0;
  for (std::size_t k = 1; k + 1 < s.size(); ++k) {
    // CoM: the position moves by the velocity, the velocity by the acceleration.
    const Vector3d mean_velocity = (s[k + 1].com_position - s[k].com_position) / dt;
    EXPECT_LT((mean_velocity - s[k].com_velocity).norm(), 0.5 * 10.0 * dt) << "t = " << s[k].time;
    EXPECT_LT((s[k + 1].com_velocity - s[k].com_velocity).norm(), 10.0 * dt) << "t = " << s[k].time;
    for (const auto foot : {&ControlSample::left_foot, &ControlSample::right_foot}) {
      const Vector4d a = s[k - 1].*foot, b = s[k].*foot, c = s[k + 1].*foot;
      max_foot_speed = std::max(max_foot_speed, (c - b).head<3>().norm() / dt);
      max_foot_acceleration =
          std::max(max_foot_acceleration, (c - 2.0 * b + a).head<3>().norm() / (dt * dt));
      EXPECT_LT((c - b).head<3>().norm(), 1.5 * dt) << "t = " << s[k].time;  // < 1.5 m/s
      // < 1.5 rad/s, the authors' code's bound on the landing's yaw rate: the command is
      // beyond the reach of 0.8 s steps and is walked with shorter ones (walking.step_timing:
      // adaptive), whose swing turns the foot at up to 1.27 rad/s (at t = 1.6 s).
      EXPECT_LT(std::abs(c(3) - b(3)), 1.5 * dt) << "t = " << s[k].time;
      // A jump of 1 mm at a landing or a re-plan would be 40 m/s^2 here.
      EXPECT_LT((c - 2.0 * b + a).head<3>().norm(), 12.0 * dt * dt) << "t = " << s[k].time;
      EXPECT_GE(b(2), -1e-12);
    }
  }
  for (std::size_t k = 0; k + 1 < s.size(); ++k) {  // single support followed by double
    if (s[k].support != wpg::SupportState::kDouble && s[k + 1].support == wpg::SupportState::kDouble)
      ++landings;
  }
  RecordProperty("max_foot_speed", std::to_string(max_foot_speed));
  RecordProperty("max_foot_acceleration", std::to_string(max_foot_acceleration));
  EXPECT_GE(landings, 6);
  EXPECT_GT(s.back().com_position.x(), 1.0);  // it walked
}

// At each landing the foot is on the ground where lastLanding() says, at the reported time,
// and the swing polynomial arrived there.
TEST(OnlineWalkingGenerator, SwingFootLandsWhereTheLandingIsReported) {
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  OnlineWalkingGenerator generator(w, GeneratorSettings());
  generator.setCommand(Vector3d(0.25, -0.05, -0.15));
  Vector3d lift_off[2] = {Vector3d::Zero(), Vector3d::Zero()};
  for (FootSide side : {FootSide::kLeft, FootSide::kRight})
    lift_off[side == FootSide::kLeft ? 0 : 1] = generator.patternGenerator().footPose(side);
  int landings = 0;
  for (int k = 0; k < 8 * kSubSamples * 8; ++k) {
    const ControlSample s = generator.step();
    if (!generator.landed()) continue;
    const wpg::Footstep& landing = generator.lastLanding();
    const auto foot = landing.side == FootSide::kLeft ? &ControlSample::left_foot
                                                      : &ControlSample::right_foot;
    // The landing is at the end of this control period.
    EXPECT_NEAR(landing.landing_time, generator.time(), 1e-9);
    // One control period before: the swing foot within 1 mm (and 1 mrad) of it, sole down.
    const Vector4d last_swing = s.*foot;
    EXPECT_LT((last_swing.head<2>() - landing.pose.head<2>()).norm(), 1e-3);
    EXPECT_LT(std::abs(last_swing(3) - landing.pose.z()), 1e-3);
    EXPECT_LT(last_swing(2), 1e-3);
    // The closing sample of the period (swing polynomial at its end) is the landing pose ...
    const Vector4d arrived = generator.currentSample().*foot;
    EXPECT_EQ(arrived.head<2>(), landing.pose.head<2>());
    EXPECT_EQ(arrived(3), landing.pose.z());
    EXPECT_LT(arrived(2), 1e-12);
    // ... and so is the next control period's, the foot on the ground.
    const ControlSample next = generator.step();
    ++k;
    EXPECT_EQ(next.*foot, Vector4d(landing.pose.x(), landing.pose.y(), 0.0, landing.pose.z()));
    // It was a step: the foot moved from where it lifted off.
    Vector3d& from = lift_off[landing.side == FootSide::kLeft ? 0 : 1];
    EXPECT_GT((landing.pose.head<2>() - from.head<2>()).norm(), 0.1);
    from = landing.pose;
    ++landings;
  }
  EXPECT_GE(landings, 6);
}

// A command given between two NMPC samples changes nothing before the next one, and is the
// reference of J1 from it on.
TEST(OnlineWalkingGenerator, ACommandTakesEffectAtTheNextNmpcSample) {
  // J1 on the instantaneous velocity, whose reference is the turned command itself (with a
  // window the new command enters the window's mean, test_velocity_window.cpp).
  WalkingParameters w;
  w.velocity_tracking = wpg::VelocityTracking::kInstantaneous;
  OnlineWalkingGenerator changed(w, GeneratorSettings()), reference(w, GeneratorSettings());
  for (OnlineWalkingGenerator* g : {&changed, &reference}) {
    g->setCommand(Vector3d(0.2, 0.0, 0.0));
    run(*g, 25 * kSubSamples + 7);  // 2.5 s, then 7 control periods into the sample
  }
  const Vector3d turn(0.1, 0.05, 0.2);
  changed.setCommand(turn);
  EXPECT_EQ(changed.command(), turn);
  for (int i = 7; i < kSubSamples; ++i) {  // the rest of the sampling period: unchanged
    const ControlSample a = changed.step(), b = reference.step();
    EXPECT_FALSE(a.nmpc_sample);
    EXPECT_EQ(a.com_position, b.com_position) << "t = " << a.time;
    EXPECT_EQ(a.com_acceleration, b.com_acceleration) << "t = " << a.time;
    EXPECT_EQ(a.left_foot, b.left_foot);
    EXPECT_EQ(a.right_foot, b.right_foot);
  }
  ASSERT_TRUE(changed.atSamplingInstant());
  const ControlSample a = changed.step(), b = reference.step();
  EXPECT_TRUE(a.nmpc_sample);
  // The state at the instant is the same; the NMPC already tracks the new command.
  EXPECT_EQ(a.com_position, b.com_position);
  const wpg::NmpcProblem& problem = changed.patternGenerator().problem();
  const wpg::PatternGenerator& pg = changed.patternGenerator();
  // J1's frame: the commanded heading (heading_reference: command, the default)
  const double heading = pg.commandedHeading();
  for (int j = 0; j < w.horizon_length; ++j) {
    const double yaw = heading + turn.z() * (j + 1) * w.sampling_period;
    EXPECT_NEAR(problem.velocity_x(j), std::cos(yaw) * turn.x() - std::sin(yaw) * turn.y(), 1e-12);
    EXPECT_NEAR(problem.velocity_y(j), std::sin(yaw) * turn.x() + std::cos(yaw) * turn.y(), 1e-12);
  }
  EXPECT_NEAR(reference.patternGenerator().problem().velocity_x(0), 0.2 * std::cos(heading), 1e-12);
  // From the instant on, the planned jerk differs.
  EXPECT_NE(pg.plan().jerk_y, reference.patternGenerator().plan().jerk_y);
  const ControlSample a1 = changed.step(), b1 = reference.step();
  EXPECT_NE(a1.com_acceleration, b1.com_acceleration);
}

wpg::Obstacle circle(double x, double y, double radius, double margin) {
  wpg::Obstacle o;
  o.center = Vector2d(x, y);
  o.radius = radius;
  o.margin = margin;
  return o;
}

// The smallest distance of a step centre to an obstacle grown by its margin and the sole
// radius (>= 0: the NMPC's constraint (18)-(19) holds).
double clearance(const wpg::ObstacleDistanceOracle& distance,
                 const std::vector<wpg::Obstacle>& obstacles, const WalkingParameters& w,
                 const Vector2d& step) {
  double worst = 1e9;
  for (int o = 0; o < static_cast<int>(obstacles.size()); ++o) {
    worst = std::min(worst, distance.signedDistance(o, step, nullptr) - obstacles[o].margin -
                                w.obstacle_foot_radius);
  }
  return worst;
}

// Obstacles given mid-walk (owned: the caller's vector is gone) keep every later step centre
// out of margin + obstacle_foot_radius; without them the same walk steps inside.
TEST(OnlineWalkingGenerator, ObstaclesGivenMidWalkAreRespected) {
  const WalkingParameters w;
  std::vector<wpg::Obstacle> kept;
  auto walk = [&](bool with_obstacles, std::vector<Vector3d>* landings) {
    OnlineWalkingGenerator generator(w, GeneratorSettings());
    generator.setCommand(Vector3d(0.2, 0.0, 0.0));
    run(generator, 20 * kSubSamples + 5);
    if (with_obstacles) {
      std::vector<wpg::Obstacle> local{circle(0.8, 0.3, 0.1, 0.1), circle(1.4, -0.35, 0.12, 0.05)};
      wpg::Obstacle box;
      box.type = wpg::ObstacleType::kBox;
      box.center = Vector2d(2.0, 0.35);
      box.size = Vector2d(0.2, 0.2);
      box.margin = 0.05;
      local.push_back(box);
      kept = local;
      generator.setObstacles(std::move(local));
    }
    // 30 s: the three obstacles stand in a tight slalom (0.26 m between the two circles' step
    // centre bounds, on the diagonal); the robot threads it without relaxing a row, slowly
    // (x = 2.3 m after 26 s, measured; a version that relaxed the rows walked straight through
    // in 13 s with step centres on the bound).
    for (int k = 0; k < 300 * kSubSamples; ++k) {
      generator.step();
      if (generator.landed()) landings->push_back(generator.lastLanding().pose);
      // A new obstacle may first meet a previewed step guessed inside it: that QP is
      // relaxed (obstacle rows first); never worse.
      const wpg::IterationStatus status = generator.lastIteration().status;
      EXPECT_TRUE(status == wpg::IterationStatus::kSolved || status == wpg::IterationStatus::kRelaxedObstacle)
          << "t = " << generator.time() << ": " << wpg::iterationStatusName(status);
    }
    EXPECT_FALSE(generator.fallen());
  };
  std::vector<Vector3d> free_steps, avoiding_steps;
  walk(false, &free_steps);
  walk(true, &avoiding_steps);
  const wpg::AnalyticObstacleDistance distance(kept);
  double worst_free = 1e9, worst_avoiding = 1e9;
  for (const Vector3d& step : free_steps)
    worst_free = std::min(worst_free, clearance(distance, kept, w, step.head<2>()));
  for (const Vector3d& step : avoiding_steps)
    worst_avoiding = std::min(worst_avoiding, clearance(distance, kept, w, step.head<2>()));
  RecordProperty("worst_clearance_without_obstacles", std::to_string(worst_free));
  RecordProperty("worst_clearance_with_obstacles", std::to_string(worst_avoiding));
  EXPECT_LT(worst_free, -0.05);  // the obstacles are on the way
  EXPECT_GE(worst_avoiding, -1e-6);
  ASSERT_GE(avoiding_steps.size(), 12u);
  EXPECT_GT(avoiding_steps.back().x(), 2.3);  // and it walked past them
}

TEST(OnlineWalkingGenerator, RemovingObstaclesMidWalkIsAllowed) {
  OnlineWalkingGenerator generator{WalkingParameters(), GeneratorSettings()};
  generator.setObstacles({circle(5.0, 0.0, 0.2, 0.1)});
  ASSERT_NE(generator.obstacleDistance(), nullptr);
  generator.setCommand(Vector3d(0.2, 0.0, 0.0));
  run(generator, 30 * kSubSamples);
  generator.setObstacles({});
  EXPECT_EQ(generator.obstacleDistance(), nullptr);
  run(generator, 10 * kSubSamples);
  EXPECT_EQ(generator.lastIteration().status, wpg::IterationStatus::kSolved);
}

// The push acts on the coming control period only: its acceleration is in that sample and
// moves the CoM, and is gone after.
TEST(OnlineWalkingGenerator, APushActsDuringTheComingControlPeriod) {
  const WalkingParameters w;
  OnlineWalkingGenerator pushed(w, GeneratorSettings()), free(w, GeneratorSettings());
  for (OnlineWalkingGenerator* g : {&pushed, &free}) {
    g->setCommand(Vector3d(0.2, 0.0, 0.0));
    run(*g, 20 * kSubSamples + 3);
  }
  pushed.setPushAcceleration(Vector2d(0.0, 2.0));
  const ControlSample a = pushed.step(), b = free.step();
  EXPECT_NEAR(a.com_acceleration.y() - b.com_acceleration.y(), 2.0, 1e-12);
  EXPECT_EQ(a.cop, b.cop);  // the push does not go through the feet
  const ControlSample a1 = pushed.step(), b1 = free.step();
  const double dt = w.control_period;
  EXPECT_NEAR(a1.com_velocity.y() - b1.com_velocity.y(), 2.0 * dt, 1e-12);
  EXPECT_NEAR(a1.com_position.y() - b1.com_position.y(), 2.0 * dt * dt / 2.0, 1e-12);
  EXPECT_EQ(a1.com_acceleration, b1.com_acceleration);  // no push in this period
}

TEST(OnlineWalkingGenerator, AFallStopsTheGenerator) {
  OnlineWalkingGenerator generator{WalkingParameters(), GeneratorSettings()};
  generator.setCommand(Vector3d(0.2, 0.0, 0.0));
  for (int k = 0; k < 400 && !generator.fallen(); ++k) {
    generator.setPushAcceleration(Vector2d(0.0, 30.0));
    generator.step();
  }
  ASSERT_TRUE(generator.fallen());
  EXPECT_EQ(generator.lastIteration().status, wpg::IterationStatus::kFallen);
  EXPECT_GT(generator.captureDistance(), GeneratorSettings().fall_capture_distance);
  const double t = generator.time();
  const ControlSample s = generator.step();
  EXPECT_EQ(generator.time(), t);
  EXPECT_EQ(s.time, t);
  generator.reset();
  EXPECT_FALSE(generator.fallen());
  EXPECT_EQ(generator.time(), 0.0);
}

TEST(OnlineWalkingGenerator, EntryPointsCheckSizesAndValues) {
  OnlineWalkingGenerator generator{WalkingParameters(), GeneratorSettings()};
  const double nan = std::nan("");
  EXPECT_NE(what([&] { generator.setCommand(VectorXd::Zero(2)); }).find("expected 3 entries"),
            std::string::npos);
  EXPECT_NE(what([&] { generator.setCommand(VectorXd::Zero(2)); }).find("got 2"), std::string::npos);
  EXPECT_NE(what([&] { generator.setCommand(Vector3d(0.1, nan, 0.0)); }).find("setCommand"),
            std::string::npos);
  EXPECT_THROW(generator.setPushAcceleration(Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(generator.setPushAcceleration(Vector2d(INFINITY, 0.0)), std::invalid_argument);
  EXPECT_THROW(generator.reset(VectorXd::Zero(4)), std::invalid_argument);
  EXPECT_THROW(generator.reset(Vector3d(0.0, 0.0, nan)), std::invalid_argument);
  // Obstacles: each validated, named by its index; nothing taken from a rejected call.
  wpg::Obstacle bad = circle(1.0, 1.0, -0.2, 0.1);
  EXPECT_NE(what([&] { generator.setObstacles({circle(1.0, 1.0, 0.2, 0.1), bad}); }).find("obstacles[1]"),
            std::string::npos);
  EXPECT_EQ(generator.obstacleDistance(), nullptr);
  EXPECT_NO_THROW(generator.setObstacles({circle(1.0, 1.0, 0.2, 0.1)}));
  ASSERT_NE(generator.obstacleDistance(), nullptr);
  EXPECT_EQ(generator.obstacleDistance()->obstacleCount(), 1);
  EXPECT_THROW(generator.setObstacles({bad}), std::invalid_argument);
  EXPECT_EQ(generator.obstacleDistance()->obstacleCount(), 1);  // the previous ones kept
  generator.setObstacles({});
  EXPECT_EQ(generator.obstacleDistance(), nullptr);
  // Parameters and settings are checked when the generator is built.
  WalkingParameters w;
  w.com_height = -1.0;
  EXPECT_THROW((OnlineWalkingGenerator{w, GeneratorSettings()}), std::invalid_argument);
  GeneratorSettings settings;
  settings.max_sqp_iterations = 0;
  EXPECT_NE(what([&] { OnlineWalkingGenerator{WalkingParameters(), settings}; })
                .find("generator.max_sqp_iterations"),
            std::string::npos);
  // The rejected calls changed nothing.
  EXPECT_EQ(generator.command(), Vector3d::Zero());
  EXPECT_EQ(generator.step().com_acceleration, Vector3d::Zero());
}

}  // namespace
