// The walk to a goal: route planner + path follower + online generator (goal_walk.hpp).
#include "wpg/planning/goal_walk.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "wpg/nearest_name.hpp"
#include "wpg/online_walking_generator.hpp"
#include "wpg/walk_loop.hpp"

namespace wpg::planning {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A route is checked for a newly sensed obstacle every this many metres [m].
constexpr double kRouteCheckSpacing = 0.02;
// Strayed from the route: at most one replan per this time [s], so that a robot held off its
// route by an obstacle the planner does not know yet does not replan at every sample.
constexpr double kStrayedReplanInterval = 1.0;
// A start inside a grown obstacle (the NMPC lets the CoM come closer than the footprint disc)
// is moved out along the obstacle's gradient by steps of this [m], at most kEscapeReach.
constexpr double kEscapeStep = 0.02;
constexpr double kEscapeReach = 1.0;
// Stops outside the tolerance after which a new route is planned from where the robot stands.
constexpr int kMaxStopRetries = 3;
// planner.algorithm for no planner: the follower walks the straight line to the goal and never
// replans (the `nmpc_only` baseline of the comparison studies: the NMPC alone meets the
// obstacles).
constexpr const char* kNoPlanner = "none";

std::string format(double value, int digits = 2) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

// The obstacles the planner knows: the known ones and those sensed so far.
std::vector<wpg::Obstacle> knownObstacles(const wpg::WalkRequest& request,
                                          const std::vector<bool>& known) {
  std::vector<wpg::Obstacle> obstacles;
  for (std::size_t i = 0; i < request.obstacles.size(); ++i) {
    if (known[i]) obstacles.push_back(request.obstacles[i]);
  }
  return obstacles;
}

// Moves `point` out of the grown obstacles (footprint disc of `radius`) along the nearest
// obstacle's gradient; returns false when it cannot within kEscapeReach.
bool escape(const World& world, double radius, Eigen::Vector2d* point) {
  for (double moved = 0.0; moved <= kEscapeReach; moved += kEscapeStep) {
    if (world.isStateValid(point->x(), point->y(), radius)) return true;
    int nearest = -1;
    world.clearance(*point, &nearest);
    if (nearest < 0) return false;
    Eigen::Vector2d gradient;
    world.signedDistance(nearest, *point, &gradient);
    *point += kEscapeStep * gradient;
  }
  return world.isStateValid(point->x(), point->y(), radius);
}

// Whether the route from arc length `from` on enters obstacle `obstacle` grown by its margin
// and the footprint radius.
bool routeBlocked(const std::vector<Eigen::Vector2d>& route, double from, const World& single,
                  double radius) {
  double s = 0.0;
  for (std::size_t i = 1; i < route.size(); ++i) {
    const Eigen::Vector2d a = route[i - 1], b = route[i];
    const double length = (b - a).norm();
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / kRouteCheckSpacing)));
    for (int k = 0; k <= pieces; ++k) {
      const double u = static_cast<double>(k) / pieces;
      if (s + u * length < from) continue;
      const Eigen::Vector2d p = a + u * (b - a);
      if (!single.isStateValid(p.x(), p.y(), radius)) return true;
    }
    s += length;
  }
  return false;
}

}  // namespace

const char* planTriggerName(PlanTrigger trigger) {
  switch (trigger) {
    case PlanTrigger::kStart:
      return "start";
    case PlanTrigger::kStrayed:
      return "strayed";
    case PlanTrigger::kBlocked:
      return "blocked";
    case PlanTrigger::kRetry:
      return "retry";
  }
  return "unknown";
}

std::string planTriggerCodes() {
  std::string codes;
  for (int code = 0; code <= static_cast<int>(PlanTrigger::kRetry); ++code) {
    codes += (codes.empty() ? "" : ", ") + std::to_string(code) + "=" +
             planTriggerName(static_cast<PlanTrigger>(code));
  }
  return codes;
}

double plannerRobotRadius(const wpg::WalkingParameters& parameters,
                          const wpg::RoutePlannerSettings& settings) {
  if (settings.robot_radius > 0.0) return settings.robot_radius;
  return wpg::defaultRobotRadius(parameters.initial_foot_separation, parameters.foot_length,
                                 parameters.foot_width);
}

void checkGoalRequest(const wpg::WalkingParameters& parameters, const wpg::WalkRequest& request,
                      const wpg::GoalRequest& goal) {
  goal.validate();
  if (goal.planner.algorithm != kNoPlanner && !isKnownPlanner(goal.planner.algorithm)) {
    std::vector<std::string> known = {kNoPlanner};
    known.insert(known.end(), plannerNames().begin(), plannerNames().end());
    std::string names;
    for (const std::string& name : known) names += (names.empty() ? "" : ", ") + name;
    throw std::invalid_argument("'planner.algorithm': expected one of " + names + ", got '" +
                                goal.planner.algorithm + "'" +
                                wpg::didYouMean(goal.planner.algorithm, known));
  }
  if (!goal.known_to_planner.empty() && goal.known_to_planner.size() != request.obstacles.size()) {
    throw std::invalid_argument("known_to_planner: expected one entry per obstacle");
  }
  const double radius = plannerRobotRadius(parameters, goal.planner);
  const Eigen::Vector2d start = Eigen::Vector2d::Zero();  // the walk starts at the origin
  const PlanningBounds bounds =
      planningBounds(request.obstacles, start, goal.goal.position, goal.planner);
  const World world(request.obstacles);
  const std::string area = "[" + format(bounds.min.x()) + ", " + format(bounds.max.x()) + "] x [" +
                           format(bounds.min.y()) + ", " + format(bounds.max.y()) + "]";
  const Eigen::Vector2d& target = goal.goal.position;
  if (!bounds.contains(target)) {
    throw std::invalid_argument("'goal.position': expected a goal inside planner.bounds " + area +
                                ", got [" + format(target.x()) + ", " + format(target.y()) + "]");
  }
  if (!bounds.contains(start)) {
    throw std::invalid_argument("'planner.bounds': expected " + area +
                                " to hold the start of the walk (the origin)");
  }
  int nearest = -1;
  double clearance = world.clearance(target, &nearest);
  if (clearance < radius) {
    throw std::invalid_argument(
        "'goal.position': expected a goal clear of every obstacle grown by its margin and the "
        "robot radius " +
        format(radius, 3) + " m, but [" + format(target.x()) + ", " + format(target.y()) + "] is " +
        format(radius - clearance, 3) + " m inside obstacles[" + std::to_string(nearest) + "]");
  }
  clearance = world.clearance(start, &nearest);
  if (clearance < radius) {
    throw std::invalid_argument(
        "'obstacles[" + std::to_string(nearest) +
        "]': expected the start of the walk (the "
        "origin) clear of the obstacle grown by its margin and the robot radius " +
        format(radius, 3) + " m, but the start is " + format(radius - clearance, 3) + " m inside");
  }
}

namespace {

// The commands of a walk to a goal: the path follower along the planned route, with the
// planning, sensing and replanning of goal_walk.hpp between NMPC iterations. Ends the walk when
// the robot stands within the goal's tolerance, or stands still with no route left.
class GoalCommands final : public CommandSource {
 public:
  GoalCommands(const wpg::WalkingParameters& parameters, const wpg::WalkRequest& request,
               const wpg::GoalRequest& goal, const PathFollowerSettings& follower_settings,
               GoalWalkResult& result)
      : parameters_(parameters),
        request_(request),
        goal_(goal),
        radius_(plannerRobotRadius(parameters, goal.planner)),
        bounds_(planningBounds(request.obstacles, Eigen::Vector2d::Zero(), goal.goal.position,
                               goal.planner)),
        follower_(parameters, goal.goal, withLookahead(follower_settings, goal)),
        no_planner_(goal.planner.algorithm == kNoPlanner),
        result_(result) {
    known_.resize(request.obstacles.size());
    for (std::size_t i = 0; i < known_.size(); ++i) known_[i] = goal.knownToPlanner(i);
    // Each unknown obstacle alone, to test whether it blocks the route once sensed.
    for (const wpg::Obstacle& obstacle : request.obstacles)
      single_worlds_.emplace_back(std::vector<wpg::Obstacle>{obstacle});
  }

  bool nextCommand(int k, double t, OnlineWalkingGenerator& generator,
                   Eigen::Vector3d& command) override {
    const ControlSample& now = generator.currentSample();
    const Eigen::Vector2d position = now.com_position.head<2>();
    const double yaw = now.free_flyer_yaw;
    const double frame_yaw = parameters_.heading_reference == HeadingReference::kCommand
                                 ? generator.patternGenerator().commandedHeading()
                                 : yaw;
    if (!no_route_) {
      if (k == 0) {
        no_route_ = !plan(t, PlanTrigger::kStart, Eigen::Vector3d(position.x(), position.y(), yaw));
      } else if (follower_.phase() == FollowerPhase::kFollow && !no_planner_) {
        replanIfNeeded(t, position, yaw);
      }
      if (!no_route_ && follower_.phase() == FollowerPhase::kStop &&
          generator.patternGenerator().standing()) {
        // Standing after the final side-by-side step: the pose between the ankles.
        const Eigen::Vector2d stand = 0.5 * (now.left_foot.head<2>() + now.right_foot.head<2>());
        if (follower_.atGoal(stand, yaw)) {
          result_.goal_reached = true;
          result_.time_to_goal = t;
          return false;
        }
        if (++stop_retries_ > kMaxStopRetries) {
          result_.outcome =
              "stopped outside the tolerance " + std::to_string(stop_retries_) + " times";
          no_route_ = true;
        } else {
          no_route_ = !plan(t, PlanTrigger::kRetry, Eigen::Vector3d(stand.x(), stand.y(), yaw));
        }
      }
      if (!no_route_) command = follower_.command(position, yaw, frame_yaw);
    }
    // Nothing more will happen: the robot stands where the route ended.
    return !(no_route_ && generator.patternGenerator().standing() && k > 0);
  }

  // A walk that reached its goal made its progress: the turn on the spot at the goal
  // (align_yaw) holds the robot where it stands with a small linear command, which the
  // progress monitor would read as no progress (walk_loop.hpp).
  bool reachedTarget() const override { return result_.goal_reached; }

 private:
  static PathFollowerSettings withLookahead(PathFollowerSettings settings,
                                            const wpg::GoalRequest& goal) {
    settings.lookahead = goal.planner.lookahead;
    return settings;
  }

  // Sensing: unknown obstacles within range become known; replans if one blocks the route, or
  // if the robot strayed from it (at most once per kStrayedReplanInterval).
  void replanIfNeeded(double t, const Eigen::Vector2d& position, double yaw) {
    bool blocked = false;
    for (std::size_t i = 0; i < known_.size(); ++i) {
      if (known_[i]) continue;
      const World& single = single_worlds_[i];
      if (single.clearance(position) > goal_.planner.sensing_range) continue;
      known_[i] = true;
      blocked = blocked || routeBlocked(follower_.route(), follower_.progress(), single, radius_);
    }
    const Eigen::Vector3d pose(position.x(), position.y(), yaw);
    if (blocked) {
      no_route_ = !plan(t, PlanTrigger::kBlocked, pose);
    } else if (follower_.distanceToRoute(position) > goal_.planner.replan_distance &&
               t - last_strayed_replan_ >= kStrayedReplanInterval) {
      last_strayed_replan_ = t;
      no_route_ = !plan(t, PlanTrigger::kStrayed, pose);
    }
  }

  // Plans a route from the robot's pose; false (and the outcome set) when there is none.
  bool plan(double time, PlanTrigger trigger, const Eigen::Vector3d& pose) {
    PlanRecord record;
    record.time = time;
    record.trigger = trigger;
    record.start = pose;
    const Eigen::Vector2d to = goal_.goal.position;
    if (no_planner_) {  // the straight line, whatever is on it
      const double heading = std::atan2(to.y() - pose.y(), to.x() - pose.x());
      record.plan.status = PlanStatus::kExactSolution;
      record.plan.waypoints = {Eigen::Vector3d(pose.x(), pose.y(), heading),
                               Eigen::Vector3d(to.x(), to.y(), heading)};
      record.plan.length = (to - pose.head<2>()).norm();
      follower_.setRoute({pose.head<2>(), to});
      result_.plans.push_back(std::move(record));
      return true;
    }
    // The walk's duration bounds its planning: all plans together get at most that many
    // seconds of planning (an unreachable goal replans at each step, each plan to its limit).
    RoutePlannerSettings settings = goal_.planner;
    const double remaining = request_.duration - result_.planning_time;
    // Spent: one last plan of 1 ms, which an unreachable goal ends as a timeout.
    settings.time_limit = std::max(1e-3, std::min(settings.time_limit, remaining));
    const RoutePlanner planner(World(knownObstacles(request_, known_)), settings, radius_,
                               bounds_);
    for (const bool k : known_) record.known_obstacles += k ? 1 : 0;
    Eigen::Vector2d from = pose.head<2>();
    const bool escaped = escape(planner.world(), radius_, &from);
    const double goal_yaw =
        goal_.goal.has_yaw ? goal_.goal.yaw : std::atan2(to.y() - from.y(), to.x() - from.x());
    if (escaped) {
      const std::uint32_t seed =
          goal_.planner.seed + static_cast<std::uint32_t>(result_.plans.size());
      record.plan = planner.plan(Eigen::Vector3d(from.x(), from.y(), pose.z()),
                                 Eigen::Vector3d(to.x(), to.y(), goal_yaw), seed);
    } else {
      record.plan.status = PlanStatus::kInvalidStart;
    }
    result_.planning_time += record.plan.statistics.time;
    const bool ok = record.plan.status == PlanStatus::kExactSolution;
    if (ok) {
      std::vector<Eigen::Vector2d> route;
      if ((from - pose.head<2>()).norm() > 1e-9) {
        // Moved out of a grown obstacle: the route starts where the robot is.
        route.push_back(pose.head<2>());
        record.plan.waypoints.insert(record.plan.waypoints.begin(), pose);
        record.plan.length += (from - pose.head<2>()).norm();
      }
      for (const Eigen::Vector3d& w : record.plan.waypoints) {
        if (route.empty() || (w.head<2>() - route.back()).norm() > 1e-9)
          route.push_back(w.head<2>());
      }
      if (route.size() < 2) route.push_back(to);
      follower_.setRoute(route);
    } else {
      result_.outcome = std::string("no route at t = ") + format(time) + " s from [" +
                        format(pose.x()) + ", " + format(pose.y()) + "] (" +
                        planTriggerName(trigger) + " plan: " + planStatusName(record.plan.status) +
                        ")";
    }
    result_.plans.push_back(std::move(record));
    return ok;
  }

  const wpg::WalkingParameters& parameters_;
  const wpg::WalkRequest& request_;
  const wpg::GoalRequest& goal_;
  const double radius_;
  const PlanningBounds bounds_;
  std::vector<bool> known_;
  std::vector<World> single_worlds_;
  PathFollower follower_;
  const bool no_planner_;
  GoalWalkResult& result_;  // plans, planning time, goal reached, outcome
  bool no_route_ = false;
  double last_strayed_replan_ = -kStrayedReplanInterval;
  int stop_retries_ = 0;
};

}  // namespace

GoalWalkResult walkToGoal(const wpg::WalkingParameters& parameters, const wpg::WalkRequest& request,
                          const wpg::GoalRequest& goal,
                          const PathFollowerSettings& follower_settings,
                          wpg::ControlLoopObserver* observer) {
  parameters.validate();
  request.validate();
  checkWalkSize(parameters, request);
  if (!goal.enabled) throw std::invalid_argument("walkToGoal: the goal request is not enabled");
  checkGoalRequest(parameters, request, goal);

  OnlineWalkingGenerator generator(parameters, request.generator);
  if (!request.obstacles.empty()) generator.setObstacles(request.obstacles);
  GoalWalkResult result;
  result.time_to_goal = kNaN;
  GoalCommands commands(parameters, request, goal, follower_settings, result);
  result.walk = runWalkLoop(generator, request, commands, observer);

  WalkResult& walk = result.walk;
  const bool fallen = generator.fallen();
  const ControlSample& last = generator.currentSample();
  const Eigen::Vector2d stand = 0.5 * (last.left_foot.head<2>() + last.right_foot.head<2>());
  result.final_pose = Eigen::Vector3d(stand.x(), stand.y(), last.free_flyer_yaw);
  result.final_distance = (stand - goal.goal.position).norm();
  result.final_yaw_error =
      goal.goal.has_yaw ? std::abs(wrapAngle(last.free_flyer_yaw - goal.goal.yaw)) : 0.0;
  // The walk loop's blocked verdict is part of why the goal was missed: the message says both.
  const std::string blocked =
      walk.blocked ? "the robot is blocked: " + walk.blocked_description : std::string();
  if (!result.goal_reached && (walk.success || (walk.blocked && walk.message == blocked))) {
    walk.success = false;  // the dataset's success and message say why the goal was missed
    if (walk.stopped_blocked) {  // generator.stop_when_blocked ended it there
      walk.message = "goal not reached: " + blocked;
    } else {
      walk.message = "goal not reached: " +
                     (result.outcome.empty() ? std::string("out of time") : result.outcome) +
                     (blocked.empty() ? "" : "; " + blocked);
    }
  }
  if (result.goal_reached) {
    result.outcome = "reached";
  } else if (fallen) {
    result.outcome = "fell: " + walk.message;
  } else if (walk.stopped_blocked) {  // generator.stop_when_blocked ended it
    result.outcome = "blocked at t = " + format(walk.trajectory.time.back(), 1) + " s, " +
                     format(result.final_distance) + " m from the goal";
  } else if (result.outcome.empty()) {
    result.outcome = "out of time: " + format(result.final_distance) + " m from the goal after " +
                     format(request.duration, 1) + " s";
  }
  return result;
}

}  // namespace wpg::planning
