// The FCL world (docs/goals-and-planners.md, "FCL 0.7 caveats": why some answers do not come
// from FCL's EPA).
#include "wpg/planning/world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <fcl/fcl.h>

#include "planar_geometry.hpp"

namespace wpg::planning {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Radius of the sphere that stands for a ground point in FCL queries. Not zero: FCL 0.7's
// GJK between a zero-radius sphere and an fcl::Convexd prism stops at a wrong vertex when the
// nearest feature is a vertical edge (errors up to 0.4 m). Points closer than this to an
// obstacle are answered by the exact 2-D formulas (they touch the probe).
constexpr double kProbeRadius = 1e-3;  // [m]
// GJK convergence threshold. FCL's default (1e-6) lets GJK stop early at a vertex of a convex
// prism (distance errors up to 0.39 m seen); 1e-10 still leaves ~1e-4 in the nearest-point
// direction close to an obstacle; at 1e-15 GJK on polytopes reaches ~1e-12 m and ~1e-8, at
// about 3 us per query (sole vs cylinder: ~1e-12 m, ~10 us).
constexpr double kDistanceTolerance = 1e-15;

// The prism's half height: at least 1 m, and more than the deepest point inside the obstacle
// (its bounding radius), so that moving vertically is never the shortest way out.
double halfHeight(double bounding_radius) { return std::max(1.0, 2.0 * bounding_radius); }

fcl::Transform3d planarTransform(const Eigen::Vector2d& translation, double yaw) {
  fcl::Transform3d transform = fcl::Transform3d::Identity();
  transform.translation() << translation.x(), translation.y(), 0.0;
  transform.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return transform;
}

// A convex polygon (counter-clockwise, relative to `origin`) extruded over z in [-h, h]. FCL
// wants every face counter-clockwise seen from outside.
std::shared_ptr<fcl::Convexd> convexPrism(const std::vector<Eigen::Vector2d>& polygon,
                                          const Eigen::Vector2d& origin, double h) {
  const int n = static_cast<int>(polygon.size());
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
  vertices->reserve(2 * n);
  for (const double z : {-h, h}) {
    for (const Eigen::Vector2d& v : polygon)
      vertices->emplace_back(v.x() - origin.x(), v.y() - origin.y(), z);
  }
  auto faces = std::make_shared<std::vector<int>>();
  faces->push_back(n);  // bottom, seen from below: clockwise from above
  for (int i = n - 1; i >= 0; --i) faces->push_back(i);
  faces->push_back(n);  // top
  for (int i = 0; i < n; ++i) faces->push_back(n + i);
  for (int i = 0; i < n; ++i) {  // sides
    const int j = (i + 1) % n;
    faces->insert(faces->end(), {4, i, j, n + j, n + i});
  }
  return std::make_shared<fcl::Convexd>(vertices, n + 2, faces, /*throw_if_invalid=*/true);
}

}  // namespace

struct World::Impl {
  struct Entry {
    std::shared_ptr<fcl::CollisionGeometryd> geometry;
    fcl::Transform3d transform;
    std::vector<Eigen::Vector2d> polygon;  // world frame, counter-clockwise; empty for circles
    Eigen::Vector2d bound_center = Eigen::Vector2d::Zero();
    double bound_radius = 0.0;
    double height = 2.0;  // of the prism, z in [-height / 2, height / 2] [m]
  };

  std::vector<wpg::Obstacle> obstacles;
  std::vector<Entry> entries;
  fcl::Sphered probe{kProbeRadius};

  const Entry& entry(int index, const char* what) const {
    if (index < 0 || index >= static_cast<int>(entries.size())) {
      throw std::out_of_range(std::string("World::") + what + ": obstacle index " +
                              std::to_string(index) + " out of range [0, " +
                              std::to_string(entries.size()) + ")");
    }
    return entries[static_cast<std::size_t>(index)];
  }

  // FCL's distance between two shapes at z = 0 when they are separated (> 0, with the nearest
  // point on the second one), or a value <= 0 when they touch or overlap. Not the signed
  // distance query (enable_signed_distance): its EPA penetration depth hangs for points near a
  // cylinder's axis or a small sphere at a box corner (docs/goals-and-planners.md).
  static double separation(const fcl::CollisionGeometryd& a, const fcl::Transform3d& a_pose,
                           const Entry& b, Eigen::Vector2d* nearest_on_b) {
    fcl::DistanceRequestd request(/*enable_nearest_points=*/true,
                                  /*enable_signed_distance=*/false, 0.0, 0.0, kDistanceTolerance,
                                  fcl::GST_LIBCCD);
    fcl::DistanceResultd result;
    const double distance =
        fcl::distance(&a, a_pose, b.geometry.get(), b.transform, request, result);
    if (nearest_on_b) *nearest_on_b = result.nearest_points[1].head<2>();
    return distance;
  }

  // Exact 2-D signed distance from the shape itself (used where the probe touches).
  double exactSignedDistance(int index, const Eigen::Vector2d& point,
                             Eigen::Vector2d* gradient) const {
    const wpg::Obstacle& obstacle = obstacles[static_cast<std::size_t>(index)];
    if (obstacle.type == wpg::ObstacleType::kCircle) {
      return circleSignedDistance(obstacle.center, obstacle.radius, point, gradient);
    }
    return polygonSignedDistance(entries[static_cast<std::size_t>(index)].polygon, point, gradient);
  }
};

World::World(std::vector<wpg::Obstacle> obstacles) {
  auto impl = std::make_shared<Impl>();
  impl->obstacles = std::move(obstacles);
  impl->entries.reserve(impl->obstacles.size());
  for (std::size_t i = 0; i < impl->obstacles.size(); ++i) {
    const wpg::Obstacle& obstacle = impl->obstacles[i];
    obstacle.validate("obstacles[" + std::to_string(i) + "]");
    Impl::Entry entry;
    wpg::boundingCircle(obstacle, &entry.bound_center, &entry.bound_radius);
    const double h = halfHeight(entry.bound_radius);
    entry.height = 2.0 * h;
    switch (obstacle.type) {
      case wpg::ObstacleType::kCircle:
        entry.geometry = std::make_shared<fcl::Cylinderd>(obstacle.radius, 2.0 * h);
        entry.transform = planarTransform(obstacle.center, 0.0);
        break;
      case wpg::ObstacleType::kBox:
        entry.polygon = obstacle.worldVertices();
        entry.geometry = std::make_shared<fcl::Boxd>(obstacle.size.x(), obstacle.size.y(), 2.0 * h);
        entry.transform = planarTransform(obstacle.center, obstacle.yaw);
        break;
      case wpg::ObstacleType::kPolygon:
        entry.polygon = obstacle.worldVertices();
        entry.geometry = convexPrism(entry.polygon, entry.bound_center, h);
        entry.transform = planarTransform(entry.bound_center, 0.0);
        break;
    }
    entry.geometry->computeLocalAABB();
    impl->entries.push_back(std::move(entry));
  }
  impl_ = std::move(impl);
}

World::~World() = default;
World::World(const World&) = default;
World& World::operator=(const World&) = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

int World::obstacleCount() const { return static_cast<int>(impl_->entries.size()); }

const std::vector<wpg::Obstacle>& World::obstacles() const { return impl_->obstacles; }

double World::signedDistance(int obstacle, const Eigen::Vector2d& point,
                             Eigen::Vector2d* gradient) const {
  const Impl::Entry& entry = impl_->entry(obstacle, "signedDistance");
  Eigen::Vector2d nearest;
  const double gap = Impl::separation(impl_->probe, planarTransform(point, 0.0), entry, &nearest);
  if (gap > 0.0) {
    // The probe sphere is clear of the prism: the point is outside, by gap + probe radius,
    // and its gradient points from the nearest point of the obstacle to it.
    if (gradient) {
      // GJK's nearest point on a convex prism is ~1e-8 m off, which turns the direction by
      // ~1e-5 a millimetre away from it: snap it onto the polygon edge it lies on.
      if (obstacles()[static_cast<std::size_t>(obstacle)].type == wpg::ObstacleType::kPolygon) {
        nearest = closestPointOnNearestEdge(entry.polygon, nearest, point);
      }
      const Eigen::Vector2d away = point - nearest;
      const double norm = away.norm();
      *gradient = norm > 0.0 ? Eigen::Vector2d(away / norm) : Eigen::Vector2d::UnitX();
    }
    return gap + kProbeRadius;
  }
  return impl_->exactSignedDistance(obstacle, point, gradient);
}

double World::footClearance(const Eigen::Vector3d& foot_pose, double sole_length, double sole_width,
                            int obstacle) const {
  const Impl::Entry& entry = impl_->entry(obstacle, "footClearance");
  if (!(sole_length > 0.0) || !(sole_width > 0.0) || !std::isfinite(sole_length) ||
      !std::isfinite(sole_width)) {
    throw std::invalid_argument(
        "World::footClearance: expected a positive sole length and width [m], got " +
        std::to_string(sole_length) + " x " + std::to_string(sole_width));
  }
  const double margin = impl_->obstacles[static_cast<std::size_t>(obstacle)].margin;
  // The sole as a box exactly as tall as the obstacle's prism: FCL 0.7's GJK between a thin box
  // and an fcl::Convexd prism stops at a wrong vertex pair when the nearest feature is a vertical
  // edge (errors up to 0.4 m); with equal heights the problem is planar and exact.
  const fcl::Boxd sole(sole_length, sole_width, entry.height);
  const double gap =
      Impl::separation(sole, planarTransform(foot_pose.head<2>(), foot_pose.z()), entry, nullptr);
  if (gap > 0.0) return gap - margin;
  // Touching or overlapping: minus the exact 2-D penetration depth.
  const std::vector<Eigen::Vector2d> rectangle =
      rectangleCorners(foot_pose.head<2>(), foot_pose.z(), sole_length, sole_width);
  const wpg::Obstacle& shape = impl_->obstacles[static_cast<std::size_t>(obstacle)];
  const double depth = shape.type == wpg::ObstacleType::kCircle
                           ? circlePolygonPenetration(shape.center, shape.radius, rectangle)
                           : polygonPenetration(rectangle, entry.polygon);
  return -depth - margin;
}

double World::clearance(const Eigen::Vector2d& point, int* nearest) const {
  double best = kInfinity;
  int best_index = -1;
  for (int i = 0; i < obstacleCount(); ++i) {
    const Impl::Entry& entry = impl_->entries[static_cast<std::size_t>(i)];
    const double margin = impl_->obstacles[static_cast<std::size_t>(i)].margin;
    // The bounding circle gives a lower bound: skip obstacles that cannot be nearer.
    if ((point - entry.bound_center).norm() - entry.bound_radius - margin >= best) continue;
    const double value = signedDistance(i, point, nullptr) - margin;
    if (value < best) {
      best = value;
      best_index = i;
    }
  }
  if (nearest) *nearest = best_index;
  return best;
}

bool World::isStateValid(double x, double y, double radius) const {
  const Eigen::Vector2d point(x, y);
  if (!point.allFinite() || !std::isfinite(radius)) return false;
  for (int i = 0; i < obstacleCount(); ++i) {
    const Impl::Entry& entry = impl_->entries[static_cast<std::size_t>(i)];
    const double margin = impl_->obstacles[static_cast<std::size_t>(i)].margin;
    if ((point - entry.bound_center).norm() - entry.bound_radius - margin >= radius) continue;
    if (signedDistance(i, point, nullptr) - margin < radius) return false;
  }
  return true;
}

double World::freeFraction(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                           double radius) const {
  // Distances from FCL are ~1e-8 m off: each advance keeps kSlack of them, and a clearance
  // below kStop counts as touching (an approach at a grazing angle would otherwise take ever
  // shorter advances). At most kMaxAdvances advances: beyond, the rest of the motion is refused.
  constexpr double kSlack = 1e-7;
  constexpr double kStop = 2e-7;
  constexpr int kMaxAdvances = 100000;
  const double length = (to - from).norm();
  if (!from.allFinite() || !to.allFinite() || !std::isfinite(radius)) return 0.0;
  double travelled = 0.0;
  for (int advance = 0; advance < kMaxAdvances; ++advance) {
    const Eigen::Vector2d point =
        length > 0.0 ? Eigen::Vector2d(from + (to - from) * (travelled / length)) : from;
    const double room = clearance(point) - radius;
    if (room < kStop) return length > 0.0 ? travelled / length : 0.0;
    travelled += room - kSlack;
    if (travelled >= length) return 1.0;
  }
  return travelled / length;
}

}  // namespace wpg::planning
