#pragma once
// The multibody side of a walk (paper Sec. IV and V-C): whole-body IK of the WPG's CoM and
// feet, Simbody replay to the multibody ZMP, the dynamic filter (Kajita preview control on
// the ZMP error) correcting the CoM, then IK and replay again to validate the corrected
// motion. Also the timing profile of the control chain per NMPC iteration.
#include "wpg/multibody_validation.hpp"
#include "wpg/preview_control.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::robots {

struct WalkReplaySettings {
  bool filter = true;                // run the dynamic filter (else replay only)
  PreviewControlSettings preview;    // Qe = 1, R = 1e-6, 1.6 s by default (Kajita 2003)
  // Threads of the validation replay (Simbody, MultibodyReplaySettings::threads): the same
  // results for any count; 1 where a caller runs one walk per core.
  int threads = 1;
  // The walking IK's frames and posture (the robot folder's `multibody:`; HRP-2's by default).
  WalkingIkSettings ik;
};

// Throws std::invalid_argument when the walk's sample counts are inconsistent or it has
// fewer than 3 samples. Pushes of `request` are removed from the ground wrench (they act on
// the CoM, paper Sec. V-B).
MultibodyValidation replayWalk(const RobotModel& model, const WalkingParameters& parameters,
                               const WalkRequest& request, const WalkTrajectory& walk,
                               const WalkReplaySettings& settings = WalkReplaySettings());

}  // namespace wpg::robots
