#pragma once
// The obstacles a walk avoids (eq. 18-19), owned with libwpg's exact 2-D distances
// (ObstacleSet: what the NMPC's obstacle rows read, allocation-free), and the choice at each
// sample of the few that enter the QP (the nearest ones, one per obstacle slot of the model).
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "wpg/obstacles.hpp"

namespace wpg {

class ObstacleSelector {
 public:
  // Takes the obstacles (validated by Obstacle::validate, key "obstacles[i]"; throws
  // std::invalid_argument and changes nothing then). An empty list removes every obstacle.
  // Allocates.
  void set(std::vector<Obstacle> obstacles);

  bool empty() const { return obstacles_.empty(); }
  const std::vector<Obstacle>& obstacles() const { return obstacles_.obstacles(); }
  // The obstacles with their distances, as the constraints use them; null without obstacles.
  const ObstacleSet* distance() const { return obstacles_.empty() ? nullptr : &obstacles_; }

  // Slot k of `slots` <- the index of the k-th nearest obstacle (bounding circle grown by its
  // margin) within `reach` of `support` [m], -1 for the rest. Does not allocate.
  void select(const Eigen::Vector2d& support, double reach, Eigen::Ref<Eigen::VectorXi> slots);

 private:
  ObstacleSet obstacles_;
  std::vector<std::pair<double, int>> order_;  // scratch, sized once per set()
};

}  // namespace wpg
