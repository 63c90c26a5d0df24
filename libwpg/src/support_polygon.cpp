// The support polygon's violation without allocation (support_polygon.hpp). Every expression
// is the one of convex_polygon.cpp (rectangleCorners, setVertices, violation; convexHull's
// monotone chain is shared: convex_hull_chain.hpp), on arrays of at most 8 corners: the
// numbers are the same to the last bit (tested).
#include "wpg/support_polygon.hpp"

#include "convex_hull_chain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wpg {
namespace {

// As convex_polygon.cpp: twice the area below which three vertices count as collinear [m^2].
constexpr double kCollinear = 1e-12;
constexpr int kMaxCorners = 8;

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// rectangleCorners(foot.head<2>(), foot(3), length, width), appended at out[count].
void appendCorners(const Eigen::Vector4d& foot, double length, double width,
                   Eigen::Vector2d* out, int& count) {
  const Eigen::Vector2d center = foot.head<2>();
  const double c = std::cos(foot(3)), s = std::sin(foot(3));
  const double hx = 0.5 * length, hy = 0.5 * width;
  const Eigen::Vector2d locals[4] = {Eigen::Vector2d(-hx, -hy), Eigen::Vector2d(hx, -hy),
                                     Eigen::Vector2d(hx, hy), Eigen::Vector2d(-hx, hy)};
  for (const Eigen::Vector2d& local : locals) {
    out[count++] = Eigen::Vector2d(center.x() + c * local.x() - s * local.y(),
                                   center.y() + s * local.x() + c * local.y());
  }
}

// convexHull (Andrew's monotone chain, collinear vertices dropped) of points[0..n), into hull;
// returns its size.
int hullOf(Eigen::Vector2d* points, int n, Eigen::Vector2d* hull) {
  // convexHull's order, by x then y (insertion sort: at most 8 points; points that tie are
  // equal, so their order does not matter)
  for (int i = 1; i < n; ++i) {
    const Eigen::Vector2d point = points[i];
    int j = i;
    for (; j > 0 && (point.x() < points[j - 1].x() ||
                     (point.x() == points[j - 1].x() && point.y() < points[j - 1].y()));
         --j)
      points[j] = points[j - 1];
    points[j] = point;
  }
  return detail::monotoneChain(points, n, hull);
}

// setVertices(vertices[0..n)) then violation(p); +infinity where setVertices fails.
double violationOf(Eigen::Vector2d* vertices, int n, const Eigen::Vector2d& p) {
  constexpr double kRefused = std::numeric_limits<double>::infinity();  // an empty polygon
  if (n < 3) return kRefused;
  for (int i = 0; i < n; ++i)
    if (!vertices[i].allFinite()) return kRefused;
  double area2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = vertices[i];
    const Eigen::Vector2d& b = vertices[(i + 1) % n];
    if ((b - a).norm() < 1e-12) return kRefused;
    area2 += a.x() * b.y() - b.x() * a.y();
  }
  if (std::abs(area2) < 1e-12) return kRefused;
  if (area2 < 0.0) std::reverse(vertices, vertices + n);
  for (int i = 0; i < n; ++i)
    if (cross(vertices[i], vertices[(i + 1) % n], vertices[(i + 2) % n]) <= kCollinear)
      return kRefused;
  double largest = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d edge = vertices[(i + 1) % n] - vertices[i];
    const Eigen::Vector2d normal = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
    const double offset = normal.dot(vertices[i]);
    largest = std::max(largest, normal.dot(p) - offset);
  }
  return largest;
}

}  // namespace

double supportPolygonViolation(const Eigen::Vector2d& p, SupportState support,
                               const Eigen::Vector4d& left, const Eigen::Vector4d& right,
                               double length, double width) {
  Eigen::Vector2d corners[kMaxCorners];
  int count = 0;
  if (support != SupportState::kRight) appendCorners(left, length, width, corners, count);
  if (support != SupportState::kLeft) appendCorners(right, length, width, corners, count);
  if (support != SupportState::kDouble) return violationOf(corners, count, p);
  Eigen::Vector2d hull[2 * kMaxCorners];
  const int n = hullOf(corners, count, hull);
  return violationOf(hull, n, p);
}

}  // namespace wpg
