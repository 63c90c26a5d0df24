#include "wpg/obstacle_tangent.hpp"

#include <algorithm>
#include <cmath>

namespace wpg {
namespace {

constexpr double kSideTie = 0.01;  // [m] offsets within this of the line count as a tie (left)

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The signed angle from a to b (counter-clockwise positive), in (-pi, pi].
double angleFrom(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::atan2(cross(a, b), a.dot(b));
}

Eigen::Vector2d rotated(const Eigen::Vector2d& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace

int obstacleSide(const Eigen::Vector2d& center, const Eigen::Vector2d& robot,
                 const Eigen::Vector2d& direction) {
  const double length = direction.norm();
  if (length <= 1e-12) return 1;
  // signed distance of the robot from the line through the centre along the command (> 0: left)
  const double offset = cross(direction, robot - center) / length;
  return offset >= -kSideTie ? 1 : -1;
}

double borderProgress(const Eigen::Vector2d& normal, const Eigen::Vector2d& direction, int side) {
  // The turn left from n to d is clockwise (negative) on the left side, counter-clockwise on
  // the right: side * that turn is -pi at n = -d, -pi/2 at the side's normal, 0 at d; cut at
  // the other side's normal (above pi/2: a turn the long way round).
  double progress = side * angleFrom(normal, direction);
  if (progress > 0.5 * M_PI) progress -= 2.0 * M_PI;
  return progress;
}

double borderOffset(const std::vector<Eigen::Vector2d>& core, double radius,
                    const Eigen::Vector2d& normal) {
  double support = normal.dot(core.front());
  for (const Eigen::Vector2d& v : core) support = std::max(support, normal.dot(v));
  return support + radius;
}

Eigen::Vector2d borderNormal(const std::vector<Eigen::Vector2d>& core, double radius,
                             const Eigen::Vector2d& com, const Eigen::Vector2d& direction,
                             int side, double clearance, const Eigen::Vector2d& facing) {
  if (direction.norm() <= 1e-12) return facing;
  // The arc of normals whose border passes `clearance` beside the CoM, as angles from
  // `facing` [lo, hi]: the intersection of one arc per core point v, centred on the direction
  // from v to the CoM, acos((radius + clearance) / |com - v|) wide on each side. When it is not
  // empty the CoM is at least radius + clearance from the core and `facing` is inside it
  // (facing . (com - v) >= the distance for every v): every point's arc holds 0, within a
  // right angle of it, so no angle wraps.
  double lo = -M_PI, hi = M_PI;
  for (const Eigen::Vector2d& v : core) {
    const Eigen::Vector2d away = com - v;
    const double distance = away.norm();
    if (distance <= radius + clearance) return facing;
    const double centre = angleFrom(facing, away);
    const double half_width = std::acos((radius + clearance) / distance);
    lo = std::max(lo, centre - half_width);
    hi = std::min(hi, centre + half_width);
  }
  if (lo > hi) return facing;
  // Turn from `facing` towards d through the passing side: clockwise when passing on the left
  // (side +1: from -d through the left normal to d), counter-clockwise on the right. The turn
  // that brings facing to d that way is side * progress(facing) (progress 0 at d).
  const double wanted = side * borderProgress(facing, direction, side);
  return rotated(facing, std::clamp(wanted, lo, hi));
}

Eigen::Vector2d borderSlide(const Eigen::Vector2d& normal, const Eigen::Vector2d& direction,
                            int side) {
  const Eigen::Vector2d tangent(-normal.y(), normal.x());
  const Eigen::Vector2d towards = side * Eigen::Vector2d(-direction.y(), direction.x());
  return tangent.dot(towards) >= 0.0 ? tangent : Eigen::Vector2d(-tangent);
}

void turnReferenceAlongBorders(const Eigen::Ref<const Eigen::Matrix2Xd>& normals,
                               const Eigen::Ref<const Eigen::Matrix2Xd>& slides,
                               const Eigen::Ref<const Eigen::VectorXd>& heading_cos,
                               const Eigen::Ref<const Eigen::VectorXd>& heading_sin,
                               double max_sideways_speed, Eigen::Ref<Eigen::VectorXd> velocity_x,
                               Eigen::Ref<Eigen::VectorXd> velocity_y) {
  constexpr double kInside = 1e-12;  // n.u >= -this: u drives into no border
  const auto drivesIntoNone = [&](const Eigen::Vector2d& u) {
    for (int k = 0; k < normals.cols(); ++k)
      if (normals.col(k).dot(u) < -kInside * u.norm()) return false;
    return true;
  };
  for (int j = 0; j < velocity_x.size(); ++j) {
    const Eigen::Vector2d v(velocity_x(j), velocity_y(j));
    const double speed = v.norm();
    if (speed <= 1e-12 || drivesIntoNone(v)) continue;
    // The nearest direction of the cone {u : n_k . u >= 0 for every border}: in the plane it
    // lies along one of the borders, the one nearest to v in angle among the directions along
    // the borders it drives into that drive into no other border; along each border, the
    // projection of v, or, square into it, the slide to the passing side.
    // Within a right angle of v only: a reference turned backwards would walk the robot away.
    Eigen::Vector2d best = Eigen::Vector2d::Zero();
    double best_cosine = -1e-9;
    for (int k = 0; k < normals.cols(); ++k) {
      const Eigen::Vector2d n = normals.col(k);
      const double into = n.dot(v);
      if (!(into < 0.0)) continue;  // zero columns and borders it does not drive into
      // Within kSquare of square into the border, v's projection along it is too short to say
      // which way round (its sign flips with the sway): slide towards the passing side.
      constexpr double kSquare = 0.1;  // |projection| / |v|: 5.7 degrees
      Eigen::Vector2d u = v - into * n;
      const double along = u.norm();
      u = along > kSquare * speed || u.dot(slides.col(k)) > 0.0 ? Eigen::Vector2d(u / along)
                                                                : Eigen::Vector2d(slides.col(k));
      const double cosine = u.dot(v) / speed;
      if (cosine > best_cosine && drivesIntoNone(u)) {
        best = u;
        best_cosine = cosine;
      }
    }
    if (best.isZero()) continue;  // no such direction: the QP holds the steps (best: a unit)
    // At the reference's speed, unless its part across the robot's heading then exceeds what
    // the gait can walk sideways: asked for more, the QP buys the missing sideways speed with
    // the outward step's length (the feasibility polygon's slanted edges) and slides along a
    // steep border more slowly than along one it can follow.
    double target = speed;
    const Eigen::Vector2d across(-heading_sin(j), heading_cos(j));
    const double sine = std::abs(across.dot(best));
    if (max_sideways_speed > 0.0 && sine * speed > max_sideways_speed)
      target = max_sideways_speed / sine;
    best *= target;
    velocity_x(j) = best.x();
    velocity_y(j) = best.y();
  }
}

}  // namespace wpg
