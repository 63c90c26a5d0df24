#pragma once
// One whole walk, offline: the NMPC (or the LMPC baseline) every sampling period, the
// interpolation at the control period, perturbations applied to the CoM. This is what
// `wpg run` calls: a loop over OnlineWalkingGenerator (online_walking_generator.hpp) that
// feeds it the request's commands and pushes and records every control period.
#include <string>

#include "wpg/obstacles.hpp"
#include "wpg/pattern_generator.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

struct WalkResult {
  WalkTrajectory trajectory;
  // false when some NMPC iteration's status fails the walk (iterationStatusFailsWalk: anything
  // but solved or relaxed_obstacle), when the robot fell, or when a step landed inside an
  // obstacle's margin; the walk is still complete and recorded (`wpg run` then exits 1).
  bool success = true;
  std::string message;  // one line: what went wrong first, empty on success
};

class OnlineWalkingGenerator;
struct ControlSample;

// A controller around the WPG inside generateWalk's loop (e.g. the dynamic filter's closed
// loop of the paper's Fig. 3, robots/online_filter_loop.hpp): called around every control
// period, it may re-initialise the generator's CoM at sampling instants.
class ControlLoopObserver {
 public:
  virtual ~ControlLoopObserver() = default;
  // Before the step() of each control period, command and push already set.
  virtual void beforeStep(OnlineWalkingGenerator& generator) = 0;
  // After each step() that did not end in a fall, with the sample it produced (recorded next).
  virtual void afterStep(OnlineWalkingGenerator& generator, const ControlSample& sample) = 0;
};

// Throws std::invalid_argument on invalid parameters or request (validate()). The obstacle
// rows use libwpg's exact 2-D signed distances (ObstacleSet); planning/'s FCL world checks the
// footsteps after the run.
// `extra_families`: constraint families added to the NMPC after the paper's ones.
// `observer`: called around every control period (not owned; may be null).
WalkResult generateWalk(const WalkingParameters& parameters, const WalkRequest& request,
                        const ConstraintFamilies& extra_families = {},
                        ControlLoopObserver* observer = nullptr);

// At most this many control periods in one walk: ~0.3 kB each in memory, 3600 s at 5 ms.
constexpr double kMaxControlPeriods = 720000.0;
// Throws std::invalid_argument naming 'duration' when the walk would record more control
// periods than kMaxControlPeriods, or no NMPC iteration (duration below half a sampling
// period) (generateWalk calls it; so may other loops, before any work).
void checkWalkSize(const WalkingParameters& parameters, const WalkRequest& request);

// The pieces of generateWalk that other loops over OnlineWalkingGenerator share (the walk to a
// goal, planning/goal_walk.cpp), so that their trajectories and verdicts are the same:
// Appends one control period's sample to the trajectory's per-period columns.
void appendControlSample(const ControlSample& sample, WalkTrajectory& trajectory);
// Fails a successful walk (success, message) when a landed step lies inside an obstacle grown
// by the obstacle rows' bound (relaxed obstacle rows; stepCentreClearance below -1e-6 m).
void checkLandingsClear(const WalkingParameters& parameters, const WalkRequest& request,
                        const ObstacleDistanceOracle& distance, WalkResult& result);

}  // namespace wpg
