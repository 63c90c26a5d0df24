// Acceptance invariants of the issue on every shipped scenario: run the whole walk as
// `wpg run` does and check the physical properties of the result (libwpg/walk_checks).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "wpg/datasets/scenario.hpp"
#include "wpg/walk_checks.hpp"
#include "wpg/walk_generator.hpp"

namespace {

const std::string kSource = WPG_SOURCE_DIR;

wpg::datasets::Scenario load(const std::string& name) {
  return wpg::datasets::loadScenario(kSource + "/datasets/scenarios/" + name + ".yaml", {},
                                     kSource + "/robots");
}

class ShippedWalk : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedWalk, KeepsBalanceAndStepFeasibility) {
  const wpg::datasets::Scenario scenario = load(GetParam());
  const wpg::WalkResult result = wpg::generateWalk(scenario.walking, scenario.request);
  ASSERT_TRUE(result.success) << result.message;
  // Without obstacles every QP is feasible; with them the obstacle rows may be relaxed (the
  // robot is blocked), never the balance rows.
  for (const wpg::MpcIterationLog& log : result.trajectory.mpc) {
    if (scenario.request.obstacles.empty())
      EXPECT_EQ(log.status, wpg::IterationStatus::kSolved) << "t = " << log.time;
    else
      EXPECT_TRUE(log.status == wpg::IterationStatus::kSolved ||
                  log.status == wpg::IterationStatus::kRelaxedObstacle) << "t = " << log.time;
  }
  // No step centre inside an obstacle grown by its margin and the sole radius (eq. 18-19, the
  // NMPC's obstacle rows).
  if (!scenario.request.obstacles.empty()) {
    const wpg::AnalyticObstacleDistance distance(scenario.request.obstacles);
    for (const wpg::Footstep& step : result.trajectory.footsteps) {
      if (step.landing_time <= 0.0) continue;
      for (int o = 0; o < distance.obstacleCount(); ++o) {
        const double clearance = distance.signedDistance(o, step.pose.head<2>(), nullptr) -
                                 scenario.request.obstacles[o].margin -
                                 scenario.walking.obstacle_foot_radius;
        EXPECT_GE(clearance, -1e-4) << "step landing at t = " << step.landing_time
                                    << " inside obstacle " << o << "'s margin";
      }
    }
  }
  const wpg::WalkCheckReport report = wpg::checkWalk(scenario.walking, result.trajectory);
  // CoP inside the margin-reduced polygon at every NMPC sample (eq. 9-13) ...
  EXPECT_LE(report.cop_sample_violation, 1e-9) << "at t = " << report.cop_sample_violation_time;
  // ... and inside the sole (support polygon without margins) at every 5 ms sample.
  EXPECT_LE(report.cop_control_violation, 1e-9) << "at t = " << report.cop_control_violation_time;
  // Steps inside the previous step's feasibility polygon (eq. 14) and yaw bound (eq. 16).
  EXPECT_LE(report.feasibility_violation, 1e-9);
  EXPECT_LE(report.max_step_yaw_change, scenario.walking.max_step_yaw_change + 1e-9);
  // A walk takes steps; the pushed standing robot takes two (the catching and the final one).
  EXPECT_GE(report.landed_steps, GetParam() == "push_standing" ? 2 : 4);
  RecordProperty("cop_margin_excursion_m", std::to_string(report.cop_margin_excursion));
  RecordProperty("speed_after_two_steps", std::to_string(report.speed_after_two_steps));
}

INSTANTIATE_TEST_SUITE_P(Scenarios, ShippedWalk,
                         ::testing::Values("walk_forward", "walk_sideways", "turn_on_the_spot",
                                           "curve", "start_walk_stop", "push",
                                           "paper_experiment_a", "paper_experiment_b",
                                           "obstacle_boxes", "obstacle_polygon",
                                           "obstacle_cluttered", "push_standing",
                                           "push_stepping_in_place"));

TEST(ShippedWalks, EveryShippedScenarioIsCovered) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/datasets/scenarios"))
    if (entry.path().extension() == ".yaml") ++count;
  // + the four walks to a goal (goal_*.yaml), run by tests/planning/test_goal_scenarios.cpp:
  // they need the route planner.
  EXPECT_EQ(count, 13 + 4) << "a new shipped scenario must be added to the list above";
}

TEST(ShippedWalks, WalkForwardTracksTheCommandedSpeed) {
  const wpg::datasets::Scenario scenario = load("walk_forward");
  const wpg::WalkResult result = wpg::generateWalk(scenario.walking, scenario.request);
  const wpg::WalkCheckReport report = wpg::checkWalk(scenario.walking, result.trajectory);
  const double command = scenario.request.reference.back().velocity.x();
  EXPECT_NEAR(report.speed_after_two_steps, command, 0.1 * command);
}

TEST(ShippedWalks, CurveTurnsAndTurnOnTheSpotStaysInPlace) {
  const wpg::datasets::Scenario curve = load("curve");
  const wpg::WalkResult c = wpg::generateWalk(curve.walking, curve.request);
  // omega = 0.2 rad/s for 14 s after the start (2.8 rad if tracked exactly; the paper's weak
  // yaw weight alpha = 2.5 gives about 1.9 rad): the heading must have turned by > 1.5 rad.
  EXPECT_GT(c.trajectory.free_flyer_yaw.back(), 1.5);
  RecordProperty("curve_final_yaw_rad", std::to_string(c.trajectory.free_flyer_yaw.back()));
  const wpg::datasets::Scenario spot = load("turn_on_the_spot");
  const wpg::WalkResult s = wpg::generateWalk(spot.walking, spot.request);
  EXPECT_GT(s.trajectory.free_flyer_yaw.back(), 1.0);
  EXPECT_LT((s.trajectory.com.back() - s.trajectory.com.front()).head<2>().norm(), 0.1);
}

TEST(ShippedWalks, PushAtAnUnrecoverableMomentEndsAsAFall) {
  const wpg::datasets::Scenario scenario = wpg::datasets::loadScenario(
      kSource + "/datasets/scenarios/push.yaml", {"pushes[0].t=4.0"}, kSource + "/robots");
  const wpg::WalkResult result = wpg::generateWalk(scenario.walking, scenario.request);
  EXPECT_FALSE(result.success);
  ASSERT_FALSE(result.trajectory.mpc.empty());
  EXPECT_EQ(result.trajectory.mpc.back().status, wpg::IterationStatus::kFallen);
  for (const auto& com : result.trajectory.com) ASSERT_TRUE(com.allFinite());
  EXPECT_LT(result.trajectory.time.back(), scenario.request.duration);
}

}  // namespace
