#pragma once
// The walk into a wall with no way round, shared by the tests of the walk loop's blocked verdict
// and of its allocations while blocked.
#include <Eigen/Core>

#include "wpg/obstacles.hpp"
#include "wpg/walk_request.hpp"

namespace wpg_test {

// Forward at 0.2 m/s from 1 s, for 30 s, into a wall 0.3 m x 6 m centred 2 m ahead, margin 0.2 m
// (the shipped obstacle_wall): the robot slides along the wall's border, sideways more than
// forward, and is blocked. Validated.
inline wpg::WalkRequest wallWalkRequest() {
  wpg::WalkRequest request;
  request.duration = 30.0;
  request.reference = {{0.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d(0.2, 0.0, 0.0)}};
  wpg::Obstacle wall;
  wall.type = wpg::ObstacleType::kBox;
  wall.center = Eigen::Vector2d(2.0, 0.0);
  wall.size = Eigen::Vector2d(0.3, 6.0);
  wall.margin = 0.2;
  request.obstacles = {wall};
  request.validate();
  return request;
}

}  // namespace wpg_test
