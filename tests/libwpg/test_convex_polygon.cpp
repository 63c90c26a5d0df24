// Tests of ConvexPolygon (half-plane form of the CoP and feasibility polygons) and convexHull.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "wpg/convex_polygon.hpp"
#include "wpg/walking_parameters.hpp"

namespace {

using Eigen::Vector2d;
using wpg::ConvexPolygon;
using wpg::convexHull;

double cross(const Vector2d& o, const Vector2d& a, const Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Structural invariants of an accepted polygon: unit outward normals, every vertex inside
// every half-plane and on exactly the two edges it bounds, counter-clockwise vertices.
void expectWellFormed(const ConvexPolygon& polygon) {
  const int n = polygon.edgeCount();
  ASSERT_EQ(static_cast<int>(polygon.vertices().size()), n);
  ASSERT_EQ(polygon.normals().rows(), n);
  ASSERT_EQ(polygon.offsets().size(), n);
  const auto& v = polygon.vertices();
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(polygon.normals().row(i).norm(), 1.0, 1e-12);
    EXPECT_GT(cross(v[i], v[(i + 1) % n], v[(i + 2) % n]), 0.0) << "not counter-clockwise at " << i;
    int on_edges = 0;
    for (int e = 0; e < n; ++e) {
      const double s = polygon.normals().row(e).dot(v[i]) - polygon.offsets()(e);
      EXPECT_LE(s, 1e-12);
      if (std::abs(s) <= 1e-12) ++on_edges;
    }
    EXPECT_EQ(on_edges, 2) << "vertex " << i;
    EXPECT_NEAR(polygon.violation(v[i]), 0.0, 1e-12);
  }
}

TEST(ConvexPolygon, AcceptsBothOrientations) {
  const std::vector<Vector2d> ccw{{0, 0}, {2, 0}, {3, 1}, {1, 2}};
  std::vector<Vector2d> cw(ccw.rbegin(), ccw.rend());
  ConvexPolygon a, b;
  std::string why;
  ASSERT_TRUE(a.setVertices(ccw, &why)) << why;
  ASSERT_TRUE(b.setVertices(cw, &why)) << why;
  expectWellFormed(a);
  expectWellFormed(b);
  // Same set of half-planes whatever the input orientation.
  ASSERT_EQ(a.edgeCount(), 4);
  ASSERT_EQ(b.edgeCount(), 4);
  for (int i = 0; i < 4; ++i) {
    bool found = false;
    for (int j = 0; j < 4; ++j) {
      if ((a.normals().row(i) - b.normals().row(j)).norm() < 1e-12 &&
          std::abs(a.offsets()(i) - b.offsets()(j)) < 1e-12)
        found = true;
    }
    EXPECT_TRUE(found) << "half-plane " << i << " of the ccw input is missing from the cw one";
  }
  // Same classification of points.
  std::mt19937 engine(7);
  std::uniform_real_distribution<double> u(-1.0, 4.0);
  for (int k = 0; k < 200; ++k) {
    const Vector2d p(u(engine), u(engine));
    EXPECT_EQ(a.contains(p), b.contains(p));
    EXPECT_NEAR(a.violation(p), b.violation(p), 1e-12);
  }
}

TEST(ConvexPolygon, RejectsInvalidPolygonsWithAReason) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    const char* name;
    std::vector<Vector2d> vertices;
    const char* keyword;  // expected in the reason
  };
  const std::vector<Case> cases{
      {"empty", {}, "fewer than 3"},
      {"two vertices", {{0, 0}, {1, 0}}, "fewer than 3"},
      {"NaN", {{0, 0}, {1, 0}, {nan, 1}}, "finite"},
      {"infinity", {{0, 0}, {inf, 0}, {0, 1}}, "finite"},
      {"repeated vertex", {{0, 0}, {1, 0}, {1, 0}, {0, 1}}, "degenerate"},
      {"closed ring (last == first)", {{0, 0}, {1, 0}, {0, 1}, {0, 0}}, "degenerate"},
      {"all collinear", {{0, 0}, {1, 1}, {2, 2}}, "degenerate"},
      {"collinear vertex on an edge", {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, "convex"},
      {"non-convex (dart)", {{0, 0}, {2, 1}, {0, 2}, {0.5, 1}}, "convex"},
      {"self-intersecting bow tie", {{0, 0}, {1, 1}, {1, 0}, {0, 1}}, ""},
  };
  for (const Case& c : cases) {
    ConvexPolygon polygon;
    std::string why;
    EXPECT_FALSE(polygon.setVertices(c.vertices, &why)) << c.name;
    EXPECT_FALSE(why.empty()) << c.name;
    EXPECT_NE(why.find(c.keyword), std::string::npos) << c.name << ": reason '" << why << "'";
    // A null reason pointer is allowed.
    EXPECT_FALSE(polygon.setVertices(c.vertices, nullptr)) << c.name;
  }
}

// A star polygon (the pentagon's vertices in the order 0, 2, 4, 1, 3) turns the same way at
// every vertex, so a test of consecutive cross products alone accepts it; it is not convex
// (it winds twice around its centre). The feasibility polygon comes from user-given
// vertices whose order is "not required", so such an input must be rejected.
TEST(ConvexPolygon, RejectsStarPolygon) {
  std::vector<Vector2d> pentagon;
  for (int k = 0; k < 5; ++k) {
    const double a = M_PI / 2 + 2 * M_PI * k / 5;
    pentagon.emplace_back(std::cos(a), std::sin(a));
  }
  const std::vector<Vector2d> star{pentagon[0], pentagon[2], pentagon[4], pentagon[1], pentagon[3]};
  ConvexPolygon polygon;
  std::string why;
  const bool accepted = polygon.setVertices(star, &why);
  EXPECT_FALSE(accepted) << "pentagram accepted as a convex polygon";
  if (accepted) {
    // What accepting it means: points of the pentagon near a vertex are declared outside.
    ConvexPolygon convex;
    ASSERT_TRUE(convex.setVertices(pentagon));
    const Vector2d p = 0.9 * pentagon[0];
    EXPECT_TRUE(convex.contains(p));
    EXPECT_TRUE(polygon.contains(p)) << "violation " << polygon.violation(p);
  } else {
    EXPECT_NE(why.find("convex"), std::string::npos) << why;
  }
  // The same vertices in convex order are accepted.
  EXPECT_TRUE(polygon.setVertices(pentagon, &why)) << why;
}

TEST(ConvexPolygon, RectangleContainsAndViolation) {
  const ConvexPolygon r = ConvexPolygon::rectangle(1.0, 0.5);
  expectWellFormed(r);
  ASSERT_EQ(r.edgeCount(), 4);
  EXPECT_NEAR(r.violation({0, 0}), -0.5, 1e-15);  // nearest edge: the long sides, 0.5 away
  EXPECT_NEAR(r.violation({0.9, 0}), -0.1, 1e-15);
  EXPECT_NEAR(r.violation({2, 0}), 1.0, 1e-15);
  EXPECT_NEAR(r.violation({0, -0.75}), 0.25, 1e-15);
  EXPECT_NEAR(r.violation({1, 0.5}), 0.0, 1e-15);  // corner
  EXPECT_NEAR(r.violation({3, 2}), 2.0, 1e-15);    // max over the edges, a lower bound of 2.5
  EXPECT_TRUE(r.contains({0, 0}));
  EXPECT_TRUE(r.contains({1, 0.5}));
  EXPECT_TRUE(r.contains({-1, -0.5}));
  EXPECT_FALSE(r.contains({1.001, 0}));
  EXPECT_FALSE(r.contains({0, -0.5001}));
  EXPECT_TRUE(r.contains({1.001, 0}, 0.002));
  EXPECT_FALSE(r.contains({1.003, 0}, 0.002));
}

TEST(ConvexPolygon, DefaultFeasibilityPolygon) {
  // Fig. 5: a left step in the right foot frame.
  const wpg::WalkingParameters w;
  ConvexPolygon left, right;
  std::string why;
  ASSERT_TRUE(left.setVertices(w.feasibilityVertices(wpg::FootSide::kLeft), &why)) << why;
  ASSERT_TRUE(right.setVertices(w.feasibilityVertices(wpg::FootSide::kRight), &why)) << why;
  expectWellFormed(left);
  EXPECT_EQ(left.edgeCount(), 5);
  EXPECT_TRUE(left.contains({0.0, 0.3}));
  EXPECT_TRUE(left.contains({0.0, 0.2}));  // on the inner edge
  EXPECT_NEAR(left.violation({0.0, 0.2}), 0.0, 1e-12);
  EXPECT_FALSE(left.contains({0.0, 0.15}));
  EXPECT_NEAR(left.violation({0.0, 0.15}), 0.05, 1e-12);
  EXPECT_FALSE(left.contains({0.0, 0.45}));
  EXPECT_GT(left.violation({0.0, 0.45}), 0.0);
  EXPECT_LE(left.violation({0.0, 0.45}), 0.05 + 1e-12);  // a lower bound of the distance
  EXPECT_FALSE(left.contains({0.3, 0.3}));
  EXPECT_FALSE(left.contains({0.0, -0.3}));  // a left step cannot land right of the support
  // Mirror image.
  EXPECT_TRUE(right.contains({0.0, -0.3}));
  EXPECT_FALSE(right.contains({0.0, 0.3}));
  for (double x : {-0.25, -0.1, 0.0, 0.15, 0.27}) {
    for (double y : {0.21, 0.25, 0.29}) {
      EXPECT_NEAR(left.violation({x, y}), right.violation({x, -y}), 1e-12);
    }
  }
}

TEST(ConvexHull, ContainsAllRandomPoints) {
  std::mt19937 engine(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_int_distribution<int> count(3, 60);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vector2d> points(count(engine));
    for (auto& p : points) p = Vector2d(normal(engine), 0.3 * normal(engine));
    const std::vector<Vector2d> hull = convexHull(points);
    ASSERT_GE(hull.size(), 3u);
    // Hull vertices are input points.
    for (const auto& h : hull) {
      EXPECT_TRUE(std::any_of(points.begin(), points.end(),
                              [&](const Vector2d& p) { return p == h; }));
    }
    ConvexPolygon polygon;
    std::string why;
    ASSERT_TRUE(polygon.setVertices(hull, &why)) << "trial " << trial << ": " << why;
    expectWellFormed(polygon);
    for (const auto& p : points) EXPECT_TRUE(polygon.contains(p, 1e-12)) << "trial " << trial;
    // Counter-clockwise as documented: the polygon keeps the order.
    for (std::size_t i = 0; i < hull.size(); ++i)
      EXPECT_EQ(polygon.vertices()[i], hull[i]);
    // A point beyond the farthest input point is outside.
    double far = 0.0;
    for (const auto& p : points) far = std::max(far, p.norm());
    EXPECT_FALSE(polygon.contains(Vector2d(far + 1.0, 0.0)));
  }
}

TEST(ConvexHull, DropsInteriorCollinearAndDuplicatePoints) {
  const std::vector<Vector2d> points{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 1}, {0, 2},
                                     {0, 1}, {2, 2}, {0, 0}, {0.5, 1.5}};
  const std::vector<Vector2d> hull = convexHull(points);
  ASSERT_EQ(hull.size(), 4u);
  ConvexPolygon polygon;
  std::string why;
  ASSERT_TRUE(polygon.setVertices(hull, &why)) << why;
  for (const Vector2d& corner : {Vector2d(0, 0), Vector2d(2, 0), Vector2d(2, 2), Vector2d(0, 2)})
    EXPECT_TRUE(std::find(hull.begin(), hull.end(), corner) != hull.end());
  // Two feet side by side (the double-support polygon of the standing robot).
  const ConvexPolygon left = ConvexPolygon::rectangle(0.0186, 0.019);
  std::vector<Vector2d> feet;
  for (const auto& v : left.vertices()) {
    feet.push_back(v + Vector2d(0, 0.095));
    feet.push_back(v - Vector2d(0, 0.095));
  }
  const std::vector<Vector2d> support = convexHull(feet);
  ASSERT_EQ(support.size(), 4u);
  ASSERT_TRUE(polygon.setVertices(support, &why)) << why;
  EXPECT_TRUE(polygon.contains({0, 0}));
  EXPECT_NEAR(polygon.violation({0, 0}), -0.0186, 1e-12);
  EXPECT_NEAR(polygon.violation({0, 0.114}), 0.0, 1e-12);
}

TEST(ConvexHull, FewerThanThreePoints) {
  EXPECT_TRUE(convexHull({}).empty());
  EXPECT_EQ(convexHull({Vector2d(1, 2)}).size(), 1u);
  EXPECT_EQ(convexHull({Vector2d(1, 2), Vector2d(0, 0)}).size(), 2u);
}

}  // namespace
