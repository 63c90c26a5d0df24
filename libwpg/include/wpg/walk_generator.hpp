#pragma once
// One whole walk, offline: the NMPC (or the LMPC baseline) every sampling period, the
// interpolation at the control period, perturbations applied to the CoM. This is what
// `wpg run` calls: a loop over OnlineWalkingGenerator (online_walking_generator.hpp) that
// feeds it the request's commands and pushes and records every control period.
#include <string>

#include "wpg/obstacles.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

struct WalkResult {
  WalkTrajectory trajectory;
  // false when some NMPC iteration ended in kFallback or kIterationLimit (the walk is still
  // complete and recorded; `wpg run` then exits 1).
  bool success = true;
  std::string message;  // one line: what went wrong first, empty on success
};

// Throws std::invalid_argument on invalid parameters or request (validate()). Obstacles
// other than circles get their signed distance from `world` (planning/'s FCL world); without
// one, from libwpg's exact 2-D AnalyticObstacleDistance.
WalkResult generateWalk(const WalkingParameters& parameters, const WalkRequest& request,
                        const ObstacleDistanceOracle* world = nullptr);

}  // namespace wpg
