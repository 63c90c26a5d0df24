#pragma once
// The convex hull of a few points on arrays (no allocation), shared by convexHull()
// (convex_polygon.hpp) and the support polygon of the walk checks (support_polygon.hpp), so that
// both give the same vertices to the last bit.
#include <Eigen/Core>

namespace wpg::detail {

// Andrew's monotone chain over points[0..n), already sorted by x then y; vertices collinear up
// to rounding (twice the area <= 1e-12 m^2, the threshold of ConvexPolygon::setVertices) are
// dropped so that setVertices accepts the hull. `hull` has room for 2n points. Returns the
// hull's size; for n < 3 the points themselves.
int monotoneChain(const Eigen::Vector2d* sorted, int n, Eigen::Vector2d* hull);

}  // namespace wpg::detail
