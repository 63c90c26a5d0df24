#include "wpg/convex_polygon.hpp"

#include "convex_hull_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wpg {
namespace {

// Twice the area below which three vertices count as collinear [m^2]; the same threshold in
// setVertices() and convexHull() so that a computed hull is always accepted.
constexpr double kCollinear = 1e-12;

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

namespace detail {

int monotoneChain(const Eigen::Vector2d* sorted, int n, Eigen::Vector2d* hull) {
  if (n < 3) {
    std::copy(sorted, sorted + n, hull);
    return n;
  }
  int k = 0;
  for (int i = 0; i < n; ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], sorted[i]) <= 0.0) --k;
    hull[k++] = sorted[i];
  }
  for (int i = n - 2, lower = k + 1; i >= 0; --i) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], sorted[i]) <= 0.0) --k;
    hull[k++] = sorted[i];
  }
  int m = k - 1;
  // The exact chain keeps vertices that are collinear up to rounding (feet side by side):
  // drop them so that setVertices() accepts the hull.
  for (bool changed = true; changed && m > 3;) {
    changed = false;
    for (int i = 0; i < m; ++i) {
      if (cross(hull[(i + m - 1) % m], hull[i], hull[(i + 1) % m]) <= kCollinear) {
        std::copy(hull + i + 1, hull + m, hull + i);
        --m;
        changed = true;
        break;
      }
    }
  }
  return m;
}

}  // namespace detail

bool ConvexPolygon::setVertices(const std::vector<Eigen::Vector2d>& vertices, std::string* why) {
  auto fail = [why](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  const int n = static_cast<int>(vertices.size());
  if (n < 3) return fail("made of fewer than 3 vertices");
  for (const auto& v : vertices)
    if (!v.allFinite()) return fail("not finite");
  double area2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const auto& a = vertices[i];
    const auto& b = vertices[(i + 1) % n];
    if ((b - a).norm() < 1e-12) return fail("degenerate (two consecutive vertices coincide)");
    area2 += a.x() * b.y() - b.x() * a.y();
  }
  if (std::abs(area2) < 1e-12) return fail("degenerate (zero area)");
  std::vector<Eigen::Vector2d> ccw = vertices;
  if (area2 < 0.0) std::reverse(ccw.begin(), ccw.end());
  double turning = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = ccw[i];
    const Eigen::Vector2d& b = ccw[(i + 1) % n];
    const Eigen::Vector2d& c = ccw[(i + 2) % n];
    if (cross(a, b, c) <= kCollinear)
      return fail("not strictly convex (or has collinear vertices)");
    const Eigen::Vector2d u = b - a, v = c - b;
    turning += std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
  }
  // Left turns everywhere are not enough: a pentagram turns left at every vertex but winds
  // twice. A simple convex polygon turns by exactly 2 pi.
  if (std::abs(turning - 2.0 * M_PI) > 1e-6) return fail("not convex (self-intersecting)");
  vertices_ = ccw;
  normals_.resize(n, 2);
  offsets_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d edge = ccw[(i + 1) % n] - ccw[i];
    const Eigen::Vector2d normal = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
    normals_.row(i) = normal.transpose();
    offsets_(i) = normal.dot(ccw[i]);
  }
  return true;
}

ConvexPolygon ConvexPolygon::rectangle(double half_length, double half_width) {
  ConvexPolygon polygon;
  polygon.setVertices({{-half_length, -half_width},
                       {half_length, -half_width},
                       {half_length, half_width},
                       {-half_length, half_width}});
  return polygon;
}

double ConvexPolygon::violation(const Eigen::Vector2d& p) const {
  if (offsets_.size() == 0) return std::numeric_limits<double>::infinity();  // empty polygon
  return (normals_ * p - offsets_).maxCoeff();
}

std::vector<Eigen::Vector2d> rectangleCorners(const Eigen::Vector2d& center, double yaw,
                                              double length, double width) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  const double hx = 0.5 * length, hy = 0.5 * width;
  std::vector<Eigen::Vector2d> corners;
  corners.reserve(4);
  for (const auto& local : {Eigen::Vector2d(-hx, -hy), Eigen::Vector2d(hx, -hy),
                            Eigen::Vector2d(hx, hy), Eigen::Vector2d(-hx, hy)}) {
    corners.emplace_back(center.x() + c * local.x() - s * local.y(),
                         center.y() + s * local.x() + c * local.y());
  }
  return corners;
}

std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> points) {
  // Andrew's monotone chain.
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  const int n = static_cast<int>(points.size());
  if (n < 3) return points;
  std::vector<Eigen::Vector2d> hull(2 * n);
  hull.resize(detail::monotoneChain(points.data(), n, hull.data()));
  return hull;
}

}  // namespace wpg
