// The support polygon's violation without allocation (support_polygon.hpp). Every expression
// is the one of convex_polygon.cpp (rectangleCorners, setVertices, violation; convexHull's
// monotone chain is shared: convex_hull_chain.hpp), on arrays of at most 8 corners: the
// numbers are the same to the last bit (tested). The cached route keeps the normals and
// offsets that violation() would compute again: the same doubles, used the same way.
#include "wpg/support_polygon.hpp"

#include "convex_hull_chain.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
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

// setVertices(vertices[0..n)) then the normals and offsets violation() uses, into normal and
// offset; returns the edge count, 0 where setVertices fails.
int edgesOf(Eigen::Vector2d* vertices, int n, Eigen::Vector2d* normal, double* offset) {
  eigen_assert(n <= kMaxCorners && "a hull has at most as many vertices as points");
  if (n < 3) return 0;
  for (int i = 0; i < n; ++i)
    if (!vertices[i].allFinite()) return 0;
  double area2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = vertices[i];
    const Eigen::Vector2d& b = vertices[(i + 1) % n];
    if ((b - a).norm() < 1e-12) return 0;
    area2 += a.x() * b.y() - b.x() * a.y();
  }
  if (std::abs(area2) < 1e-12) return 0;
  if (area2 < 0.0) std::reverse(vertices, vertices + n);
  for (int i = 0; i < n; ++i)
    if (cross(vertices[i], vertices[(i + 1) % n], vertices[(i + 2) % n]) <= kCollinear)
      return 0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d edge = vertices[(i + 1) % n] - vertices[i];
    normal[i] = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
    offset[i] = normal[i].dot(vertices[i]);
  }
  return n;
}

// Bit for bit: == would take -0.0 for 0.0 (whose corners may differ in a zero's sign) and
// never match a NaN.
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool sameBits(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 4) == 0;
}

}  // namespace

SupportPolygon::SupportPolygon(SupportState support, const Eigen::Vector4d& left,
                               const Eigen::Vector4d& right, double length, double width) {
  static_assert(kMaxEdges == kMaxCorners, "edgesOf writes at most kMaxCorners edges");
  Eigen::Vector2d corners[kMaxCorners];
  int count = 0;
  if (support != SupportState::kRight) appendCorners(left, length, width, corners, count);
  if (support != SupportState::kLeft) appendCorners(right, length, width, corners, count);
  if (support != SupportState::kDouble) {
    edge_count_ = edgesOf(corners, count, normal_, offset_);
    return;
  }
  Eigen::Vector2d hull[2 * kMaxCorners];
  const int n = hullOf(corners, count, hull);
  edge_count_ = edgesOf(hull, n, normal_, offset_);
}

double SupportPolygon::violation(const Eigen::Vector2d& p) const {
  if (edge_count_ == 0) return std::numeric_limits<double>::infinity();  // an empty polygon
  double largest = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < edge_count_; ++i) largest = std::max(largest, normal_[i].dot(p) - offset_[i]);
  return largest;
}

double supportPolygonViolation(const Eigen::Vector2d& p, SupportState support,
                               const Eigen::Vector4d& left, const Eigen::Vector4d& right,
                               double length, double width) {
  return SupportPolygon(support, left, right, length, width).violation(p);
}

bool SupportPolygonCache::holds(SupportState support, const Eigen::Vector4d& left,
                                const Eigen::Vector4d& right, double length, double width) const {
  return built_ && support == support_ && sameBits(length, length_) && sameBits(width, width_) &&
         (support == SupportState::kRight || sameBits(left, left_)) &&
         (support == SupportState::kLeft || sameBits(right, right_));
}

double SupportPolygonCache::violation(const Eigen::Vector2d& p, SupportState support,
                                      const Eigen::Vector4d& left, const Eigen::Vector4d& right,
                                      double length, double width) {
  if (!holds(support, left, right, length, width)) {
    polygon_ = SupportPolygon(support, left, right, length, width);
    built_ = true;
    support_ = support;
    left_ = left;
    right_ = right;
    length_ = length;
    width_ = width;
  }
  return polygon_.violation(p);
}

}  // namespace wpg
