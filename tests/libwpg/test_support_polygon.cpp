// The allocation-free support polygon (support_polygon.hpp) gives the number of the
// ConvexPolygon route to the last bit: random feet (apart, overlapping, side by side, one on
// the other) and points inside and outside, and every sample of a walk. So does the cache that
// builds it once per support phase.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "wpg/convex_polygon.hpp"
#include "wpg/support_polygon.hpp"
#include "wpg/walk_generator.hpp"

namespace {

using wpg::SupportState;

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

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

// A 6 s walk forward, sideways and turning at once: single and double supports, yawed feet.
wpg::WalkTrajectory curvedWalk(const wpg::WalkingParameters& parameters) {
  wpg::WalkRequest request;
  request.duration = 6.0;
  request.reference = {{0.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d(0.2, 0.05, 0.1)}};
  return wpg::generateWalk(parameters, request).trajectory;
}

TEST(SupportPolygon, AgreesOnEverySampleOfAWalk) {
  const wpg::WalkingParameters parameters;
  const wpg::WalkTrajectory walk = curvedWalk(parameters);
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

// On every sample of a walk, with the sizes of the walk checks' three polygons and the run
// metrics' one, each in its own cache as they use them.
TEST(SupportPolygonCache, IsTheUncachedViolationOnEverySampleOfAWalk) {
  const wpg::WalkingParameters parameters;
  const wpg::WalkTrajectory walk = curvedWalk(parameters);
  const double sizes[3][2] = {{parameters.foot_length, parameters.foot_width},
                              {2.0 * parameters.copHalfLength(), 2.0 * parameters.copHalfWidth()},
                              {parameters.foot_length - 0.02, parameters.foot_width - 0.02}};
  wpg::SupportPolygonCache caches[3];
  int support_changes = 0;
  for (std::size_t i = 0; i < walk.size(); ++i) {
    if (i > 0 && (walk.support[i] != walk.support[i - 1])) ++support_changes;
    for (int k = 0; k < 3; ++k) {
      const double cached =
          caches[k].violation(walk.cop[i], walk.support[i], walk.left_foot[i],
                              walk.right_foot[i], sizes[k][0], sizes[k][1]);
      const double uncached =
          wpg::supportPolygonViolation(walk.cop[i], walk.support[i], walk.left_foot[i],
                                       walk.right_foot[i], sizes[k][0], sizes[k][1]);
      ASSERT_TRUE(sameBits(cached, uncached))
          << "sample " << i << " polygon " << k << ": " << cached << " vs " << uncached;
    }
  }
  EXPECT_GT(support_changes, 10);  // the walk steps: the caches are built again many times
}

// Random sequences that repeat inputs, change one of them (the support, a size, the supporting
// foot, the swing foot, a zero's sign) or hold degenerate polygons: the cache's number is the
// uncached one, bit for bit, at every call.
TEST(SupportPolygonCache, IsTheUncachedViolationOnRandomInputs) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 7);
  const SupportState states[3] = {SupportState::kDouble, SupportState::kLeft, SupportState::kRight};
  wpg::SupportPolygonCache cache;
  SupportState support = SupportState::kDouble;
  Eigen::Vector4d left(0.0, 0.1, 0.0, 0.0), right(0.0, -0.1, 0.0, 0.0);
  double length = 0.2172, width = 0.138;
  int refused = 0;
  for (int call = 0; call < 50000; ++call) {
    switch (pick(rng)) {
      case 0:
        support = states[call % 3];
        break;
      case 1:
        left << u(rng), u(rng), 0.0, M_PI * u(rng);
        break;
      case 2:
        right << left.x() + 0.3 * u(rng), left.y() - 0.2 + 0.05 * u(rng), 0.0,
            left(3) + 0.3 * u(rng);
        break;
      case 3:
        length = call % 7 == 0 ? 0.0 : 0.2 + 0.05 * u(rng);  // 0: a degenerate sole
        break;
      case 4:
        right = left;  // one foot on the other
        break;
      case 5:  // -0.0 for 0.0: the same number, maybe not the same bits in the corners
        left(3) = left(3) == 0.0 ? -left(3) : 0.0;
        break;
      default:  // the same inputs, another point
        break;
    }
    const Eigen::Vector2d p =
        0.5 * (left + right).head<2>() + 0.3 * Eigen::Vector2d(u(rng), u(rng));
    const double cached = cache.violation(p, support, left, right, length, width);
    const double uncached = wpg::supportPolygonViolation(p, support, left, right, length, width);
    ASSERT_TRUE(sameBits(cached, uncached)) << "call " << call << ": " << cached << " vs " << uncached;
    if (std::isinf(uncached)) ++refused;
  }
  EXPECT_GT(refused, 100);
}

}  // namespace
