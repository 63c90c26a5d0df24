// WalkingParameters::heading_reference: the frame of J1's command and the target of J2's step
// yaws. support_foot is the paper's eq. (8) (each step turns by T_step * omega from the support
// foot); command tracks the commanded heading, the integral of omega since the walk started.
#include <gtest/gtest.h>

#include <cmath>

#include "../common/paper_gait.hpp"
#include "wpg/pattern_generator.hpp"
#include "wpg/walk_generator.hpp"

namespace {

wpg::WalkRequest curveRequest() {
  wpg::WalkRequest request;
  request.duration = 15.0;
  request.reference = {{0.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d(0.2, 0.0, 0.2)}};
  return request;
}

double finalYaw(wpg::HeadingReference reference, const wpg::WalkRequest& request) {
  // The paper's J2 weight (alpha) with the default yaw bound (0.2 rad/s needs 0.16 rad/step).
  wpg::WalkingParameters parameters = wpg_test::paperGait();
  parameters.max_step_yaw_change = 0.17;
  parameters.heading_reference = reference;
  const wpg::WalkResult result = wpg::generateWalk(parameters, request);
  EXPECT_TRUE(result.success) << result.message;
  return result.trajectory.free_flyer_yaw.back();
}

TEST(HeadingReference, ParsesItsNames) {
  wpg::HeadingReference r = wpg::HeadingReference::kSupportFoot;
  EXPECT_TRUE(wpg::parseHeadingReference("command", &r));
  EXPECT_EQ(r, wpg::HeadingReference::kCommand);
  EXPECT_TRUE(wpg::parseHeadingReference("support_foot", &r));
  EXPECT_EQ(r, wpg::HeadingReference::kSupportFoot);
  EXPECT_FALSE(wpg::parseHeadingReference("world", &r));
  EXPECT_STREQ(wpg::headingReferenceName(wpg::HeadingReference::kCommand), "command");
  EXPECT_STREQ(wpg::headingReferenceName(wpg::HeadingReference::kSupportFoot), "support_foot");
  // The default (straight walks and tracked turns); the paper's is support_foot.
  EXPECT_EQ(wpg::WalkingParameters().heading_reference, wpg::HeadingReference::kCommand);
}

TEST(HeadingReference, CommandHeadingTracksTheIntegralOfOmega) {
  // 0.2 rad/s for 14 s: 2.8 rad commanded. The paper's chained J2 (weight alpha = 2.5) loses
  // yaw at every step and ends near 2.0 rad; tracking the commanded heading catches up to
  // within about one step's turn (0.16 rad; the feet land once per 0.8 s).
  const double commanded = 0.2 * 14.0;
  const double paper = finalYaw(wpg::HeadingReference::kSupportFoot, curveRequest());
  const double command = finalYaw(wpg::HeadingReference::kCommand, curveRequest());
  RecordProperty("final_yaw_support_foot", std::to_string(paper));
  RecordProperty("final_yaw_command", std::to_string(command));
  EXPECT_LT(paper, commanded - 0.5);
  EXPECT_NEAR(command, commanded, 0.2);
}

TEST(HeadingReference, IntegratesOmegaFromTheHeadingAtTheStart) {
  wpg::WalkingParameters parameters;
  parameters.heading_reference = wpg::HeadingReference::kCommand;
  // J1 on the instantaneous velocity: its reference is the turned command itself (a window
  // averages it, test_velocity_window.cpp).
  parameters.velocity_tracking = wpg::VelocityTracking::kInstantaneous;
  wpg::PatternGenerator generator(parameters, wpg::GeneratorSettings());
  generator.reset(Eigen::Vector3d(1.0, 2.0, 0.5));
  EXPECT_DOUBLE_EQ(generator.commandedHeading(), 0.5);
  const Eigen::Vector3d command(0.2, 0.05, 0.1);
  const double T = parameters.sampling_period;
  for (int k = 0; k < 12; ++k) {
    generator.update(k * T, command);
    // The command held for k samples since the walk started at t = 0.
    EXPECT_NEAR(generator.commandedHeading(), 0.5 + 0.1 * k * T, 1e-12) << "sample " << k;
    // J1's reference at horizon sample j: the command turned by the heading at that sample.
    for (int j : {0, 7, 15}) {
      const double yaw = 0.5 + 0.1 * (k + j + 1) * T;
      EXPECT_NEAR(generator.problem().velocity_x(j),
                  std::cos(yaw) * command.x() - std::sin(yaw) * command.y(), 1e-12);
      EXPECT_NEAR(generator.problem().velocity_y(j),
                  std::sin(yaw) * command.x() + std::cos(yaw) * command.y(), 1e-12);
    }
    generator.advance(generator.comX(), generator.comY());
  }
}

TEST(HeadingReference, ARestartWalksOnFromWhereTheRobotStopped) {
  // Turn, stop, stand, then walk straight: the commanded heading restarts from the feet, so
  // the robot does not turn on to the heading commanded before it stopped. With the paper's
  // yaw bound (0.05 rad per step) the feet turn at most 0.0625 rad/s, far behind the command's
  // 0.2 rad/s: about 0.25 rad when it stops, against 0.8 commanded.
  wpg::WalkRequest request;
  request.duration = 16.0;
  request.reference = {{0.0, Eigen::Vector3d::Zero()},
                       {1.0, Eigen::Vector3d(0.1, 0.0, 0.2)},
                       {5.0, Eigen::Vector3d::Zero()},
                       {9.0, Eigen::Vector3d(0.2, 0.0, 0.0)}};
  // The paper's yaw bound and J2 weight (the situation this test builds), command heading.
  wpg::WalkingParameters parameters = wpg_test::paperGait();
  parameters.heading_reference = wpg::HeadingReference::kCommand;
  const wpg::WalkResult result = wpg::generateWalk(parameters, request);
  ASSERT_TRUE(result.success) << result.message;
  const wpg::WalkTrajectory& t = result.trajectory;
  std::size_t stop = 0;
  while (t.time[stop] < 9.0) ++stop;
  const double stopped_yaw = t.free_flyer_yaw[stop];
  EXPECT_GT(stopped_yaw, 0.15);  // it did turn, ...
  EXPECT_LT(stopped_yaw, 0.5);   // ... far less than commanded
  // Within the yaw the paper's weights give every other foot (docs/formulation.md).
  EXPECT_NEAR(t.free_flyer_yaw.back(), stopped_yaw, 0.05);
  // ... and walks along that heading.
  const Eigen::Vector2d walked = (t.com.back() - t.com[stop]).head<2>();
  EXPECT_GT(walked.norm(), 0.8);
  EXPECT_NEAR(std::atan2(walked.y(), walked.x()), stopped_yaw, 0.1);
}

}  // namespace
