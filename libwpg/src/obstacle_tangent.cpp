#include "wpg/obstacle_tangent.hpp"

#include <algorithm>
#include <cmath>

namespace wpg {
namespace {

constexpr double kSideTie = 0.01;  // [m] offsets within this of the line count as a tie (left)

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
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

Eigen::Vector2d commandTangentNormal(const Eigen::Vector2d& center, double radius,
                                     const Eigen::Vector2d& com, const Eigen::Vector2d& direction,
                                     int side, double clearance) {
  const Eigen::Vector2d d = com - center;
  const double distance = d.norm();
  const double length = direction.norm();
  if (distance <= 1e-12) {  // CoM at the centre (inside: the row is violated whatever n is)
    if (length <= 1e-12) return Eigen::Vector2d::UnitX();
    return side * Eigen::Vector2d(-direction.y(), direction.x()) / length;
  }
  const Eigen::Vector2d facing = d / distance;  // the tangent facing the CoM
  if (length <= 1e-12 || distance <= radius + clearance) return facing;
  // The wanted normal: perpendicular to the command, on the passing side (border parallel to
  // the command). The normals whose border passes at least `clearance` beside the CoM,
  // n.(com - c) >= radius + clearance, are those within acos((radius + clearance) / distance)
  // of `facing`: turn `facing` towards the wanted one, at most that far.
  const Eigen::Vector2d wanted = side * Eigen::Vector2d(-direction.y(), direction.x()) / length;
  const double turn = std::atan2(cross(facing, wanted), facing.dot(wanted));
  const double max_turn = std::acos((radius + clearance) / distance);
  const double a = std::clamp(turn, -max_turn, max_turn);
  const double c = std::cos(a), s = std::sin(a);
  return {c * facing.x() - s * facing.y(), s * facing.x() + c * facing.y()};
}

void turnReferenceAlongBorders(const Eigen::Ref<const Eigen::Matrix2Xd>& normals,
                               double max_sideways_speed, Eigen::Ref<Eigen::VectorXd> velocity_x,
                               Eigen::Ref<Eigen::VectorXd> velocity_y) {
  for (int j = 0; j < velocity_x.size(); ++j) {
    const Eigen::Vector2d command(velocity_x(j), velocity_y(j));
    Eigen::Vector2d v = command;
    const double speed = v.norm();
    bool turned = false;
    for (int k = 0; k < normals.cols(); ++k) {
      const Eigen::Vector2d n = normals.col(k);
      const double into = n.dot(v);
      if (into < 0.0) {  // n is a unit vector (or zero: no change)
        v -= into * n;
        turned = true;
      }
    }
    const double length = v.norm();
    if (!turned || length <= 1e-12) continue;
    // Along the border at the commanded speed, unless its part across the command then exceeds
    // what the gait can walk sideways: asked for more, the QP buys the missing sideways speed
    // with the outward step's length (the feasibility polygon's slanted edges) and slides along
    // a steep border more slowly than along one it can follow.
    double target = speed;
    const double sine = std::abs(cross(command, v)) / (speed * length);
    if (max_sideways_speed > 0.0 && sine * speed > max_sideways_speed) {
      target = max_sideways_speed / sine;
    }
    v *= target / length;
    velocity_x(j) = v.x();
    velocity_y(j) = v.y();
  }
}

}  // namespace wpg
