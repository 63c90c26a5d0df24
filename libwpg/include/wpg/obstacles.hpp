#pragma once
// Convex obstacles on the ground for the NMPC's avoidance constraint (paper Sec. III-D,
// eq. 18-19): their description, and their exact 2-D signed distances (ObstacleSet), which the
// NMPC's obstacle rows read. ObstacleDistanceOracle is the interface both ObstacleSet and
// planning/'s FCL world implement (the world serves the route planner and the post-run
// footstep checks, and is checked against ObstacleSet in tests).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/walking_parameters.hpp"

namespace wpg {

enum class ObstacleType { kCircle, kBox, kPolygon };
const char* obstacleTypeName(ObstacleType type);

struct Obstacle {
  ObstacleType type = ObstacleType::kCircle;
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  // circle, box [m]
  double radius = 0.0;                               // circle [m]
  Eigen::Vector2d size = Eigen::Vector2d::Zero();    // box: full length along its x, width [m]
  double yaw = 0.0;                                  // box [rad]
  std::vector<Eigen::Vector2d> vertices;             // polygon, convex [m]
  // Security margin: no step centre closer than this to the obstacle (swept volume of the
  // robot, paper Fig. 8's outer circle) [m].
  double margin = 0.0;

  // Throws std::invalid_argument naming `key` and what was expected (non-positive radius or
  // size, negative margin, non-convex or degenerate polygon, non-finite values).
  void validate(const std::string& key) const;
  // Vertices of a box or polygon in the world frame (counter-clockwise); empty for a circle.
  std::vector<Eigen::Vector2d> worldVertices() const;
};

// Signed distance from a ground point to one obstacle: positive outside, negative inside,
// with its gradient with respect to the point (a unit vector away from the obstacle).
class ObstacleDistanceOracle {
 public:
  virtual ~ObstacleDistanceOracle() = default;
  virtual int obstacleCount() const = 0;
  virtual double signedDistance(int obstacle, const Eigen::Vector2d& point,
                                Eigen::Vector2d* gradient) const = 0;
};

}  // namespace wpg

namespace wpg {

// The obstacles of a walk with libwpg's exact 2-D signed distances: what the NMPC's obstacle
// rows read at every sample (allocation-free queries; the FCL world of planning/ serves the
// route planner and the post-run checks), and an independent check of that world in tests.
// Owns its obstacles: built once (allocates), read-only afterwards.
class ObstacleSet : public ObstacleDistanceOracle {
 public:
  ObstacleSet() = default;
  // Throws std::invalid_argument naming 'obstacles[i]' when an obstacle is invalid
  // (Obstacle::validate).
  explicit ObstacleSet(std::vector<Obstacle> obstacles);
  int obstacleCount() const override { return static_cast<int>(obstacles_.size()); }
  bool empty() const { return obstacles_.empty(); }
  double signedDistance(int obstacle, const Eigen::Vector2d& point,
                        Eigen::Vector2d* gradient) const override;
  const Obstacle& obstacle(int index) const { return obstacles_[index]; }
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }
  // Circle enclosing obstacle `index` grown by its margin: (x, y, radius) [m], for the cheap
  // selection of the obstacles near the previewed steps.
  const Eigen::Vector3d& reachCircle(int index) const { return reach_[index]; }
  // Obstacle `index` as a convex core grown by a radius: a circle's centre and radius, a box's
  // or polygon's vertices (world, counter-clockwise) and 0. The borders of the obstacle rows
  // (obstacle_tangent.hpp) are supporting lines of the core grown further by the step-centre
  // margin.
  const std::vector<Eigen::Vector2d>& core(int index) const { return core_[index]; }
  double coreRadius(int index) const {
    return obstacles_[index].type == ObstacleType::kCircle ? obstacles_[index].radius : 0.0;
  }

 private:
  std::vector<Obstacle> obstacles_;
  std::vector<std::vector<Eigen::Vector2d>> vertices_;  // world, counter-clockwise
  std::vector<std::vector<Eigen::Vector2d>> core_;      // vertices, or a circle's centre
  std::vector<Eigen::Vector3d> reach_;
};
// The name this class had before it owned the obstacles of the NMPC.
using AnalyticObstacleDistance = ObstacleSet;

// Exact 2-D signed distances (> 0 outside) with their gradient with respect to the point
// (optional; a unit vector away from the shape): to a circle, and to a convex polygon given
// counter-clockwise (outside: distance to the nearest edge; inside: minus the distance to the
// nearest edge line, gradient that edge's outward normal).
double circleSignedDistance(const Eigen::Vector2d& center, double radius,
                            const Eigen::Vector2d& point, Eigen::Vector2d* gradient);
double polygonSignedDistance(const std::vector<Eigen::Vector2d>& polygon,
                             const Eigen::Vector2d& point, Eigen::Vector2d* gradient);

// How far beyond `obstacle`'s shape the NMPC's obstacle row (eq. 18-19,
// nmpc/obstacle_constraint.cpp) keeps a step centre, in parameters.obstacle_distance_form:
//  - sole_clearance: margin + obstacle_foot_radius (a circle: |f - c| >= R + m + r_sole);
//  - paper: sqrt(R^2 + m^2) - R for a circle (eq. 18 as written: |f - c|^2 >= R^2 + m^2), and
//    the margin for the other shapes (the step a point).
double stepCentreMargin(const Obstacle& obstacle, const WalkingParameters& parameters);
// What that bound is, in words, for messages and reports ("margin + obstacle_foot_radius" for
// sole_clearance).
const char* stepCentreBoundName(const WalkingParameters& parameters);

// The margin of the NMPC's obstacle constraint at a step centre: signed distance to obstacle
// `index` (described by `obstacle`) - stepCentreMargin(obstacle, parameters), >= 0 when the
// constraint holds. The one definition behind the start check and the landing check of
// generateWalk, the dataset's step_centre_clearance and planning/'s footstep report.
double stepCentreClearance(const ObstacleDistanceOracle& distance, int index,
                           const Obstacle& obstacle, const WalkingParameters& parameters,
                           const Eigen::Vector2d& centre);

// Centre and radius of a circle enclosing the obstacle (cheap reach test).
void boundingCircle(const Obstacle& obstacle, Eigen::Vector2d* center, double* radius);

}  // namespace wpg
