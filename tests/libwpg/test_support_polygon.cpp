// The allocation-free support polygon (support_polygon.hpp) gives the number of the
// ConvexPolygon route to the last bit: random feet (apart, overlapping, side by side, one on
// the other) and points inside and outside, and every sample of a walk.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "wpg/convex_polygon.hpp"
#include "wpg/support_polygon.hpp"
#include "wpg/walk_generator.hpp"

namespace {

using wpg::SupportState;

// What the walk checks computed before: a ConvexPolygon of the corners (single support) or of
// their hull (double support), then violation(p); +infinity when setVertices refuses it.
double throughConvexPolygon(const Eigen::Vector2d& p, SupportState support,
                            const Eigen::Vector4d& left, const Eigen::Vector4d& right,
                            double length, double width) {
  std::vector<Eigen::Vector2d> corners;
  for (const Eigen::Vector4d* foot : {&left, &right}) {
    if ((foot == &left && support == SupportState::kRight) ||
        (foot == &right && support == SupportState::kLeft))
      continue;
    for (const Eigen::Vector2d& corner :
         wpg::rectangleCorners(foot->head<2>(), (*foot)(3), length, width))
      corners.push_back(corner);
  }
  wpg::ConvexPolygon polygon;
  if (!polygon.setVertices(support == SupportState::kDouble ? wpg::convexHull(corners) : corners))
    return std::numeric_limits<double>::infinity();
  return polygon.violation(p);
}

TEST(SupportPolygon, IsTheConvexPolygonsViolationToTheLastBit) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const SupportState states[3] = {SupportState::kDouble, SupportState::kLeft, SupportState::kRight};
  int inside = 0, outside = 0, refused = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double yaw = M_PI * u(rng);
    Eigen::Vector4d left(u(rng), u(rng), 0.0, yaw);
    Eigen::Vector4d right = left;
    switch (trial % 5) {
      case 0:  // apart, turned
        right << left.x() + 0.3 * u(rng), left.y() - 0.2 + 0.05 * u(rng), 0.0, yaw + 0.3 * u(rng);
        break;
      case 1:  // overlapping
        right << left.x() + 0.05 * u(rng), left.y() + 0.05 * u(rng), 0.0, yaw + 0.5 * u(rng);
        break;
      case 2:  // side by side, same yaw: collinear hull vertices
        right << left.x() - 0.19 * std::sin(yaw), left.y() + 0.19 * std::cos(yaw), 0.0, yaw;
        break;
      case 3:  // one on the other: repeated corners
        break;
      default:  // far apart
        right << left.x() + 2.0 * u(rng), left.y() + 2.0 * u(rng), 0.0, M_PI * u(rng);
    }
    const Eigen::Vector2d p = 0.5 * (left + right).head<2>() + 0.3 * Eigen::Vector2d(u(rng), u(rng));
    const SupportState support = states[trial % 3];
    const double length = 0.2172, width = 0.138;
    const double expected = throughConvexPolygon(p, support, left, right, length, width);
    const double fast = wpg::supportPolygonViolation(p, support, left, right, length, width);
    ASSERT_EQ(fast, expected) << "trial " << trial;
    if (std::isinf(expected)) ++refused;
    else if (expected <= 0.0) ++inside;
    else ++outside;
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 1000);
  // A line segment of corners (zero area) is refused, as setVertices refuses it.
  const Eigen::Vector4d foot(0.0, 0.0, 0.0, 0.0);
  EXPECT_TRUE(std::isinf(wpg::supportPolygonViolation(Eigen::Vector2d::Zero(), SupportState::kLeft,
                                                      foot, foot, 0.2, 0.0)));
  EXPECT_TRUE(std::isinf(throughConvexPolygon(Eigen::Vector2d::Zero(), SupportState::kLeft, foot,
                                              foot, 0.2, 0.0)));
}

TEST(SupportPolygon, AgreesOnEverySampleOfAWalk) {
  wpg::WalkingParameters parameters;
  wpg::WalkRequest request;
  request.duration = 6.0;
  request.reference = {{0.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d(0.2, 0.05, 0.1)}};
  const wpg::WalkTrajectory walk = wpg::generateWalk(parameters, request).trajectory;
  for (std::size_t i = 0; i < walk.size(); ++i) {
    for (double shrink : {0.0, 0.02}) {
      const double length = parameters.foot_length - shrink, width = parameters.foot_width - shrink;
      ASSERT_EQ(wpg::supportPolygonViolation(walk.cop[i], walk.support[i], walk.left_foot[i],
                                             walk.right_foot[i], length, width),
                throughConvexPolygon(walk.cop[i], walk.support[i], walk.left_foot[i],
                                     walk.right_foot[i], length, width))
          << "sample " << i;
    }
  }
}

}  // namespace
