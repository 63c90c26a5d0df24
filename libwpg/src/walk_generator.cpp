// generateWalk: the walk loop with the request's velocity schedule (walk_generator.hpp).
#include "wpg/walk_generator.hpp"

#include <stdexcept>
#include <string>

#include "wpg/obstacles.hpp"
#include "wpg/online_walking_generator.hpp"

namespace wpg {
namespace {

// The feet must start clear of every obstacle grown by the obstacle rows' bound (its margin and
// the sole radius by default; obstacle_distance_form).
void requireFeetClear(const OnlineWalkingGenerator& generator, const WalkRequest& request,
                      const ObstacleDistanceOracle& distance) {
  const WalkingParameters& parameters = generator.parameters();
  for (int o = 0; o < static_cast<int>(request.obstacles.size()); ++o) {
    for (FootSide side : {FootSide::kLeft, FootSide::kRight}) {
      const Eigen::Vector3d& foot = generator.patternGenerator().footPose(side);
      const double clearance = stepCentreClearance(distance, o, request.obstacles[o],
                                                   parameters, foot.head<2>());
      if (clearance < 0.0) {
        throw std::invalid_argument(
            "'obstacles[" + std::to_string(o) + "]': expected the initial feet clear of the " +
            "obstacle grown by " + stepCentreBoundName(parameters) + ", but the " +
            (side == FootSide::kLeft ? "left" : "right") + " foot is " +
            std::to_string(-clearance) + " m inside");
      }
    }
  }
}

}  // namespace

WalkResult generateWalk(const WalkingParameters& parameters, const WalkRequest& request,
                        const ConstraintFamilies& extra_families,
                        ControlLoopObserver* observer) {
  parameters.validate();
  request.validate();
  checkWalkSize(parameters, request);
  OnlineWalkingGenerator generator(parameters, request.generator, extra_families);
  // Obstacle distances: libwpg's exact 2-D ones, as the NMPC's rows see them.
  if (!request.obstacles.empty()) {
    generator.setObstacles(request.obstacles);
    requireFeetClear(generator, request, *generator.obstacleDistance());
  }
  ScheduledCommands commands(request);
  return runWalkLoop(generator, request, commands, observer);
}

}  // namespace wpg
