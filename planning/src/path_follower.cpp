// The pure pursuit path follower (path_follower.hpp).
#include "wpg/planning/path_follower.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace wpg::planning {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Matrix2d rotation(double yaw) {
  Eigen::Matrix2d r;
  r << std::cos(yaw), -std::sin(yaw), std::sin(yaw), std::cos(yaw);
  return r;
}

// Scales the translation (x, y) so that |x| <= limit_x and |y| <= limit_y, keeping its
// direction (clamping each component alone would turn it).
Eigen::Vector2d scaleInto(const Eigen::Vector2d& v, double limit_x, double limit_y) {
  double scale = 1.0;
  if (std::abs(v.x()) > limit_x) scale = std::min(scale, limit_x / std::abs(v.x()));
  if (std::abs(v.y()) > limit_y) scale = std::min(scale, limit_y / std::abs(v.y()));
  return v * scale;
}

}  // namespace

double wrapAngle(double angle) {
  angle = std::fmod(angle + kPi, 2.0 * kPi);
  if (angle <= 0.0) angle += 2.0 * kPi;
  return angle - kPi;
}

const char* followerPhaseName(FollowerPhase phase) {
  switch (phase) {
    case FollowerPhase::kFollow:
      return "follow";
    case FollowerPhase::kAlignYaw:
      return "align_yaw";
    case FollowerPhase::kStop:
      return "stop";
  }
  return "unknown";
}

PathFollower::PathFollower(const wpg::WalkingParameters& parameters, const wpg::WalkGoal& goal,
                           const PathFollowerSettings& settings)
    : goal_(goal),
      settings_(settings),
      limits_(parameters.max_forward_velocity, parameters.max_lateral_velocity,
              parameters.max_angular_velocity) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(settings.lookahead) || !positive(settings.cruise_fraction) ||
      settings.cruise_fraction > 1.0 || !positive(settings.slow_distance) ||
      !positive(settings.min_speed) || !positive(settings.heading_gain) ||
      !(settings.lateral_gain >= 0.0) || !positive(settings.arrive_fraction) ||
      settings.arrive_fraction > 1.0) {
    throw std::invalid_argument(
        "PathFollower: expected positive lookahead, speeds and gains, fractions in (0, 1]");
  }
  if (!positive(goal.tolerance) || !positive(goal.yaw_tolerance)) {
    throw std::invalid_argument("PathFollower: expected positive goal tolerances");
  }
}

void PathFollower::setRoute(const std::vector<Eigen::Vector2d>& route) {
  if (route.size() < 2) {
    throw std::invalid_argument("PathFollower::setRoute: expected at least 2 points, got " +
                                std::to_string(route.size()));
  }
  route_ = route;
  arc_.assign(route_.size(), 0.0);
  for (std::size_t i = 1; i < route_.size(); ++i)
    arc_[i] = arc_[i - 1] + (route_[i] - route_[i - 1]).norm();
  progress_ = 0.0;
  phase_ = FollowerPhase::kFollow;
  // The heading to stand with at a goal without a yaw: along the last leg of the route.
  for (std::size_t i = route_.size() - 1; i > 0; --i) {
    const Eigen::Vector2d leg = route_[i] - route_[i - 1];
    if (leg.norm() > 1e-6) {
      final_heading_ = std::atan2(leg.y(), leg.x());
      break;
    }
  }
}

Eigen::Vector2d PathFollower::pointAt(double s) const {
  if (s <= 0.0) return route_.front();
  for (std::size_t i = 1; i < route_.size(); ++i) {
    if (s <= arc_[i]) {
      const double length = arc_[i] - arc_[i - 1];
      const double u = length > 0.0 ? (s - arc_[i - 1]) / length : 1.0;
      return route_[i - 1] + u * (route_[i] - route_[i - 1]);
    }
  }
  return route_.back();
}

double PathFollower::project(const Eigen::Vector2d& point) const {
  double best_distance = std::numeric_limits<double>::infinity();
  double best_s = progress_;
  const double window_end = progress_ + std::max(settings_.lookahead, 0.5);
  for (std::size_t i = 1; i < route_.size(); ++i) {
    if (arc_[i] < progress_) continue;    // behind the progress
    if (arc_[i - 1] > window_end) break;  // beyond the window
    const Eigen::Vector2d a = route_[i - 1], ab = route_[i] - a;
    const double length2 = ab.squaredNorm();
    double u = length2 > 0.0 ? (point - a).dot(ab) / length2 : 0.0;
    u = std::clamp(u, 0.0, 1.0);
    const double s = std::max(progress_, arc_[i - 1] + u * (arc_[i] - arc_[i - 1]));
    const double distance = (pointAt(s) - point).norm();
    if (distance < best_distance) {
      best_distance = distance;
      best_s = s;
    }
  }
  return best_s;
}

double PathFollower::distanceToRoute(const Eigen::Vector2d& point) const {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < route_.size(); ++i) {
    const Eigen::Vector2d a = route_[i - 1], ab = route_[i] - a;
    const double length2 = ab.squaredNorm();
    const double u = length2 > 0.0 ? std::clamp((point - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    best = std::min(best, (a + u * ab - point).norm());
  }
  return best;
}

bool PathFollower::atGoal(const Eigen::Vector2d& position, double yaw) const {
  if ((position - goal_.position).norm() > goal_.tolerance) return false;
  return !goal_.has_yaw || std::abs(wrapAngle(yaw - goal_.yaw)) <= goal_.yaw_tolerance;
}

Eigen::Vector3d PathFollower::command(const Eigen::Vector2d& position, double yaw,
                                      double frame_yaw) {
  if (route_.empty()) throw std::logic_error("PathFollower::command: no route (setRoute first)");
  const Eigen::Matrix2d to_frame = rotation(frame_yaw).transpose();
  const double to_goal = (goal_.position - position).norm();
  const double arrive = settings_.arrive_fraction * goal_.tolerance;
  progress_ = project(position);
  const double left = std::max(0.0, routeLength() - progress_);

  if (phase_ == FollowerPhase::kFollow && to_goal <= arrive && left <= settings_.lookahead) {
    phase_ = goal_.has_yaw ? FollowerPhase::kAlignYaw : FollowerPhase::kStop;
  }
  if (phase_ == FollowerPhase::kAlignYaw &&
      std::abs(wrapAngle(goal_.yaw - yaw)) <= 0.5 * goal_.yaw_tolerance) {
    phase_ = FollowerPhase::kStop;
  }
  if (phase_ == FollowerPhase::kStop) return Eigen::Vector3d::Zero();

  Eigen::Vector2d velocity;  // world frame [m/s]
  double heading;            // wanted heading [rad]
  if (phase_ == FollowerPhase::kAlignYaw) {
    // Turning on the spot, holding the position against the drift of the steps.
    velocity = settings_.lateral_gain * (goal_.position - position);
    if (velocity.norm() > settings_.min_speed) velocity *= settings_.min_speed / velocity.norm();
    heading = goal_.yaw;
  } else {
    const Eigen::Vector2d target = pointAt(progress_ + settings_.lookahead);
    const Eigen::Vector2d projection = pointAt(progress_);
    const Eigen::Vector2d chord = target - position;
    // Speed: cruise, ramped down over the last slow_distance of the route (or of the straight
    // distance to the goal, when the robot lags behind its projection there).
    const double cruise = settings_.cruise_fraction * limits_.x();
    const double remaining = std::max(left, to_goal);
    const double speed =
        std::clamp(cruise * remaining / settings_.slow_distance, settings_.min_speed, cruise);
    velocity =
        chord.norm() > 1e-9 ? Eigen::Vector2d(chord.normalized() * speed) : Eigen::Vector2d::Zero();
    // Lateral correction: back towards the route in proportion to the cross-track error.
    velocity += settings_.lateral_gain * (projection - position);
    // Head along the route: towards the lookahead point while it is not too close, then hold
    // the final heading (or turn to the goal's yaw over the last metre).
    if (chord.norm() > 0.5 * settings_.lookahead && left > 0.5 * settings_.lookahead) {
      heading = std::atan2(chord.y(), chord.x());
    } else {
      heading = goal_.has_yaw && to_goal < 1.0 ? goal_.yaw : final_heading_;
    }
  }
  const Eigen::Vector2d in_frame = scaleInto(to_frame * velocity, limits_.x(), limits_.y());
  const double omega = std::clamp(settings_.heading_gain * wrapAngle(heading - frame_yaw),
                                  -limits_.z(), limits_.z());
  return Eigen::Vector3d(in_frame.x(), in_frame.y(), omega);
}

}  // namespace wpg::planning
