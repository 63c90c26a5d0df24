#include "wpg/obstacle_tangent.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

// The least distance between the segments [p0, p1] and [q0, q1] (either may be a point).
double segmentDistance(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                       const Eigen::Vector2d& q0, const Eigen::Vector2d& q1) {
  const Eigen::Vector2d u = p1 - p0, v = q1 - q0;
  // proper crossing: each segment's ends on opposite sides of the other's line
  if (cross(u, q0 - p0) * cross(u, q1 - p0) < 0.0 && cross(v, p0 - q0) * cross(v, p1 - q0) < 0.0)
    return 0.0;
  const auto pointToSegment = [](const Eigen::Vector2d& x, const Eigen::Vector2d& a,
                                 const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((x - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (x - (a + t * ab)).norm();
  };
  return std::min({pointToSegment(p0, q0, q1), pointToSegment(p1, q0, q1),
                   pointToSegment(q0, p0, p1), pointToSegment(q1, p0, p1)});
}

// Whether `x` is inside (or on) the convex polygon `core` (>= 3 vertices, either orientation).
bool insideCore(const std::vector<Eigen::Vector2d>& core, const Eigen::Vector2d& x) {
  if (core.size() < 3) return false;
  bool negative = false, positive = false;
  for (std::size_t i = 0; i < core.size(); ++i) {
    const double turn = cross(core[(i + 1) % core.size()] - core[i], x - core[i]);
    negative |= turn < 0.0;
    positive |= turn > 0.0;
  }
  return !(negative && positive);
}

// The support h(n) + radius of the hull of the discs (core[i], radius(i)) for a unit n.
template <class Radius>
double support(const std::vector<Eigen::Vector2d>& core, const Radius& radius,
               const Eigen::Vector2d& normal) {
  double most = normal.dot(core.front()) + radius(0);
  for (std::size_t i = 1; i < core.size(); ++i)
    most = std::max(most, normal.dot(core[i]) + radius(i));
  return most;
}

template <class Radius>
Eigen::Vector2d turnedBorder(const std::vector<Eigen::Vector2d>& core, const Radius& radius,
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
  for (std::size_t i = 0; i < core.size(); ++i) {
    const Eigen::Vector2d away = com - core[i];
    const double distance = away.norm();
    if (distance <= radius(i) + clearance) return facing;
    const double centre = angleFrom(facing, away);
    const double half_width = std::acos((radius(i) + clearance) / distance);
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

}  // namespace

double borderOffset(const std::vector<Eigen::Vector2d>& core, double radius,
                    const Eigen::Vector2d& normal) {
  return support(core, [radius](std::size_t) { return radius; }, normal);
}

double borderOffset(const std::vector<Eigen::Vector2d>& points, const std::vector<double>& radii,
                    const Eigen::Vector2d& normal) {
  return support(points, [&radii](std::size_t i) { return radii[i]; }, normal);
}

Eigen::Vector2d borderNormal(const std::vector<Eigen::Vector2d>& core, double radius,
                             const Eigen::Vector2d& com, const Eigen::Vector2d& direction,
                             int side, double clearance, const Eigen::Vector2d& facing) {
  return turnedBorder(core, [radius](std::size_t) { return radius; }, com, direction, side,
                      clearance, facing);
}

Eigen::Vector2d borderNormal(const std::vector<Eigen::Vector2d>& points,
                             const std::vector<double>& radii, const Eigen::Vector2d& com,
                             const Eigen::Vector2d& direction, int side, double clearance,
                             const Eigen::Vector2d& facing) {
  return turnedBorder(points, [&radii](std::size_t i) { return radii[i]; }, com, direction,
                      side, clearance, facing);
}

Eigen::Vector2d hullFacing(const std::vector<Eigen::Vector2d>& points,
                           const std::vector<double>& radii, const Eigen::Vector2d& point) {
  // The distance from a point p outside a convex set is max over unit n of n.p - h(n) (h its
  // support), attained where the nearest point of the set lies: on one disc (n along p - v) or
  // on a segment tangent to two discs (n with n.(w - v) = r_v - r_w, pointing outwards). Those
  // candidates hold the maximizer; every other n gives a lower value, so the best of them is
  // the gradient of the distance (inside the set: the direction of least depth).
  const auto clearanceOf = [&](const Eigen::Vector2d& n) {
    return n.dot(point) - borderOffset(points, radii, n);
  };
  Eigen::Vector2d best(1.0, 0.0);
  double best_clearance = -std::numeric_limits<double>::infinity();
  const auto consider = [&](const Eigen::Vector2d& n) {
    const double value = clearanceOf(n);
    if (value > best_clearance) {
      best_clearance = value;
      best = n;
    }
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d away = point - points[i];
    if (away.norm() > 1e-12) consider(away.normalized());
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const Eigen::Vector2d along = points[j] - points[i];
      const double length = along.norm();
      if (length <= 1e-12) continue;
      const Eigen::Vector2d u = along / length, across(-u.y(), u.x());
      const double c = (radii[i] - radii[j]) / length;  // n.u of the tangents
      if (std::abs(c) > 1.0) continue;                   // one disc holds the other
      const double s = std::sqrt(1.0 - c * c);
      consider(c * u + s * across);
      consider(c * u - s * across);
    }
  }
  return best;
}

double coreDistance(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  if (insideCore(a, b.front()) || insideCore(b, a.front())) return 0.0;
  double least = (a.front() - b.front()).norm();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector2d& a1 = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j)
      least = std::min(least, segmentDistance(a[i], a1, b[j], b[(j + 1) % b.size()]));
  }
  return least;
}

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
                               double max_sideways_speed,
                               const Eigen::Ref<const Eigen::VectorXd>& room,
                               double preview_time, Eigen::Ref<Eigen::VectorXd> velocity_x,
                               Eigen::Ref<Eigen::VectorXd> velocity_y) {
  constexpr double kInside = 1e-12;  // n.u >= -this: u drives into no border
  const auto drivesIntoNone = [&](const Eigen::Vector2d& u) {
    for (int k = 0; k < normals.cols(); ++k)
      if (normals.col(k).dot(u) < -kInside * u.norm()) return false;
    return true;
  };
  // The same within the preview: walked along the unit u at `speed` for `preview_time`, the CoM
  // stays on the free side of every border it has room before (n.u >= -room / distance).
  const auto reachesNoneInPreview = [&](const Eigen::Vector2d& u, double speed) {
    const double distance = speed * preview_time;
    for (int k = 0; k < normals.cols(); ++k) {
      const double slack = distance > 0.0 ? std::max(room(k), 0.0) / distance : 0.0;
      if (normals.col(k).dot(u) < -kInside - slack) return false;
    }
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
    double best_speed = speed;
    const auto nearestAlongBorders = [&](bool within_preview) {
      double best_cosine = -1e-9;
      for (int k = 0; k < normals.cols(); ++k) {
        const Eigen::Vector2d n = normals.col(k);
        const double into = n.dot(v);
        if (!(into < 0.0)) continue;  // zero columns and borders it does not drive into
        // Within kSquare of square into the border, v's projection along it is too short to
        // say which way round (its sign flips with the sway): slide towards the passing side.
        constexpr double kSquare = 0.1;  // |projection| / |v|: 5.7 degrees
        Eigen::Vector2d u = v - into * n;
        const double along = u.norm();
        const bool wall = slides.col(k).isZero();
        if (wall && along <= 1e-12) continue;
        u = wall || along > kSquare * speed || u.dot(slides.col(k)) > 0.0
                ? Eigen::Vector2d(u / along)
                : Eigen::Vector2d(slides.col(k));
        const double cosine = u.dot(v) / speed;
        if (cosine > best_cosine &&
            (within_preview ? reachesNoneInPreview(u, speed) : drivesIntoNone(u))) {
          best = u;
          best_cosine = cosine;
          best_speed = wall ? along : speed;
        }
      }
    };
    nearestAlongBorders(false);
    // Two borders that nearly face each other across the way (the gap between two obstacles
    // met one after the other, crossed at a slant) leave a strip whose borders meet far ahead:
    // every direction along one drives, slightly, into the other, and the cone is empty. Along
    // the strip the robot reaches neither border within the preview: that direction it takes.
    // Measured on obstacle_scenes.yaml's slaloms 1 m apart at +-0.4 m: the reference left
    // square into the near border, the robot marked time 8-10 s at the entrance of each gap.
    if (best.isZero()) nearestAlongBorders(true);
    if (best.isZero()) continue;  // no such direction: the QP holds the steps (best: a unit)
    // At the reference's speed, unless its part across the robot's heading then exceeds what
    // the gait can walk sideways: asked for more, the QP buys the missing sideways speed with
    // the outward step's length (the feasibility polygon's slanted edges) and slides along a
    // steep border more slowly than along one it can follow.
    double target = best_speed;
    const Eigen::Vector2d across(-heading_sin(j), heading_cos(j));
    const double sine = std::abs(across.dot(best));
    if (max_sideways_speed > 0.0 && sine * target > max_sideways_speed)
      target = max_sideways_speed / sine;
    best *= target;
    velocity_x(j) = best.x();
    velocity_y(j) = best.y();
  }
}

}  // namespace wpg
