// The reach of a steady two-step gait (wpg/gait_reach.hpp): a port of analysis/gait_reach.py,
// step for step, so that both give the same lambda (tests/libwpg/test_gait_reach.cpp).
#include "wpg/gait_reach.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace wpg {
namespace {

using Vector2 = Eigen::Vector2d;
using Matrix2 = Eigen::Matrix2d;

Matrix2 rotation(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Matrix2 r;
  r << c, -s, s, c;
  return r;
}

// At most 5 polygon edges per foot: 10 half-planes a x <= b.
constexpr int kMaxRows = 10;
struct HalfPlanes {
  std::array<Vector2, kMaxRows> a;
  std::array<double, kMaxRows> b{};
  int count = 0;
  void add(const Vector2& row, double rhs) {
    a[count] = row;
    b[count] = rhs;
    ++count;
  }
};

// The outward half-planes of a convex polygon given in either orientation.
void addPolygon(const std::array<Vector2, 5>& vertices, HalfPlanes& out) {
  double area = 0.0;
  for (int i = 0; i < 5; ++i) {
    const Vector2& p = vertices[i];
    const Vector2& q = vertices[(i + 1) % 5];
    area += p.x() * q.y() - q.x() * p.y();
  }
  for (int k = 0; k < 5; ++k) {
    // Counter-clockwise order: reversed when the area is negative.
    const int i = area < 0.0 ? 4 - k : k;
    const int j = area < 0.0 ? (8 - k) % 5 : (k + 1) % 5;
    const Vector2 edge = vertices[j] - vertices[i];
    const Vector2 outward(edge.y(), -edge.x());
    out.add(outward, outward.dot(vertices[i]));
  }
}

// Whether {x : rows x <= rhs} (bounded) is not empty: a large box clipped by each half-plane.
bool feasible2d(const HalfPlanes& h) {
  constexpr int kCapacity = 4 + kMaxRows + 2;  // each clip adds at most one vertex
  std::array<Vector2, kCapacity> polygon{Vector2(-10.0, -10.0), Vector2(10.0, -10.0),
                                         Vector2(10.0, 10.0), Vector2(-10.0, 10.0)};
  std::array<Vector2, kCapacity> clipped;
  int size = 4;
  for (int r = 0; r < h.count; ++r) {
    int out = 0;
    for (int i = 0; i < size; ++i) {
      const Vector2& p = polygon[i];
      const Vector2& q = polygon[(i + 1) % size];
      const double fp = h.a[r].dot(p) - h.b[r], fq = h.a[r].dot(q) - h.b[r];
      if (fp <= 1e-12) clipped[out++] = p;
      if ((fp < -1e-12 && fq > 1e-12) || (fp > 1e-12 && fq < -1e-12))
        clipped[out++] = p + (q - p) * fp / (fp - fq);
    }
    if (out == 0) return false;
    size = out;
    std::copy(clipped.begin(), clipped.begin() + size, polygon.begin());
  }
  return true;
}

// Whether the line {point + s direction} meets {x : rows x <= rhs}.
bool feasibleLine(const HalfPlanes& h, const Vector2& point, const Vector2& direction) {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  for (int r = 0; r < h.count; ++r) {
    const double slope = h.a[r].dot(direction), room = h.b[r] - h.a[r].dot(point);
    if (std::abs(slope) < 1e-15) {
      if (room < -1e-12) return false;
    } else if (slope > 0.0) {
      high = std::min(high, room / slope);
    } else {
      low = std::max(low, room / slope);
    }
  }
  return low <= high + 1e-12;
}

// Whether the stride anchored at the left (or right) step walks `scale` times the target:
// the linear program of gait_reach.hpp at one lambda.
class StrideFeasibility {
 public:
  StrideFeasibility(const Vector2& target, double omega, double step_duration,
                    const std::array<Vector2, 5>& left, const std::array<Vector2, 5>& right,
                    bool regular, bool left_first)
      : regular_(regular) {
    const double delta = omega * step_duration;
    const Matrix2 m = -0.5 * rotation(-delta);  // m = M p2
    const Matrix2 a1 = rotation(delta / 2);
    const Matrix2 a2 =
        rotation(delta / 2) * ((rotation(2 * delta) - Matrix2::Identity()) * m + rotation(delta));
    const double sinc = std::abs(delta) > 1e-12 ? std::sin(delta) / delta : 1.0;
    const Matrix2 k = rotation(-delta) / (2 * step_duration * sinc);
    const Matrix2 v1 = k * a1, v2 = k * a2;
    addPolygon(left_first ? left : right, first_);
    addPolygon(left_first ? right : left, second_);
    const Matrix2 v2_inverse = v2.inverse();
    w_ = v2_inverse * v1;
    u_ = v2_inverse * target;
  }

  bool operator()(double scale) const {
    // p2 = V2^-1 (scale v - V1 p1) inside the second polygon: a condition on p1.
    HalfPlanes rows = first_;
    for (int r = 0; r < second_.count; ++r)
      rows.add(-(second_.a[r].transpose() * w_).transpose(),
               second_.b[r] - scale * second_.a[r].dot(u_));
    if (!regular_) return feasible2d(rows);
    // p1.x = p2.x: (e1 + (V2^-1 V1)^T e1) . p1 = scale (V2^-1 v).x
    const Vector2 normal = Vector2(1.0, 0.0) + w_.row(0).transpose();
    const double value = scale * u_.x();
    if (normal.norm() < 1e-15) return std::abs(value) < 1e-12 && feasible2d(rows);
    const Vector2 point = normal * value / normal.dot(normal);
    return feasibleLine(rows, point, Vector2(-normal.y(), normal.x()));
  }

 private:
  bool regular_;
  HalfPlanes first_, second_;
  Matrix2 w_;
  Vector2 u_;
};

double reach(const StrideFeasibility& feasible) {
  if (!feasible(0.0)) return 0.0;
  double low = 0.0, high = 1.0;
  while (feasible(high) && high < 64.0) {
    low = high;
    high *= 2.0;
  }
  for (int i = 0; i < 60; ++i) {
    const double middle = 0.5 * (low + high);
    if (feasible(middle)) {
      low = middle;
    } else {
      high = middle;
    }
  }
  return low;
}

// The polygons of a left step (in the right foot's frame) and of its mirror image.
void footPolygons(const std::array<double, 5>& feasibility_x,
                  const std::array<double, 5>& feasibility_y, std::array<Vector2, 5>* left,
                  std::array<Vector2, 5>* right) {
  for (int i = 0; i < 5; ++i) {
    (*left)[i] = Vector2(feasibility_x[i], feasibility_y[i]);
    (*right)[i] = Vector2(feasibility_x[i], -feasibility_y[i]);
  }
}

}  // namespace

double gaitReach(const Eigen::Vector2d& velocity, double omega, double step_duration,
                 const std::array<double, 5>& feasibility_x,
                 const std::array<double, 5>& feasibility_y, bool regular) {
  if (std::abs(velocity.x()) < 1e-12 && std::abs(velocity.y()) < 1e-12)
    return std::numeric_limits<double>::infinity();
  std::array<Vector2, 5> left, right;
  footPolygons(feasibility_x, feasibility_y, &left, &right);
  return std::max(
      reach(StrideFeasibility(velocity, omega, step_duration, left, right, regular, true)),
      reach(StrideFeasibility(velocity, omega, step_duration, left, right, regular, false)));
}

bool gaitReachesCommand(const Eigen::Vector2d& velocity, double omega, double step_duration,
                        const std::array<double, 5>& feasibility_x,
                        const std::array<double, 5>& feasibility_y, bool regular) {
  if (std::abs(velocity.x()) < 1e-12 && std::abs(velocity.y()) < 1e-12) return true;
  std::array<Vector2, 5> left, right;
  footPolygons(feasibility_x, feasibility_y, &left, &right);
  // reach() >= 1 exactly when lambda = 0 and lambda = 1 are feasible: its doubling starts at 1.
  for (const bool left_first : {true, false}) {
    const StrideFeasibility feasible(velocity, omega, step_duration, left, right, regular,
                                     left_first);
    if (feasible(0.0) && feasible(1.0)) return true;
  }
  return false;
}

}  // namespace wpg
