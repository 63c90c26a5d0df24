#pragma once
// The global route planner: OMPL's geometric planners in SE(2) over the obstacles
// the planner knows (an FCL World). A state (x, y, yaw) is valid when the robot's footprint
// disc of `robot_radius` is clear of every obstacle grown by its margin
// (World::isStateValid); motions are checked every 2 cm or finer; the objective is the path
// length; the solution goes through OMPL's path simplifier. OMPL stays in the .cpp files: this
// header needs only Eigen, libwpg and the World.
//
// Reproducibility: every random number generator a plan creates (state samplers, the
// planner's own, the simplifier's) is seeded from `seed`, so one seed gives one route whatever
// else runs in the process or on other threads (OMPL 1.5.2's unseeded RNGs draw from a
// process-wide sequence: docs/dependencies.md). Planners that run until their termination
// condition (the optimizing ones) stop after max_iterations of their iterations, counted on the
// planning thread, not after a time (docs/goals-and-planners.md lists the reproducible ones).
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/planning/world.hpp"
#include "wpg/walk_goal.hpp"

namespace wpg::planning {

// The outcome in OMPL's terms (ompl::base::PlannerStatus), plus the checks done before OMPL
// is called.
enum class PlanStatus : std::uint8_t {
  kExactSolution = 0,
  kApproximateSolution = 1,  // the route ends short of the goal (solution_difference > 0)
  kNoSolution = 2,           // the planner stopped without a route (its iterations ran out)
  kTimeout = 3,              // the time limit ran out without a route
  kInvalidStart = 4,         // the start is in a grown obstacle or out of the bounds
  kInvalidGoal = 5,          // the goal is in a grown obstacle or out of the bounds
};
const char* planStatusName(PlanStatus status);  // "exact_solution", "timeout", ...
// "0=exact_solution, 1=approximate_solution, ..." for the dataset's `codes` attribute.
std::string planStatusCodes();

// The numbers of one plan, named as ompl::tools::Benchmark names its run properties ("time",
// "solved", "solution length", "solution clearance", "simplification time", "graph states",
// ...), with underscores.
struct PlanStatistics {
  double time = 0.0;    // [s] wall time of the planner's solve()
  bool solved = false;  // an exact or approximate route
  bool approximate_solution = false;
  double solution_difference = 0.0;  // [m, rad] how far the approximate route ends from the goal
  double solution_length = 0.0;      // in the SE(2) metric (x-y length + 0.5 x |yaw change|)
  double solution_clearance =
      0.0;  // [m] least clearance of the route's states (World, minus the radius)
  double simplification_time = 0.0;         // [s]
  double simplified_solution_length = 0.0;  // SE(2) metric, after simplification
  int graph_states = 0;                     // vertices of the planner's graph/tree
  int graph_motions = 0;                    // its edges
  int iterations = 0;                       // termination checks seen (the planner's iterations)
};

struct RoutePlan {
  PlanStatus status = PlanStatus::kNoSolution;
  // (x [m], y [m], yaw [rad]) from the start to the goal; empty without a solution. The yaws
  // are OMPL's (interpolated), the follower heads along the x-y polyline.
  std::vector<Eigen::Vector3d> waypoints;
  double length = 0.0;  // [m] of the x-y polyline
  PlanStatistics statistics;
  bool solved() const {
    return status == PlanStatus::kExactSolution || status == PlanStatus::kApproximateSolution;
  }
};

// The planners this build knows, by name (lower case): rrtconnect, rrtstar, ...
const std::vector<std::string>& plannerNames();
bool isKnownPlanner(const std::string& name);
// Whether a planner's routes depend on its seed only (see the header comment).
bool isReproduciblePlanner(const std::string& name);

// x-y bounds of the planning area.
struct PlanningBounds {
  Eigen::Vector2d min = Eigen::Vector2d::Zero();
  Eigen::Vector2d max = Eigen::Vector2d::Zero();
  bool contains(const Eigen::Vector2d& point) const {
    return (point.array() >= min.array()).all() && (point.array() <= max.array()).all();
  }
};
// settings.bounds when set, else the bounding box of the obstacles (grown by their margins),
// the start and the goal, grown by 2 m.
PlanningBounds planningBounds(const std::vector<wpg::Obstacle>& obstacles,
                              const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                              const wpg::RoutePlannerSettings& settings);

class RoutePlanner {
 public:
  // `world`: the obstacles the planner knows; `robot_radius` [m] > 0. Throws
  // std::invalid_argument on an unknown algorithm ("'planner.algorithm': expected one of ...")
  // or bad settings.
  RoutePlanner(World world, const wpg::RoutePlannerSettings& settings, double robot_radius,
               PlanningBounds bounds);

  // A route from `start` to `goal` (x, y, yaw) [m, m, rad] (the follower heads along the x-y
  // polyline; the yaws only weigh turns in the SE(2) length). `seed` overrides settings.seed
  // for this plan (a replan uses its own). Never throws for an unreachable goal: the status
  // says it. May be called from several threads at once.
  RoutePlan plan(const Eigen::Vector3d& start, const Eigen::Vector3d& goal,
                 std::uint32_t seed) const;

  const World& world() const { return world_; }
  double robotRadius() const { return robot_radius_; }
  const PlanningBounds& bounds() const { return bounds_; }
  // World::isStateValid inside the bounds.
  bool isValid(const Eigen::Vector2d& point) const;

 private:
  World world_;
  wpg::RoutePlannerSettings settings_;
  double robot_radius_ = 0.0;
  PlanningBounds bounds_;
};

}  // namespace wpg::planning
