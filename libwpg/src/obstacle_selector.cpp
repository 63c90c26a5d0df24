#include "wpg/obstacle_selector.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace wpg {

void ObstacleSelector::set(std::vector<Obstacle> obstacles, const ObstacleDistanceOracle* world) {
  for (std::size_t i = 0; i < obstacles.size(); ++i)
    obstacles[i].validate("obstacles[" + std::to_string(i) + "]");
  if (world && world->obstacleCount() != static_cast<int>(obstacles.size())) {
    throw std::invalid_argument(
        "obstacle distance: expected a world holding the " + std::to_string(obstacles.size()) +
        " obstacles given, in the same order, got one with " +
        std::to_string(world->obstacleCount()));
  }
  obstacles_ = std::move(obstacles);
  analytic_distance_.reset();
  distance_ = nullptr;
  bounds_.clear();
  if (!obstacles_.empty()) {
    if (world) {
      distance_ = world;
    } else {
      analytic_distance_ = std::make_unique<AnalyticObstacleDistance>(obstacles_);
      distance_ = analytic_distance_.get();
    }
  }
  for (const Obstacle& obstacle : obstacles_) {
    Eigen::Vector2d center;
    double radius = 0.0;
    boundingCircle(obstacle, &center, &radius);
    bounds_.emplace_back(center.x(), center.y(), radius + obstacle.margin);
  }
  order_.assign(bounds_.size(), {0.0, 0});
}

void ObstacleSelector::select(const Eigen::Vector2d& support, double reach,
                              Eigen::Ref<Eigen::VectorXi> slots) {
  slots.setConstant(-1);
  const int slot_count = static_cast<int>(slots.size());
  if (slot_count == 0 || bounds_.empty()) return;
  int candidates = 0;
  for (std::size_t i = 0; i < bounds_.size(); ++i) {
    const double gap = (bounds_[i].head<2>() - support).norm() - bounds_[i].z();
    if (gap < reach) order_[candidates++] = {gap, static_cast<int>(i)};
  }
  const int kept = std::min(candidates, slot_count);
  std::partial_sort(order_.begin(), order_.begin() + kept, order_.begin() + candidates);
  for (int k = 0; k < kept; ++k) slots(k) = order_[k].second;
}

}  // namespace wpg
