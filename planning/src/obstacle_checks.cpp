#include "wpg/planning/obstacle_checks.hpp"

#include <algorithm>
#include <limits>

namespace wpg::planning {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Keeps the smallest value of a column and where it is.
void keepMinimum(double value, int step, double* minimum, int* minimum_step) {
  if (value < *minimum) {
    *minimum = value;
    *minimum_step = step;
  }
}

}  // namespace

FootstepObstacleReport checkFootsteps(const World& world, const wpg::WalkingParameters& parameters,
                                      const wpg::WalkTrajectory& trajectory) {
  FootstepObstacleReport report;
  report.min_clearance = report.min_foot_distance = report.min_centre_clearance = kInfinity;
  const std::size_t steps = trajectory.footsteps.size();
  report.clearance.assign(steps, kInfinity);
  report.clearance_obstacle.assign(steps, -1);
  report.foot_distance.assign(steps, kInfinity);
  report.centre_clearance.assign(steps, kInfinity);
  report.centre_clearance_obstacle.assign(steps, -1);
  for (std::size_t s = 0; s < steps; ++s) {
    const Eigen::Vector3d& pose = trajectory.footsteps[s].pose;
    for (int i = 0; i < world.obstacleCount(); ++i) {
      const double margin = world.obstacles()[static_cast<std::size_t>(i)].margin;
      const double clearance =
          world.footClearance(pose, parameters.foot_length, parameters.foot_width, i);
      if (clearance < report.clearance[s]) {
        report.clearance[s] = clearance;
        report.clearance_obstacle[s] = i;
      }
      report.foot_distance[s] = std::min(report.foot_distance[s], clearance + margin);
      // The NMPC's obstacle row (eq. 18-19): the margin grown by the sole radius, or the
      // paper's sqrt(R^2 + m^2) (parameters.obstacle_distance_form).
      const double centre =
          wpg::stepCentreClearance(world, i, world.obstacles()[static_cast<std::size_t>(i)],
                                   parameters, pose.head<2>());
      if (centre < report.centre_clearance[s]) {
        report.centre_clearance[s] = centre;
        report.centre_clearance_obstacle[s] = i;
      }
    }
    const int step = static_cast<int>(s);
    keepMinimum(report.clearance[s], step, &report.min_clearance, &report.min_clearance_step);
    keepMinimum(report.foot_distance[s], step, &report.min_foot_distance,
                &report.min_foot_distance_step);
    keepMinimum(report.centre_clearance[s], step, &report.min_centre_clearance,
                &report.min_centre_clearance_step);
  }
  return report;
}

}  // namespace wpg::planning
