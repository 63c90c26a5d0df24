#pragma once
// The world model: the scenario's obstacles as FCL collision objects, one model for the NMPC's
// obstacle constraints (paper Sec. III-D, eq. 18-19, generalized to convex shapes through
// libwpg's ObstacleDistanceOracle), the after-run footstep checks and, later, the OMPL route
// planner's state validity. FCL stays behind a pimpl: this header needs only Eigen and libwpg.
//
// Shapes: a circle is an fcl::Cylinderd, a box an fcl::Boxd, a convex polygon an fcl::Convexd
// prism, all extruded over z in [-h, h] with h = max(1 m, 2 x the bounding radius) so that
// the vertical direction is never the shortest way out of an obstacle. Ground points and feet
// live at z = 0. How each query uses FCL, and where it does not (FCL 0.7's EPA penetration
// depth hangs in some configurations), is explained in docs/goals-and-planners.md.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "wpg/obstacles.hpp"

namespace wpg::planning {

class World : public wpg::ObstacleDistanceOracle {
 public:
  // Validates every obstacle (Obstacle::validate with the key "obstacles[i]"): throws
  // std::invalid_argument with its message on a bad one. An empty world is valid.
  explicit World(std::vector<wpg::Obstacle> obstacles);
  ~World() override;
  // Copies share the (immutable) FCL geometry. Every const member function may be called from
  // several threads at once.
  World(const World&);
  World& operator=(const World&);
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  int obstacleCount() const override;
  const std::vector<wpg::Obstacle>& obstacles() const;

  // Signed distance [m] from the ground point to obstacle `obstacle` (its shape, margin not
  // included): > 0 outside, < 0 inside, exact in 2-D; `gradient` (optional) receives its
  // gradient with respect to the point, a unit vector pointing away from the obstacle.
  // Outside, from FCL's distance query (nearest points); inside and within 1 mm of the
  // boundary, from the prism's own faces (docs/goals-and-planners.md, "FCL 0.7 caveats").
  // Throws std::out_of_range on a bad index.
  double signedDistance(int obstacle, const Eigen::Vector2d& point,
                        Eigen::Vector2d* gradient) const override;

  // Signed distance [m] between the foot sole, a rectangle of sole_length x sole_width
  // centred on the ankle at `foot_pose` (x, y [m], yaw [rad]), and the obstacle grown by its
  // margin, i.e. signed_distance(sole, obstacle) - margin: < 0 when the sole enters the margin
  // (and < -margin when it enters the obstacle itself). Separated shapes: FCL's distance
  // between a thin box and the obstacle; overlapping ones: the exact 2-D penetration depth.
  // Throws std::out_of_range on a bad index, std::invalid_argument on a non-positive size.
  double footClearance(const Eigen::Vector3d& foot_pose, double sole_length, double sole_width,
                       int obstacle) const;

  // min over obstacles of signedDistance(i, point) - margin_i [m], +infinity in an empty
  // world; `nearest` (optional) receives the index of that obstacle (-1 when none).
  double clearance(const Eigen::Vector2d& point, int* nearest = nullptr) const;

  // For a planner's state validity checker: true when a disc of `radius` [m] centred on
  // (x, y) stays out of every obstacle grown by its margin (clearance >= radius).
  bool isStateValid(double x, double y, double radius) const;

  // For a planner's motion validator: the fraction in [0, 1] of the straight motion from
  // `from` to `to` over which a disc of `radius` [m] stays out of every grown obstacle, the
  // whole motion checked, not sampled points of it (1: all of it; 0: not even `from`). By
  // conservative advancement: clearance is a distance, so the disc is free over the next
  // clearance(p) - radius of the motion from p; it stops 0.1 um short of an obstacle.
  double freeFraction(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                      double radius) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace wpg::planning
