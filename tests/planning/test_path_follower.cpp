// The path follower (planning/path_follower.hpp) on its own, and chained with the NMPC
// (planning/goal_walk.hpp): commands within the clamps, where they point, slowing, yaw
// alignment, and a walk that stops standing within the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "../common/goal_walking.hpp"
#include "wpg/planning/goal_walk.hpp"
#include "wpg/planning/path_follower.hpp"

namespace {

using wpg::planning::FollowerPhase;
using wpg::planning::PathFollower;

wpg::WalkGoal goalAt(double x, double y) {
  wpg::WalkGoal goal;
  goal.position = Eigen::Vector2d(x, y);
  return goal;
}

TEST(PathFollower, CommandsStayWithinTheRobotsClampsEverywhere) {
  wpg::WalkingParameters parameters;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> position(-3.0, 6.0), angle(-4.0, 4.0);
  for (const bool with_yaw : {false, true}) {
    wpg::WalkGoal goal = goalAt(4.0, 1.0);
    goal.has_yaw = with_yaw;
    goal.yaw = 2.0;
    PathFollower follower(parameters, goal, {});
    follower.setRoute({{0.0, 0.0}, {1.0, -1.0}, {3.0, -1.0}, {4.0, 1.0}});
    for (int i = 0; i < 20000; ++i) {
      if (i % 100 == 0) follower.restart();
      const Eigen::Vector3d c =
          follower.command(Eigen::Vector2d(position(rng), position(rng)), angle(rng), angle(rng));
      ASSERT_TRUE(c.allFinite());
      ASSERT_LE(std::abs(c.x()), parameters.max_forward_velocity + 1e-12);
      ASSERT_LE(std::abs(c.y()), parameters.max_lateral_velocity + 1e-12);
      ASSERT_LE(std::abs(c.z()), parameters.max_angular_velocity + 1e-12);
    }
  }
}

TEST(PathFollower, WalksAlongTheRouteCorrectsSidewaysAndTurnsTowardsIt) {
  wpg::WalkingParameters parameters;
  PathFollower follower(parameters, goalAt(5.0, 0.0), {});
  follower.setRoute({{0.0, 0.0}, {5.0, 0.0}});
  // On the route, facing along it: forward at cruise speed, no turn.
  Eigen::Vector3d c = follower.command(Eigen::Vector2d(1.0, 0.0), 0.0, 0.0);
  EXPECT_NEAR(c.x(), 0.75 * parameters.max_forward_velocity, 1e-9);
  EXPECT_NEAR(c.y(), 0.0, 1e-9);
  EXPECT_NEAR(c.z(), 0.0, 1e-9);
  // 0.3 m to the left of the route: a velocity back to the right (-y in the robot frame).
  c = follower.command(Eigen::Vector2d(1.5, 0.3), 0.0, 0.0);
  EXPECT_GT(c.x(), 0.0);
  EXPECT_LT(c.y(), -0.05);
  // Facing +y on the route: turns right (omega < 0), the route direction is -y in its frame.
  c = follower.command(Eigen::Vector2d(2.0, 0.0), M_PI / 2, M_PI / 2);
  EXPECT_LT(c.z(), 0.0);
  EXPECT_LT(c.y(), 0.0);
  // The command frame is the one given (the NMPC's), not the robot's yaw.
  const Eigen::Vector3d in_frame = follower.command(Eigen::Vector2d(2.5, 0.0), 0.0, 0.3);
  EXPECT_LT(in_frame.y(), 0.0);  // +x world is to the right of a frame turned by +0.3
  EXPECT_LT(in_frame.z(), 0.0);
}

TEST(PathFollower, SlowsNearTheGoalThenStopsOrAlignsItsYaw) {
  wpg::WalkingParameters parameters;
  PathFollower follower(parameters, goalAt(4.0, 0.0), {});
  follower.setRoute({{0.0, 0.0}, {4.0, 0.0}});
  const double far = follower.command(Eigen::Vector2d(1.0, 0.0), 0.0, 0.0).head<2>().norm();
  const double near = follower.command(Eigen::Vector2d(3.7, 0.0), 0.0, 0.0).head<2>().norm();
  const double nearer = follower.command(Eigen::Vector2d(3.85, 0.0), 0.0, 0.0).head<2>().norm();
  EXPECT_LT(near, 0.5 * far);
  EXPECT_LT(nearer, near);
  EXPECT_EQ(follower.phase(), FollowerPhase::kFollow);
  // Within arrive_fraction x tolerance: stop (zero command).
  EXPECT_EQ(follower.command(Eigen::Vector2d(3.95, 0.02), 0.0, 0.0), Eigen::Vector3d::Zero());
  EXPECT_EQ(follower.phase(), FollowerPhase::kStop);

  wpg::WalkGoal with_yaw = goalAt(4.0, 0.0);
  with_yaw.has_yaw = true;
  with_yaw.yaw = 1.0;
  PathFollower aligning(parameters, with_yaw, {});
  aligning.setRoute({{0.0, 0.0}, {4.0, 0.0}});
  Eigen::Vector3d c = aligning.command(Eigen::Vector2d(3.97, 0.0), 0.0, 0.0);
  EXPECT_EQ(aligning.phase(), FollowerPhase::kAlignYaw);
  EXPECT_NEAR(c.z(), parameters.max_angular_velocity, 1e-12);  // turning left to yaw 1
  EXPECT_LE(c.head<2>().norm(), 0.05 + 1e-12);                 // on the spot
  c = aligning.command(Eigen::Vector2d(3.97, 0.0), 0.98, 0.98);
  EXPECT_EQ(aligning.phase(), FollowerPhase::kStop);
  EXPECT_EQ(c, Eigen::Vector3d::Zero());
  EXPECT_TRUE(aligning.atGoal(Eigen::Vector2d(4.1, 0.05), 0.95));
  EXPECT_FALSE(aligning.atGoal(Eigen::Vector2d(4.1, 0.05), 0.8));
  EXPECT_FALSE(aligning.atGoal(Eigen::Vector2d(4.2, 0.0), 1.0));
}

TEST(PathFollower, DistanceToTheRouteAndProgressAlongIt) {
  wpg::WalkingParameters parameters;
  PathFollower follower(parameters, goalAt(2.0, 2.0), {});
  follower.setRoute({{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}});
  EXPECT_NEAR(follower.distanceToRoute(Eigen::Vector2d(1.0, 0.5)), 0.5, 1e-12);
  EXPECT_NEAR(follower.distanceToRoute(Eigen::Vector2d(2.5, 1.0)), 0.5, 1e-12);
  EXPECT_NEAR(follower.routeLength(), 4.0, 1e-12);
  follower.command(Eigen::Vector2d(1.0, 0.1), 0.0, 0.0);
  EXPECT_NEAR(follower.progress(), 1.0, 1e-12);
  EXPECT_THROW(follower.setRoute({{0.0, 0.0}}), std::invalid_argument);
}

// The chain: the follower drives the online generator; the robot stops standing within the
// tolerance of the goal (and of its yaw), and the same request gives the same walk.
using wpg_test::goalWalking;

TEST(GoalWalk, StopsStandingWithinTheToleranceOfPositionAndYaw) {
  const wpg::WalkingParameters parameters = goalWalking();
  wpg::WalkRequest request;
  request.duration = 40.0;
  wpg::GoalRequest goal;
  goal.enabled = true;
  goal.goal = goalAt(2.0, -0.8);
  goal.goal.has_yaw = true;
  goal.goal.yaw = -0.8;
  const wpg::planning::GoalWalkResult walk = wpg::planning::walkToGoal(parameters, request, goal);
  ASSERT_TRUE(walk.goal_reached) << walk.outcome;
  EXPECT_TRUE(walk.walk.success) << walk.walk.message;
  EXPECT_LE(walk.final_distance, goal.goal.tolerance);
  EXPECT_LE(walk.final_yaw_error, goal.goal.yaw_tolerance);
  EXPECT_EQ(walk.plans.size(), 1u);
  // The walk ends once standing at the goal, well before the budget; the last sample is
  // standing (both feet down, side by side).
  EXPECT_LT(walk.time_to_goal, 30.0);
  EXPECT_NEAR(walk.walk.trajectory.time.back(), walk.time_to_goal, 1e-9);
  EXPECT_EQ(walk.walk.trajectory.support.back(), wpg::SupportState::kDouble);

  const wpg::planning::GoalWalkResult again = wpg::planning::walkToGoal(parameters, request, goal);
  ASSERT_EQ(again.walk.trajectory.com.size(), walk.walk.trajectory.com.size());
  for (std::size_t i = 0; i < walk.walk.trajectory.com.size(); ++i)
    ASSERT_EQ(again.walk.trajectory.com[i], walk.walk.trajectory.com[i]) << "sample " << i;
}

TEST(GoalWalk, APushThatThrowsTheRobotOffItsRouteMakesItReplanFromWhereItIs) {
  const wpg::WalkingParameters parameters = goalWalking();
  wpg::WalkRequest request;
  request.duration = 40.0;
  wpg::Push push;
  push.t = 6.0;
  push.force = Eigen::Vector2d(0.0, -40.0);  // larger pushes at this phase fell the NMPC alone
  request.pushes = {push};
  wpg::GoalRequest goal;
  goal.enabled = true;
  goal.goal = goalAt(3.0, 1.5);
  goal.planner.replan_distance = 0.15;
  const wpg::planning::GoalWalkResult walk = wpg::planning::walkToGoal(parameters, request, goal);
  ASSERT_TRUE(walk.goal_reached) << walk.outcome;
  ASSERT_GE(walk.plans.size(), 2u);
  EXPECT_EQ(walk.plans[0].trigger, wpg::planning::PlanTrigger::kStart);
  EXPECT_EQ(walk.plans[1].trigger, wpg::planning::PlanTrigger::kStrayed);
  EXPECT_GT(walk.plans[1].time, push.t);
  EXPECT_LT(walk.plans[1].time, push.t + 2.0);
  // Replanned from where the robot was (its CoM), not from the old route.
  const Eigen::Vector2d from = walk.plans[1].plan.waypoints.front().head<2>();
  EXPECT_LT((from - walk.plans[1].start.head<2>()).norm(), 1e-9);
  // At most one strayed replan per second.
  for (std::size_t i = 2; i < walk.plans.size(); ++i)
    EXPECT_GE(walk.plans[i].time - walk.plans[i - 1].time, 1.0 - 1e-9);
}

TEST(GoalWalk, WithoutAPlannerTheStraightLineIsFollowedAndNeverReplanned) {
  const wpg::WalkingParameters parameters = goalWalking();
  wpg::WalkRequest request;
  request.duration = 40.0;
  wpg::Obstacle wall;
  wall.type = wpg::ObstacleType::kBox;
  wall.center = Eigen::Vector2d(1.5, 0.0);
  wall.size = Eigen::Vector2d(0.2, 3.0);
  wall.margin = 0.1;
  request.obstacles = {wall};
  wpg::GoalRequest goal;
  goal.enabled = true;
  goal.goal = goalAt(3.0, 0.0);
  goal.planner.algorithm = "none";
  const wpg::planning::GoalWalkResult blocked =
      wpg::planning::walkToGoal(parameters, request, goal);
  EXPECT_FALSE(blocked.goal_reached);
  EXPECT_FALSE(blocked.walk.success);
  EXPECT_NE(blocked.walk.message.find("goal not reached"), std::string::npos);
  EXPECT_EQ(blocked.plans.size(), 1u);
  // The planner goes round the wall.
  goal.planner.algorithm = "rrtconnect";
  const wpg::planning::GoalWalkResult round = wpg::planning::walkToGoal(parameters, request, goal);
  EXPECT_TRUE(round.goal_reached) << round.outcome;
}

TEST(GoalWalk, BadGoalRequestsNameTheirKey) {
  const wpg::WalkingParameters parameters = goalWalking();
  wpg::WalkRequest request;
  wpg::Obstacle post;
  post.type = wpg::ObstacleType::kCircle;
  post.center = Eigen::Vector2d(2.0, 0.0);
  post.radius = 0.3;
  post.margin = 0.1;
  request.obstacles = {post};
  wpg::GoalRequest goal;
  goal.enabled = true;
  const auto message = [&]() -> std::string {
    try {
      wpg::planning::checkGoalRequest(parameters, request, goal);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  goal.goal = goalAt(2.1, 0.0);  // inside the grown post
  EXPECT_EQ(message().rfind("'goal.position'", 0), 0u) << message();
  goal.goal = goalAt(4.0, 0.0);
  EXPECT_EQ(message(), "");
  goal.planner.algorithm = "dijkstra";
  EXPECT_EQ(message().rfind("'planner.algorithm'", 0), 0u) << message();
  goal.planner.algorithm = "rrtconnect";
  goal.planner.time_limit = -1.0;
  EXPECT_EQ(message().rfind("'planner.time_limit'", 0), 0u) << message();
  goal.planner.time_limit = 1.0;
  goal.planner.has_bounds = true;
  goal.planner.bounds << -1.0, 3.0, -1.0, 1.0;  // the goal outside
  EXPECT_EQ(message().rfind("'goal.position'", 0), 0u) << message();
  goal.planner.has_bounds = false;
  request.obstacles[0].center = Eigen::Vector2d(0.3, 0.0);  // on the start
  EXPECT_EQ(message().rfind("'obstacles[0]'", 0), 0u) << message();
}

}  // namespace
