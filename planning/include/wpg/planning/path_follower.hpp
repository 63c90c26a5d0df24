#pragma once
// The path follower: from a route (an x-y polyline) and the robot's pose, the
// velocity command [vx, vy, omega] that the NMPC tracks, at every NMPC sample, within the
// robot's clamps (WalkingParameters::max_*_velocity).
//
// Pure pursuit: the robot walks towards the point of the route `lookahead` ahead of its
// projection on the route, plus a lateral correction towards the route (a humanoid can step
// sideways), and turns its heading towards that point. The speed ramps down within
// slow_distance of the goal (the robot stops with one more step and a side-by-side step: it
// must arrive slowly to stand inside the tolerance). Once within arrive_fraction x tolerance
// of the goal it turns on the spot to the goal's yaw (when the goal has one), then commands
// zero: the walk's loop (goal_walk.hpp) waits for the final side-by-side step and checks the
// standing pose.
//
// The command is expressed in the frame the NMPC reads it in (heading_reference: the feet's
// yaw, or the commanded heading): the caller passes that frame's yaw.
#include <vector>

#include <Eigen/Core>

#include "wpg/walk_goal.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::planning {

struct PathFollowerSettings {
  double lookahead = 0.5;         // [m] pure pursuit lookahead along the route
  double cruise_fraction = 0.75;  // cruise speed as a fraction of max_forward_velocity
  double slow_distance = 1.0;     // [m] of route left where the speed starts ramping down
  double min_speed = 0.05;        // [m/s] the slowest approach speed
  double heading_gain = 1.0;      // [1/s] omega = gain x heading error (then clamped)
  double lateral_gain = 0.5;      // [1/s] velocity towards the route per metre of cross-track error
  double arrive_fraction = 0.5;   // stop walking within this fraction of the goal's tolerance
};

enum class FollowerPhase {
  kFollow,    // walking along the route
  kAlignYaw,  // at the goal, turning to its yaw
  kStop,      // zero command: stopping (the final side-by-side step)
};
const char* followerPhaseName(FollowerPhase phase);

class PathFollower {
 public:
  // Throws std::invalid_argument on a non-positive lookahead or speed settings.
  PathFollower(const wpg::WalkingParameters& parameters, const wpg::WalkGoal& goal,
               const PathFollowerSettings& settings);

  // A new route (at least two x-y points; the last is the goal's position); restarts the
  // progress along it and the phase (kFollow). Throws std::invalid_argument on fewer points.
  void setRoute(const std::vector<Eigen::Vector2d>& route);
  const std::vector<Eigen::Vector2d>& route() const { return route_; }

  // The command for the robot at `position` (CoM, world) [m] whose heading is `yaw` [rad]
  // (the feet's mean yaw), expressed in the frame of yaw `frame_yaw` [rad] (the NMPC's command
  // frame). |vx| <= max_forward_velocity, |vy| <= max_lateral_velocity,
  // |omega| <= max_angular_velocity. Moves the phase forward (never back: restart() does).
  Eigen::Vector3d command(const Eigen::Vector2d& position, double yaw, double frame_yaw);

  // Back to kFollow on the same route (after a stop outside the tolerance).
  void restart() { phase_ = FollowerPhase::kFollow; }
  FollowerPhase phase() const { return phase_; }

  // Distance [m] from `point` to the route (the nearest of its segments).
  double distanceToRoute(const Eigen::Vector2d& point) const;
  // Arc length [m] of the route's projection of the robot at the last command().
  double progress() const { return progress_; }
  double routeLength() const { return arc_.empty() ? 0.0 : arc_.back(); }

  // Whether a standing robot at `position` with yaw `yaw` is at the goal (within the
  // tolerances; the yaw only when the goal has one).
  bool atGoal(const Eigen::Vector2d& position, double yaw) const;

 private:
  // The point at arc length s (clamped to the route).
  Eigen::Vector2d pointAt(double s) const;
  // Arc length of the projection of `point` on the route, searched from the current progress
  // to one lookahead ahead, so that a route passing near itself does not make it jump.
  double project(const Eigen::Vector2d& point) const;

  wpg::WalkGoal goal_;
  PathFollowerSettings settings_;
  Eigen::Vector3d limits_;  // max |vx|, |vy|, |omega|
  std::vector<Eigen::Vector2d> route_;
  std::vector<double> arc_;  // arc length at each route point
  double progress_ = 0.0;
  double final_heading_ = 0.0;  // the heading held at the goal when it has no yaw
  FollowerPhase phase_ = FollowerPhase::kFollow;
};

// The angle in (-pi, pi].
double wrapAngle(double angle);

}  // namespace wpg::planning
