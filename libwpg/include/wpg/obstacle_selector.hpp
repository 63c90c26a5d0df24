#pragma once
// The obstacles a walk avoids (eq. 18-19), owned, with the distance the NMPC measures them
// with, and the choice at each sample of the few that enter the QP (the nearest ones, one per
// obstacle slot of the model).
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "wpg/obstacles.hpp"

namespace wpg {

class ObstacleSelector {
 public:
  // Takes the obstacles (validated by Obstacle::validate, key "obstacles[i]"; throws
  // std::invalid_argument). Shapes other than circles are measured by `world` when given (it
  // must hold the same obstacles, in the same order: its obstacleCount() is checked, and it
  // must outlive this object or the next set()), else by an owned AnalyticObstacleDistance.
  // An empty list removes every obstacle. Allocates.
  void set(std::vector<Obstacle> obstacles, const ObstacleDistanceOracle* world = nullptr);

  bool empty() const { return obstacles_.empty(); }
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }
  // The distance the constraints use; null without obstacles.
  const ObstacleDistanceOracle* distance() const { return distance_; }

  // Slot k of `slots` <- the index of the k-th nearest obstacle (bounding circle grown by its
  // margin) within `reach` of `support` [m], -1 for the rest. Does not allocate.
  void select(const Eigen::Vector2d& support, double reach, Eigen::Ref<Eigen::VectorXi> slots);

 private:
  std::vector<Obstacle> obstacles_;
  std::unique_ptr<AnalyticObstacleDistance> analytic_distance_;
  const ObstacleDistanceOracle* distance_ = nullptr;
  std::vector<Eigen::Vector3d> bounds_;  // bounding circle: x, y, radius + margin
  std::vector<std::pair<double, int>> order_;  // scratch, sized once per set()
};

}  // namespace wpg
