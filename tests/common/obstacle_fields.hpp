#pragma once
// Obstacle sets shared by tests and benchmarks.
#include <vector>

#include <Eigen/Core>

#include "wpg/obstacles.hpp"

namespace wpg_test {

// A circle, a box and a triangle around the origin (one of each shape, with margins).
inline std::vector<wpg::Obstacle> threeObstacles() {
  std::vector<wpg::Obstacle> obstacles(3);
  obstacles[0].type = wpg::ObstacleType::kCircle;
  obstacles[0].center = Eigen::Vector2d(0.6, 0.2);
  obstacles[0].radius = 0.15;
  obstacles[0].margin = 0.1;
  obstacles[1].type = wpg::ObstacleType::kBox;
  obstacles[1].center = Eigen::Vector2d(-0.5, -0.4);
  obstacles[1].size = Eigen::Vector2d(0.4, 0.2);
  obstacles[1].yaw = 0.6;
  obstacles[1].margin = 0.05;
  obstacles[2].type = wpg::ObstacleType::kPolygon;
  obstacles[2].vertices = {{0.3, -0.9}, {0.7, -0.8}, {0.5, -0.5}};
  obstacles[2].margin = 0.02;
  return obstacles;
}

// A corridor along +x of `count` obstacles every 0.5 m, alternately at y = +-half_width:
// circles, boxes and triangles in turn, margin 0.1 m. With half_width 1 m, three of them are
// within reach of the previewed steps of a robot walking along the x axis at every sample.
inline std::vector<wpg::Obstacle> obstacleCorridor(int count, double half_width) {
  std::vector<wpg::Obstacle> obstacles;
  for (int i = 0; i < count; ++i) {
    wpg::Obstacle o;
    const double x = 0.5 * i, y = (i % 2 ? half_width : -half_width);
    o.margin = 0.1;
    if (i % 3 == 0) {
      o.type = wpg::ObstacleType::kCircle;
      o.center = Eigen::Vector2d(x, y);
      o.radius = 0.15;
    } else if (i % 3 == 1) {
      o.type = wpg::ObstacleType::kBox;
      o.center = Eigen::Vector2d(x, y);
      o.size = Eigen::Vector2d(0.3, 0.2);
      o.yaw = 0.3;
    } else {
      o.type = wpg::ObstacleType::kPolygon;
      o.vertices = {{x - 0.15, y - 0.1}, {x + 0.15, y - 0.1}, {x, y + 0.15}};
    }
    obstacles.push_back(o);
  }
  return obstacles;
}

}  // namespace wpg_test
