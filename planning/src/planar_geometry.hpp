#pragma once
// Exact 2-D geometry of convex shapes on the ground, private to planning: the answers the FCL
// world gives where FCL's own penetration depth (EPA) cannot be trusted
// (docs/goals-and-planners.md, "FCL 0.7 caveats").
#include <Eigen/Core>
#include <vector>

#include "wpg/convex_polygon.hpp"
#include "wpg/obstacles.hpp"

namespace wpg::planning {

// The exact circle and polygon signed distances are libwpg's (wpg/obstacles.hpp):
using wpg::circleSignedDistance;
using wpg::polygonSignedDistance;

// The point of the edge of `polygon` nearest to `on_boundary` (a point on, or within a rounding
// error of, the boundary) that is closest to `point`: refines an approximate nearest point.
Eigen::Vector2d closestPointOnNearestEdge(const std::vector<Eigen::Vector2d>& polygon,
                                          const Eigen::Vector2d& on_boundary,
                                          const Eigen::Vector2d& point);

using wpg::rectangleCorners;  // libwpg (wpg/convex_polygon.hpp)

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
