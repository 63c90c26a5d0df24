#pragma once
// A walk to a goal: the global route planner (route_planner.hpp) chained with the
// NMPC through the path follower (path_follower.hpp), sample by sample over libwpg's online
// generator (online_walking_generator.hpp), with replanning:
//  - at the start, a route over the obstacles known to the planner;
//  - when the robot strays farther than planner.replan_distance from its route (a push, or the
//    NMPC stepping around something);
//  - when an obstacle unknown to the planner (known_to_planner: false) comes within
//    planner.sensing_range of the robot and blocks the rest of the route: it becomes known.
// The NMPC keeps every obstacle in its constraints, known to the planner or not.
// planner.algorithm `none` is the walk without a planner: the straight line to the goal,
// never replanned (the NMPC alone meets the obstacles: the `nmpc_only` baseline). The walk ends
// when the robot stands within the goal's tolerance (after the final side-by-side step), when
// `duration` runs out, when the robot falls or when no route is found.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/planning/path_follower.hpp"
#include "wpg/planning/route_planner.hpp"
#include "wpg/walk_loop.hpp"
#include "wpg/walk_goal.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::planning {

// Why a plan was made.
enum class PlanTrigger : std::uint8_t {
  kStart = 0,    // the first route
  kStrayed = 1,  // farther than replan_distance from the route
  kBlocked = 2,  // an obstacle unknown to the planner was sensed on the route
  kRetry = 3,    // stopped outside the tolerance: a new route from where the robot stands
};
const char* planTriggerName(PlanTrigger trigger);
std::string planTriggerCodes();  // "0=start, 1=strayed, ..."

struct PlanRecord {
  double time = 0.0;  // [s] of the walk when the plan was made
  PlanTrigger trigger = PlanTrigger::kStart;
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // (x, y, yaw) planned from
  int known_obstacles = 0;                          // obstacles the planner knew
  RoutePlan plan;  // status, waypoints (the route followed), statistics
};

struct GoalWalkResult {
  // The walk loop's result (walk_loop.hpp): success false when fallen, on an NMPC failure, or
  // when the goal was not reached.
  wpg::WalkResult walk;
  std::vector<PlanRecord> plans;
  bool goal_reached = false;
  double time_to_goal = 0.0;  // [s] when the robot stood within the tolerance (NaN if never)
  // The standing pose at the end (mid-point of the ankles, mean foot yaw), its distance [m]
  // and yaw error [rad] to the goal (yaw error 0 for a goal without yaw).
  Eigen::Vector3d final_pose = Eigen::Vector3d::Zero();
  double final_distance = 0.0;
  double final_yaw_error = 0.0;
  double planning_time = 0.0;  // [s] sum of the plans' statistics.time
  std::string outcome;         // one line: "reached", or why not
};

// The footprint radius the planner uses: settings.robot_radius, or from the robot when 0.
double plannerRobotRadius(const wpg::WalkingParameters& parameters,
                          const wpg::RoutePlannerSettings& settings);

// The checks of a goal request against the world, before anything runs: known algorithm, the
// start (the origin, where the walk starts) and the goal clear of every obstacle grown by its
// margin and the footprint radius, and inside the bounds. Throws std::invalid_argument naming
// the key ("'goal.position': ...", "'planner.algorithm': ...").
void checkGoalRequest(const wpg::WalkingParameters& parameters, const wpg::WalkRequest& request,
                      const wpg::GoalRequest& goal);

// Runs the walk. `observer` (not owned, may be null): a controller around the WPG, called
// around every control period of the walk loop as in generateWalk (the dynamic filter's loop of
// the paper's Fig. 3, robots/online_filter_loop.hpp); the follower reads the WPG's own CoM,
// which the closed loop re-initialises at each NMPC iteration. Throws std::invalid_argument on
// invalid parameters, request or goal.
GoalWalkResult walkToGoal(const wpg::WalkingParameters& parameters, const wpg::WalkRequest& request,
                          const wpg::GoalRequest& goal, const PathFollowerSettings& follower = {},
                          wpg::ControlLoopObserver* observer = nullptr);

}  // namespace wpg::planning
