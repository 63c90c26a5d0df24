#pragma once
// Steady-state command tracking of a walk (datasets/METRICS.md, `steady_*`): the mean velocity
// of the CoM in the robot's frame and the robot's heading rate over whole gait cycles once the
// last command of the scenario has held for a settling time, and how far they are from that
// command, in units of its tolerance. The study of docs/command_tracking.md reads them.
#include "wpg/walk_request.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::analysis {

// The command's last entry must have held this long before the measurement starts [s]: the
// start, and the yaw's catch-up at the yaw bound after it (up to 12 s at 0.2 rad/s), are over.
constexpr double kSteadySettlingTime = 15.0;
// Tolerance of each component: this fraction of the commanded value ...
constexpr double kSteadyRelativeTolerance = 0.1;
// ... but at least this much (a zero command is met within an absolute band).
constexpr double kSteadyVelocityFloor = 0.01;  // [m/s] for vx, vy
constexpr double kSteadyYawRateFloor = 0.01;   // [rad/s] for omega

struct SteadyTracking {
  double vx, vy;  // [m/s] mean CoM velocity in the robot's (smoothed heading's) frame
  double omega;   // [rad/s] heading rate
  double score;   // [1] largest |measured - commanded| / tolerance over vx, vy, omega
};

// All NaN when the scenario has no velocity command (a walk to a goal) or the walk holds no
// whole gait cycle after the settling time.
SteadyTracking steadyTracking(const WalkingParameters& walking, const WalkRequest& request,
                              const WalkTrajectory& trajectory);

}  // namespace wpg::analysis
