#pragma once
// A walk to a goal instead of a velocity schedule: where to go, and how the global
// route planner (planning/: OMPL over the FCL world) and the path follower that turns its route
// into velocity commands are set up. Plain data like walk_request.hpp: datasets/ reads it from
// the scenario's `goal:` and `planner:` keys, planning/ plans, follows and replans. libwpg
// itself does not use it; it lives here because both of those modules need it and neither
// depends on the other.
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace wpg {

struct WalkGoal {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m], world frame
  bool has_yaw = false;        // without a yaw, the robot stops facing along the route's last leg
  double yaw = 0.0;            // [rad], world frame
  double tolerance = 0.15;     // the robot stands within this of `position` [m]
  double yaw_tolerance = 0.1;  // and within this of `yaw` [rad] (when has_yaw)
};

// planner.time_limit at most this [s]: a plan never runs for days. A walk's plans together
// also get at most its duration of planning (planning/goal_walk.cpp).
constexpr double kMaxPlannerTimeLimit = 600.0;

struct RoutePlannerSettings {
  // One of OMPL's geometric planners by name (docs/goals-and-planners.md lists them): rrtconnect,
  // rrtstar, informedrrtstar, bitstar, prmstar, ...; `none`: no planner, the straight line to
  // the goal (the NMPC alone meets the obstacles).
  std::string algorithm = "rrtconnect";
  double time_limit = 1.0;  // [s] of planning per (re)plan, a hard cap
  // Optimizing planners (rrtstar, prmstar, ...) stop after this many of their iterations, so
  // that their route depends on the seed and not on the machine's speed (the time limit still
  // caps them). Planners that stop at their first solution (rrtconnect) ignore it.
  int max_iterations = 1500;
  std::uint32_t seed = 1;  // every random number of a plan derives from it
  // Radius of the robot's footprint disc [m] that must stay clear of every known obstacle grown
  // by its margin; <= 0: from the robot, half the stance width plus the sole's half diagonal.
  double robot_radius = 0.0;
  double replan_distance = 0.4;  // replan when the robot is farther than this from the route [m]
  // An obstacle unknown to the planner is seen once it is within this of the robot [m].
  double sensing_range = 2.0;
  double lookahead = 0.5;  // pure pursuit: the point of the route this far ahead [m]
  // Planning area [x_min, x_max, y_min, y_max] [m]; unset: the bounding box of the obstacles,
  // the start and the goal grown by 2 m.
  bool has_bounds = false;
  Eigen::Vector4d bounds = Eigen::Vector4d::Zero();
};

struct GoalRequest {
  bool enabled = false;  // false: the walk follows WalkRequest::reference
  WalkGoal goal;
  RoutePlannerSettings planner;
  // One entry per WalkRequest::obstacles entry: false = unknown to the planner until sensed.
  // The NMPC keeps every obstacle in its constraints either way. Empty = all known.
  std::vector<bool> known_to_planner;

  bool knownToPlanner(std::size_t obstacle) const {
    return obstacle >= known_to_planner.size() || known_to_planner[obstacle];
  }
  // Throws std::invalid_argument naming the key ("goal.tolerance", "planner.time_limit", ...)
  // and what was expected; the algorithm's name is checked by planning/ (it knows the list).
  void validate() const;
};

// Half the stance width plus the sole's half diagonal [m]: the default footprint radius.
double defaultRobotRadius(double stance_width, double foot_length, double foot_width);

}  // namespace wpg
