#include "wpg/obstacle_selector.hpp"

#include <algorithm>

#include "wpg/obstacle_tangent.hpp"

namespace wpg {

void ObstacleSelector::set(std::vector<Obstacle> obstacles) {
  ObstacleSet validated(std::move(obstacles));  // throws before anything changes
  obstacles_ = std::move(validated);
  order_.assign(obstacles_.obstacleCount(), {0.0, 0});
  side_.assign(obstacles_.obstacleCount(), 0);
  normal_.assign(obstacles_.obstacleCount(), Eigen::Vector2d::Zero());
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
    if (gap < reach) {
      order_[candidates++] = {gap, i};
    } else {
      side_[i] = 0;  // out of reach: its side is chosen afresh when it comes back
    }
  }
  const int kept = std::min(candidates, slot_count);
  std::partial_sort(order_.begin(), order_.begin() + kept, order_.begin() + candidates);
  for (int k = 0; k < kept; ++k) slots(k) = order_[k].second;
}

void ObstacleSelector::tangentNormals(const Eigen::Vector2d& com,
                                      const Eigen::Vector2d& feet_middle,
                                      const Eigen::Vector2d& direction, double foot_radius,
                                      double clearance,
                                      const Eigen::Ref<const Eigen::VectorXi>& slots,
                                      Eigen::Ref<Eigen::Matrix2Xd> normals) {
  normals.setZero();
  // Among other obstacles a circle keeps the row at the step: their half-planes, each turned
  // towards the command on its own, may leave no room between them (obstacle_cluttered: rows
  // relaxed, a step 4 cm inside a margin).
  int in_reach = 0;
  for (int k = 0; k < slots.size(); ++k) in_reach += slots(k) >= 0 ? 1 : 0;
  if (in_reach > 1) return;
  for (int k = 0; k < slots.size(); ++k) {
    const int index = slots(k);
    if (index < 0) continue;
    const Obstacle& obstacle = obstacles_.obstacle(index);
    if (obstacle.type != ObstacleType::kCircle) continue;
    const bool fresh = side_[index] == 0;
    if (fresh) side_[index] = obstacleSide(obstacle.center, feet_middle, direction);
    const double radius = obstacle.radius + obstacle.margin + foot_radius;
    const Eigen::Vector2d candidate =
        commandTangentNormal(obstacle.center, radius, com, direction, side_[index], clearance);
    // The border only ever turns towards the command (a ratchet): recomputed beside a CoM that
    // walked straight on, it would recede in front of the robot at every sample, and the robot
    // would walk up to the circle instead of sliding along the border.
    const double length = direction.norm();
    if (fresh || length <= 1e-12) {
      normal_[index] = candidate;
    } else {
      const Eigen::Vector2d wanted =
          side_[index] * Eigen::Vector2d(-direction.y(), direction.x()) / length;
      if (candidate.dot(wanted) >= normal_[index].dot(wanted)) normal_[index] = candidate;
    }
    normals.col(k) = normal_[index];
  }
}

}  // namespace wpg
