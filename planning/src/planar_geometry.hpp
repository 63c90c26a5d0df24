#pragma once
// Exact 2-D geometry of convex shapes on the ground, private to planning: the answers the FCL
// world gives where FCL's own penetration depth (EPA) cannot be trusted (README).
#include <Eigen/Core>
#include <vector>

namespace wpg::planning {

// Signed distance from `point` to the circle (center, radius): > 0 outside; gradient (optional)
// the unit vector from the centre to the point (+x at the centre).
double circleSignedDistance(const Eigen::Vector2d& center, double radius,
                            const Eigen::Vector2d& point, Eigen::Vector2d* gradient);

// Signed distance from `point` to a convex polygon (counter-clockwise): outside, the distance
// to the nearest edge; inside, minus the distance to the nearest edge line. Gradient
// (optional): away from the polygon (the nearest edge's outward normal inside).
double polygonSignedDistance(const std::vector<Eigen::Vector2d>& polygon,
                             const Eigen::Vector2d& point, Eigen::Vector2d* gradient);

// The point of the edge of `polygon` nearest to `on_boundary` (a point on, or within a rounding
// error of, the boundary) that is closest to `point`: refines an approximate nearest point.
Eigen::Vector2d closestPointOnNearestEdge(const std::vector<Eigen::Vector2d>& polygon,
                                          const Eigen::Vector2d& on_boundary,
                                          const Eigen::Vector2d& point);

// Corners (counter-clockwise) of a length x width rectangle centred on `center`, turned by yaw.
std::vector<Eigen::Vector2d> rectangleVertices(const Eigen::Vector2d& center, double yaw,
                                               double length, double width);

// Penetration depth (the shortest translation that separates them) of two overlapping convex
// polygons, by the separating axis theorem: > 0 when they overlap, <= 0 when they do not (then
// a lower bound of minus their distance).
double polygonPenetration(const std::vector<Eigen::Vector2d>& a,
                          const std::vector<Eigen::Vector2d>& b);

// Penetration depth of a circle and a convex polygon: radius - signed distance of the centre
// (exact for convex shapes, inside and outside); <= 0 when they do not overlap.
double circlePolygonPenetration(const Eigen::Vector2d& center, double radius,
                                const std::vector<Eigen::Vector2d>& polygon);

}  // namespace wpg::planning
