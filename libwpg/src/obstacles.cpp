#include "wpg/obstacles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "wpg/convex_polygon.hpp"

namespace wpg {

const char* obstacleTypeName(ObstacleType type) {
  switch (type) {
    case ObstacleType::kCircle: return "circle";
    case ObstacleType::kBox: return "box";
    case ObstacleType::kPolygon: return "polygon";
  }
  return "unknown";
}

void Obstacle::validate(const std::string& key) const {
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument("'" + key + "': expected " + what);
  };
  if (!std::isfinite(margin) || margin < 0.0) fail("margin: a finite distance >= 0 m");
  switch (type) {
    case ObstacleType::kCircle:
      if (!center.allFinite()) fail("center: two finite numbers [m]");
      if (!std::isfinite(radius) || radius <= 0.0) fail("radius: a positive distance in m");
      break;
    case ObstacleType::kBox:
      if (!center.allFinite()) fail("center: two finite numbers [m]");
      if (!size.allFinite() || size.minCoeff() <= 0.0) fail("size: two positive lengths [m]");
      if (!std::isfinite(yaw)) fail("yaw: a finite angle in rad");
      break;
    case ObstacleType::kPolygon: {
      ConvexPolygon polygon;
      std::string why;
      if (!polygon.setVertices(vertices, &why)) fail("vertices: a convex polygon, got one " + why);
      break;
    }
  }
}

std::vector<Eigen::Vector2d> Obstacle::worldVertices() const {
  if (type == ObstacleType::kCircle) return {};
  if (type == ObstacleType::kPolygon) {
    ConvexPolygon polygon;
    polygon.setVertices(vertices);
    return polygon.vertices();
  }
  return rectangleCorners(center, yaw, size.x(), size.y());
}

void boundingCircle(const Obstacle& obstacle, Eigen::Vector2d* center, double* radius) {
  if (obstacle.type == ObstacleType::kCircle) {
    *center = obstacle.center;
    *radius = obstacle.radius;
    return;
  }
  const std::vector<Eigen::Vector2d> vertices = obstacle.worldVertices();
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& v : vertices) mean += v;
  mean /= static_cast<double>(vertices.size());
  double r = 0.0;
  for (const auto& v : vertices) r = std::max(r, (v - mean).norm());
  *center = mean;
  *radius = r;
}

ObstacleSet::ObstacleSet(std::vector<Obstacle> obstacles) : obstacles_(std::move(obstacles)) {
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    const Obstacle& obstacle = obstacles_[i];
    obstacle.validate("obstacles[" + std::to_string(i) + "]");
    vertices_.push_back(obstacle.worldVertices());
    core_.push_back(obstacle.type == ObstacleType::kCircle
                        ? std::vector<Eigen::Vector2d>{obstacle.center}
                        : vertices_.back());
    Eigen::Vector2d center;
    double radius = 0.0;
    boundingCircle(obstacle, &center, &radius);
    reach_.emplace_back(center.x(), center.y(), radius + obstacle.margin);
  }
}

double stepCentreMargin(const Obstacle& obstacle, const WalkingParameters& parameters) {
  if (parameters.obstacle_distance_form == ObstacleDistanceForm::kSoleClearance)
    return obstacle.margin + parameters.obstacle_foot_radius;
  if (obstacle.type != ObstacleType::kCircle) return obstacle.margin;
  // eq. (18): |f - c| >= sqrt(R^2 + m^2), i.e. the signed distance |f - c| - R at least this
  const double R = obstacle.radius, m = obstacle.margin;
  return std::sqrt(R * R + m * m) - R;
}

const char* stepCentreBoundName(const WalkingParameters& parameters) {
  return parameters.obstacle_distance_form == ObstacleDistanceForm::kPaper
             ? "sqrt(R^2 + m^2) from a circle's centre (eq. 18 as written; margin for other "
               "shapes)"
             : "margin + obstacle_foot_radius";
}

double stepCentreClearance(const ObstacleDistanceOracle& distance, int index,
                           const Obstacle& obstacle, const WalkingParameters& parameters,
                           const Eigen::Vector2d& centre) {
  return distance.signedDistance(index, centre, nullptr) - stepCentreMargin(obstacle, parameters);
}

double circleSignedDistance(const Eigen::Vector2d& center, double radius,
                            const Eigen::Vector2d& point, Eigen::Vector2d* gradient) {
  const Eigen::Vector2d d = point - center;
  const double norm = d.norm();
  if (gradient) *gradient = norm > 0.0 ? Eigen::Vector2d(d / norm) : Eigen::Vector2d(1.0, 0.0);
  return norm - radius;
}

double polygonSignedDistance(const std::vector<Eigen::Vector2d>& v, const Eigen::Vector2d& p,
                             Eigen::Vector2d* gradient) {
  const int n = static_cast<int>(v.size());
  double best_plane = -std::numeric_limits<double>::infinity();
  Eigen::Vector2d best_normal = Eigen::Vector2d::UnitX();
  double best_outside = std::numeric_limits<double>::infinity();
  Eigen::Vector2d best_closest = p;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = v[i], b = v[(i + 1) % n];
    const Eigen::Vector2d edge = b - a;
    const Eigen::Vector2d normal = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
    const double plane = normal.dot(p - a);
    if (plane > best_plane) {
      best_plane = plane;
      best_normal = normal;
    }
    const double s = std::clamp((p - a).dot(edge) / edge.squaredNorm(), 0.0, 1.0);
    const Eigen::Vector2d closest = a + s * edge;
    const double distance = (p - closest).norm();
    if (distance < best_outside) {
      best_outside = distance;
      best_closest = closest;
    }
  }
  if (best_plane <= 0.0) {  // inside (or on the boundary)
    if (gradient) *gradient = best_normal;
    return best_plane;
  }
  if (gradient) *gradient = (p - best_closest) / best_outside;
  return best_outside;
}

double ObstacleSet::signedDistance(int index, const Eigen::Vector2d& p,
                                                Eigen::Vector2d* gradient) const {
  const Obstacle& obstacle = obstacles_[index];
  if (obstacle.type == ObstacleType::kCircle)
    return circleSignedDistance(obstacle.center, obstacle.radius, p, gradient);
  return polygonSignedDistance(vertices_[index], p, gradient);
}

}  // namespace wpg
