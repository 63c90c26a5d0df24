#pragma once
// One whole walk, offline: the NMPC (or the LMPC baseline) every sampling period, the
// interpolation at the control period, perturbations applied to the CoM. This is what
// `wpg run` calls: the walk loop (walk_loop.hpp) over OnlineWalkingGenerator
// (online_walking_generator.hpp) with the request's velocity schedule as its commands.
#include "wpg/pattern_generator.hpp"
#include "wpg/walk_loop.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

// Throws std::invalid_argument on invalid parameters or request (validate()). The obstacle
// rows use libwpg's exact 2-D signed distances (ObstacleSet); planning/'s FCL world checks the
// footsteps after the run.
// `extra_families`: constraint families added to the NMPC after the paper's ones.
// `observer`: called around every control period (not owned; may be null).
WalkResult generateWalk(const WalkingParameters& parameters, const WalkRequest& request,
                        const ConstraintFamilies& extra_families = {},
                        ControlLoopObserver* observer = nullptr);

}  // namespace wpg
