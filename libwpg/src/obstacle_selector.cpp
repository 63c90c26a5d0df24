#include "wpg/obstacle_selector.hpp"

#include <algorithm>

namespace wpg {

void ObstacleSelector::set(std::vector<Obstacle> obstacles) {
  ObstacleSet validated(std::move(obstacles));  // throws before anything changes
  obstacles_ = std::move(validated);
  order_.assign(obstacles_.obstacleCount(), {0.0, 0});
}

void ObstacleSelector::select(const Eigen::Vector2d& support, double reach,
                              Eigen::Ref<Eigen::VectorXi> slots) {
  slots.setConstant(-1);
  const int slot_count = static_cast<int>(slots.size());
  if (slot_count == 0 || obstacles_.empty()) return;
  int candidates = 0;
  for (int i = 0; i < obstacles_.obstacleCount(); ++i) {
    const Eigen::Vector3d& circle = obstacles_.reachCircle(i);
    const double gap = (circle.head<2>() - support).norm() - circle.z();
    if (gap < reach) order_[candidates++] = {gap, i};
  }
  const int kept = std::min(candidates, slot_count);
  std::partial_sort(order_.begin(), order_.begin() + kept, order_.begin() + candidates);
  for (int k = 0; k < kept; ++k) slots(k) = order_[k].second;
}

}  // namespace wpg
