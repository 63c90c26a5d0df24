#pragma once
// The support polygon of a walk sample, without allocation: the sole under the ankle in single
// support, the convex hull of both soles in double support (the polygon of the CoP bounds,
// paper eq. (12) without security margins). The walk checks (walk_checks.hpp) and the run
// metrics evaluate it at every 5 ms sample; building a ConvexPolygon there (vectors, a hull, a
// convexity test with atan2 per vertex) cost more than generating the walk.
#include <Eigen/Core>

#include "wpg/walk_trajectory.hpp"

namespace wpg {

// max_i (a_i' p - b_i) over the edges of the support polygon (<= 0 inside, minus the distance
// to the nearest edge; > 0 a lower bound of the distance outside), for soles of length x width
// centred on the feet (x, y, z, yaw) on the ground: the same number, to the last bit, as
// ConvexPolygon::setVertices of rectangleCorners (single support) or of convexHull of both
// feet's corners (double support), then violation(p); +infinity where setVertices would refuse
// the polygon (degenerate). The rectangle and the monotone-chain hull are simple polygons by
// construction, so setVertices' winding test (atan2 per vertex) is not needed.
double supportPolygonViolation(const Eigen::Vector2d& p, SupportState support,
                               const Eigen::Vector4d& left, const Eigen::Vector4d& right,
                               double length, double width);

}  // namespace wpg
