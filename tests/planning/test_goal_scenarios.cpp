// The shipped walks to a goal (datasets/scenarios/goal_*.yaml), run as `wpg run` runs them and
// checked on the data: the goal reached standing within its tolerance, every step centre
// outside every margin by the FCL world's post-check, the walk's physical invariants; the U
// trap without a planner holds the robot; the unknown obstacle is sensed and replanned round.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/planning/goal_walk.hpp"
#include "wpg/planning/obstacle_checks.hpp"
#include "wpg/walk_checks.hpp"
#include "../common/source_dir.hpp"

namespace {

const std::string kSource = wpg_test::sourceDir();

wpg::datasets::Scenario load(const std::string& name,
                             const std::vector<std::string>& overrides = {}) {
  return wpg::datasets::loadScenario(kSource + "/datasets/scenarios/" + name + ".yaml", overrides,
                                     kSource + "/robots");
}

class ShippedGoalWalk : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedGoalWalk, ReachesTheGoalWithEveryStepOutOfTheMargins) {
  const wpg::datasets::Scenario scenario = load(GetParam());
  const wpg::planning::GoalWalkResult walk =
      wpg::planning::walkToGoal(scenario.walking, scenario.request, scenario.goal);
  ASSERT_TRUE(walk.goal_reached) << walk.outcome;
  EXPECT_TRUE(walk.walk.success) << walk.walk.message;
  EXPECT_LE(walk.final_distance, scenario.goal.goal.tolerance);
  if (scenario.goal.goal.has_yaw) EXPECT_LE(walk.final_yaw_error, scenario.goal.goal.yaw_tolerance);
  EXPECT_LT(walk.time_to_goal, scenario.request.duration);
  for (const wpg::planning::PlanRecord& plan : walk.plans)
    EXPECT_EQ(plan.plan.status, wpg::planning::PlanStatus::kExactSolution);
  // The FCL post-check of every step: centre beyond margin + obstacle_foot_radius.
  const wpg::planning::World world(scenario.request.obstacles);
  const wpg::planning::FootstepObstacleReport steps =
      wpg::planning::checkFootsteps(world, scenario.walking, walk.walk.trajectory);
  EXPECT_GE(steps.min_centre_clearance, -1e-9) << "step " << steps.min_centre_clearance_step;
  const wpg::WalkCheckReport report = wpg::checkWalk(scenario.walking, walk.walk.trajectory);
  EXPECT_LE(report.cop_sample_violation, 1e-9);
  EXPECT_LE(report.feasibility_violation, 1e-9);
  EXPECT_LE(report.max_step_yaw_change, scenario.walking.max_step_yaw_change + 1e-9);
  RecordProperty("time_to_goal_s", std::to_string(walk.time_to_goal));
  RecordProperty("replans", std::to_string(walk.plans.size() - 1));
}

INSTANTIATE_TEST_SUITE_P(Scenarios, ShippedGoalWalk,
                         ::testing::Values("goal_cluttered", "goal_u_trap", "goal_unknown_obstacle",
                                           "goal_with_yaw"));

TEST(ShippedGoalWalks, TheUnknownObstacleIsSensedAndTheRouteReplannedRoundIt) {
  const wpg::datasets::Scenario scenario = load("goal_unknown_obstacle");
  const wpg::planning::GoalWalkResult walk =
      wpg::planning::walkToGoal(scenario.walking, scenario.request, scenario.goal);
  ASSERT_GE(walk.plans.size(), 2u);
  // The first route, planned without the circle, runs through it; the replan knows it.
  EXPECT_EQ(walk.plans[0].known_obstacles, 1);
  EXPECT_EQ(walk.plans[1].trigger, wpg::planning::PlanTrigger::kBlocked);
  EXPECT_EQ(walk.plans[1].known_obstacles, 2);
  const wpg::planning::World circle({scenario.request.obstacles[0]});
  const double radius = scenario.goal.planner.robot_radius;
  const auto crosses = [&](const std::vector<Eigen::Vector3d>& route) {
    for (std::size_t i = 1; i < route.size(); ++i)
      for (int k = 0; k <= 100; ++k) {
        const Eigen::Vector2d p =
            route[i - 1].head<2>() + (route[i] - route[i - 1]).head<2>() * k / 100.0;
        if (!circle.isStateValid(p.x(), p.y(), radius)) return true;
      }
    return false;
  };
  EXPECT_TRUE(crosses(walk.plans[0].plan.waypoints));
  EXPECT_FALSE(crosses(walk.plans[1].plan.waypoints));
  // Sensed within the range: the CoM was at most sensing_range from the circle's margin.
  EXPECT_GT(walk.plans[1].time, 1.0);
  EXPECT_LE(circle.clearance(walk.plans[1].start.head<2>()), scenario.goal.planner.sensing_range);
  EXPECT_TRUE(walk.goal_reached) << walk.outcome;
}

TEST(ShippedGoalWalks, TheUTrapHoldsARobotCommandedStraightAtTheGoal) {
  const wpg::datasets::Scenario scenario = load("goal_u_trap", {"planner.algorithm=none"});
  const wpg::planning::GoalWalkResult walk =
      wpg::planning::walkToGoal(scenario.walking, scenario.request, scenario.goal);
  EXPECT_FALSE(walk.goal_reached);
  EXPECT_FALSE(walk.walk.success);
  EXPECT_NE(walk.outcome.find("out of time"), std::string::npos) << walk.outcome;
  // Held inside the U, short of its back wall (x = 2.5): the goal (4.2, 0) stays > 1.5 m away.
  EXPECT_LT(walk.final_pose.x(), 2.5);
  EXPECT_GT(walk.final_distance, 1.5);
  // Stuck is an outcome: blocked from the window that starts at 10.9 s, in front of the back
  // wall; the goal's own outcome stays (out of time) and the message says both.
  EXPECT_TRUE(walk.walk.blocked);
  EXPECT_NEAR(walk.walk.blocked_since, 10.9, 1e-9);
  EXPECT_LT(walk.walk.blocked_position.x(), 2.5);
  EXPECT_EQ(walk.walk.message.rfind("goal not reached: out of time; the robot is blocked: ", 0), 0u)
      << walk.walk.message;
  EXPECT_NE(walk.walk.message.find("since t = 10.9 s"), std::string::npos) << walk.walk.message;
  EXPECT_LT(walk.walk.progress_ratio, 0.2);
}

// generator.stop_when_blocked ends the goal walk at the sample it is found blocked (one window
// after its start), with that as the goal's outcome instead of running out the 90 s.
TEST(ShippedGoalWalks, StopWhenBlockedEndsTheTrappedGoalWalk) {
  const wpg::datasets::Scenario scenario =
      load("goal_u_trap", {"planner.algorithm=none", "generator.stop_when_blocked=true"});
  const wpg::planning::GoalWalkResult walk =
      wpg::planning::walkToGoal(scenario.walking, scenario.request, scenario.goal);
  EXPECT_FALSE(walk.goal_reached);
  ASSERT_TRUE(walk.walk.blocked);
  EXPECT_TRUE(walk.walk.stopped_blocked);
  EXPECT_NEAR(walk.walk.blocked_since, 10.9, 1e-9);
  EXPECT_NEAR(walk.walk.trajectory.time.back(), 10.9 + 4.8, 1e-9);
  EXPECT_EQ(walk.outcome.rfind("blocked at t = 15.7 s, ", 0), 0u) << walk.outcome;
}

// The shipped goal walks reach their goals unblocked (goal_with_yaw ends with its turn on the
// spot at the goal), walking most of what their commands ask for.
TEST(ShippedGoalWalks, GoalWalksThatReachTheirGoalAreNotBlocked) {
  for (const char* name :
       {"goal_cluttered", "goal_u_trap", "goal_unknown_obstacle", "goal_with_yaw"}) {
    const wpg::datasets::Scenario scenario = load(name);
    const wpg::planning::GoalWalkResult walk =
        wpg::planning::walkToGoal(scenario.walking, scenario.request, scenario.goal);
    ASSERT_TRUE(walk.goal_reached) << name << ": " << walk.outcome;
    EXPECT_FALSE(walk.walk.blocked) << name;
    EXPECT_TRUE(walk.walk.success) << name << ": " << walk.walk.message;
    EXPECT_GT(walk.walk.progress_ratio, 0.5) << name;
  }
}

}  // namespace
