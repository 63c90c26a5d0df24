#include "planar_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wpg::planning {

namespace {

Eigen::Vector2d closestOnSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                 const Eigen::Vector2d& point) {
  const Eigen::Vector2d edge = b - a;
  return a + std::clamp((point - a).dot(edge) / edge.squaredNorm(), 0.0, 1.0) * edge;
}

}  // namespace

Eigen::Vector2d closestPointOnNearestEdge(const std::vector<Eigen::Vector2d>& polygon,
                                          const Eigen::Vector2d& on_boundary,
                                          const Eigen::Vector2d& point) {
  const std::size_t n = polygon.size();
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const double distance =
        (on_boundary - closestOnSegment(polygon[i], polygon[(i + 1) % n], on_boundary)).norm();
    if (distance < best_distance) {
      best_distance = distance;
      best = i;
    }
  }
  return closestOnSegment(polygon[best], polygon[(best + 1) % n], point);
}

namespace {

// Smallest overlap of the projections of a and b on the outward normals of `edges`' edges.
double smallestOverlap(const std::vector<Eigen::Vector2d>& edges,
                       const std::vector<Eigen::Vector2d>& a,
                       const std::vector<Eigen::Vector2d>& b) {
  double smallest = std::numeric_limits<double>::infinity();
  const std::size_t n = edges.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d edge = edges[(i + 1) % n] - edges[i];
    const Eigen::Vector2d axis = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
    double a_min = std::numeric_limits<double>::infinity(), a_max = -a_min;
    double b_min = a_min, b_max = a_max;
    for (const Eigen::Vector2d& v : a) {
      a_min = std::min(a_min, axis.dot(v));
      a_max = std::max(a_max, axis.dot(v));
    }
    for (const Eigen::Vector2d& v : b) {
      b_min = std::min(b_min, axis.dot(v));
      b_max = std::max(b_max, axis.dot(v));
    }
    smallest = std::min(smallest, std::min(a_max - b_min, b_max - a_min));
  }
  return smallest;
}

}  // namespace

double polygonPenetration(const std::vector<Eigen::Vector2d>& a,
                          const std::vector<Eigen::Vector2d>& b) {
  // For two convex polygons the minimum translation is along one of their edge normals.
  return std::min(smallestOverlap(a, a, b), smallestOverlap(b, a, b));
}

double circlePolygonPenetration(const Eigen::Vector2d& center, double radius,
                                const std::vector<Eigen::Vector2d>& polygon) {
  return radius - polygonSignedDistance(polygon, center, nullptr);
}

}  // namespace wpg::planning
