#pragma once
// A convex polygon as half-planes a_i' p <= b_i (outward unit normals), built from vertices.
// Used for the CoP polygon (Fig. 4, eq. 9), the step feasibility polygon (Fig. 5, eq. 14) and
// the invariant checks of finished walks.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace wpg {

class ConvexPolygon {
 public:
  ConvexPolygon() = default;

  // Vertices in either orientation. Returns false (with the reason in *why) when there are
  // fewer than 3 vertices, a vertex is not finite, two consecutive vertices coincide, or the
  // polygon is not strictly convex.
  bool setVertices(const std::vector<Eigen::Vector2d>& vertices, std::string* why = nullptr);
  // Axis-aligned rectangle centred on the origin.
  static ConvexPolygon rectangle(double half_length, double half_width);

  int edgeCount() const { return static_cast<int>(offsets_.size()); }
  // Rows: outward unit normals; offsets: a_i' p <= b_i inside.
  const Eigen::Matrix<double, Eigen::Dynamic, 2>& normals() const { return normals_; }
  const Eigen::VectorXd& offsets() const { return offsets_; }
  const std::vector<Eigen::Vector2d>& vertices() const { return vertices_; }  // counter-clockwise

  // max_i (a_i' p - b_i): <= 0 inside; > 0 is (a lower bound of) the distance outside.
  double violation(const Eigen::Vector2d& p) const;
  bool contains(const Eigen::Vector2d& p, double tolerance = 0.0) const {
    return violation(p) <= tolerance;
  }

 private:
  std::vector<Eigen::Vector2d> vertices_;
  Eigen::Matrix<double, Eigen::Dynamic, 2> normals_;
  Eigen::VectorXd offsets_;
};

// Corners (counter-clockwise) of a length x width rectangle centred on `center`, turned by
// `yaw`: foot soles and box obstacles.
std::vector<Eigen::Vector2d> rectangleCorners(const Eigen::Vector2d& center, double yaw,
                                              double length, double width);

// Convex hull (counter-clockwise, no collinear points) of a point set; used for the double
// support polygon.
std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> points);

}  // namespace wpg
