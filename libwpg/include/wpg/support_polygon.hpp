#pragma once
// The support polygon of a walk sample, without allocation: the sole under the ankle in single
// support, the convex hull of both soles in double support (the polygon of the CoP bounds,
// paper eq. (12) without security margins). The walk checks (walk_checks.hpp) and the run
// metrics evaluate it at every 5 ms sample; building a ConvexPolygon there (vectors, a hull, a
// convexity test with atan2 per vertex) cost more than generating the walk.
#include <Eigen/Core>

#include "wpg/walk_trajectory.hpp"

namespace wpg {

// The edges of the support polygon for soles of length x width centred on the feet (x, y, z,
// yaw) on the ground, built once to test many points: the vertices of ConvexPolygon::
// setVertices of rectangleCorners (single support) or of convexHull of both feet's corners
// (double support), each edge's outward unit normal and offset computed as setVertices and
// violation() compute them. The rectangle and the monotone-chain hull are simple polygons by
// construction, so setVertices' winding test (atan2 per vertex) is not needed.
class SupportPolygon {
 public:
  SupportPolygon() = default;  // refused (empty): violation() is +infinity
  SupportPolygon(SupportState support, const Eigen::Vector4d& left, const Eigen::Vector4d& right,
                 double length, double width);
  // max_i (a_i' p - b_i) over the edges (<= 0 inside, minus the distance to the nearest edge;
  // > 0 a lower bound of the distance outside): the same number, to the last bit, as
  // ConvexPolygon::violation(p); +infinity where setVertices would refuse the polygon
  // (degenerate).
  double violation(const Eigen::Vector2d& p) const;

 private:
  static constexpr int kMaxEdges = 8;  // the hull of two rectangles' 8 corners
  int edge_count_ = 0;                 // 0: refused
  Eigen::Vector2d normal_[kMaxEdges];
  double offset_[kMaxEdges] = {};
};

// SupportPolygon(support, left, right, length, width).violation(p).
double supportPolygonViolation(const Eigen::Vector2d& p, SupportState support,
                               const Eigen::Vector4d& left, const Eigen::Vector4d& right,
                               double length, double width);

// supportPolygonViolation over consecutive samples, the polygon built again only when what it
// depends on changes: the support state, the sizes, and the feet it stands on (the swing foot
// does not count in single support). Feet do not move while they support, so a walk builds
// one polygon per support phase instead of one per 5 ms sample (the hull and the normals' square
// roots were 10 % of a batch study). Inputs are compared bit for bit, so the number is the
// uncached one to the last bit whatever they hold (-0.0, NaN). Does not allocate.
class SupportPolygonCache {
 public:
  double violation(const Eigen::Vector2d& p, SupportState support, const Eigen::Vector4d& left,
                   const Eigen::Vector4d& right, double length, double width);

 private:
  bool holds(SupportState support, const Eigen::Vector4d& left, const Eigen::Vector4d& right,
             double length, double width) const;
  bool built_ = false;
  SupportState support_ = SupportState::kDouble;
  Eigen::Vector4d left_ = Eigen::Vector4d::Zero(), right_ = Eigen::Vector4d::Zero();
  double length_ = 0.0, width_ = 0.0;
  SupportPolygon polygon_;
};

}  // namespace wpg
