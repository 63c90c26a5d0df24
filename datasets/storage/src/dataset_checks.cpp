// The checks a run dataset holds (dataset_checks.hpp).
#include "wpg/datasets/storage/dataset_checks.hpp"

#include <algorithm>
#include <limits>

namespace wpg::datasets {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double minimum(const std::vector<double>& values) {
  double value = kInfinity;
  for (const double v : values) value = std::min(value, v);
  return value;
}

}  // namespace

FootstepObstacleChecks checkFootstepsAgainstObstacles(const WalkingParameters& parameters,
                                                      const std::vector<Obstacle>& obstacles,
                                                      const WalkTrajectory& trajectory,
                                                      const FootstepClearances* clearances) {
  FootstepObstacleChecks checks;
  const std::size_t steps = trajectory.footsteps.size();
  checks.step_centre_clearance.assign(steps, kInfinity);
  checks.step_centre_clearance_obstacle.assign(steps, -1);
  if (!obstacles.empty()) {
    const AnalyticObstacleDistance distance(obstacles);
    for (std::size_t s = 0; s < steps; ++s) {
      const Eigen::Vector2d ankle = trajectory.footsteps[s].pose.head<2>();
      for (int i = 0; i < distance.obstacleCount(); ++i) {
        // The NMPC's obstacle row (eq. 18-19): d(f) >= stepCentreMargin (margin +
        // obstacle_foot_radius, or the paper's sqrt(R^2 + m^2) - R: obstacle_distance_form).
        const double value = stepCentreClearance(
            distance, i, obstacles[static_cast<std::size_t>(i)], parameters, ankle);
        if (value < checks.step_centre_clearance[s]) {
          checks.step_centre_clearance[s] = value;
          checks.step_centre_clearance_obstacle[s] = i;
        }
      }
    }
  }
  checks.min_step_centre_clearance = minimum(checks.step_centre_clearance);
  checks.min_step_clearance = clearances ? minimum(clearances->clearance) : kInfinity;
  checks.min_step_foot_distance = clearances ? minimum(clearances->foot_distance) : kInfinity;
  return checks;
}

DatasetChecks computeDatasetChecks(const Scenario& scenario, const WalkTrajectory& trajectory,
                                   const FootstepClearances* clearances) {
  DatasetChecks checks;
  checks.walk = checkWalk(scenario.walking, trajectory);
  checks.has_obstacles = !scenario.request.obstacles.empty();
  if (checks.has_obstacles) {
    checks.footsteps = checkFootstepsAgainstObstacles(scenario.walking, scenario.request.obstacles,
                                                      trajectory, clearances);
  }
  return checks;
}

}  // namespace wpg::datasets
