#pragma once
// The closed loop of the paper's Fig. 3, run online one control period (5 ms) at a time:
//
//   WPG (OnlineWalkingGenerator) --c, f--> dynamic filter --c~--> IK --> q sent to the robot
//     ^                                        |
//     +---- CoM state sent (every NMPC iteration, when closed_loop or reinitialize_wpg) ----+
//
// The WPG is whoever commands it: the velocity schedule of the request (generateWalk) or the
// route planner's path follower of a walk to a goal (planning/goal_walk.hpp), which gives the
// NMPC a command every iteration in the same loop (runWalkLoop, walk_loop.hpp): the filter
// sits around the generator's steps, not around the command source, so both run the same loop.
// The arrow back is off by default (mode online, an open loop). closed_loop closes it in a
// stable form: the WPG restarts from the CoM state sent to the robot and the filter runs on
// (OnlineDynamicFilter::absorbIncrement); reinitialize_wpg is the paper's Fig. 3 read
// literally (the filter restarts from rest after the WPG absorbed its correction), unstable
// here: wpg/dynamic_filter.hpp says why.
// At every NMPC iteration the filter takes what the NMPC previews of the coming motion (the
// plan in force: OnlineWalkingGenerator::previewReference) over the current sampling period
// plus the filter's preview (Sec. V-A: one step, 0.8 s), runs the walking IK over it and
// its multibody ZMP (the momentum rate of the kinematics, momentum_zmp.hpp: Simbody's inverse
// dynamics within 1e-9 m), and gets the multibody ZMP error it will preview until the next
// iteration; between two iterations the plan does not change, nor does the window. Every
// control period it advances the preview controller by one step (OnlineDynamicFilter), adds
// its correction to the WPG's CoM and solves the IK of the corrected motion (the q sent to the
// robot; Newton from the previous ticks' solutions). Nothing of the walk after the current
// instant is used but the NMPC's plan: the filter is causal (tested). Neither the window nor
// the tick allocates once the first window has sized the buffers.
//
// Each stage is timed in its own control period (MultibodyValidation::tick_stage_time), as the
// paper's Sec. V-C table measures the control loop. The motion sent to the robot is replayed
// once more at the end (validation, not part of the loop: Simbody's inverse dynamics) for the
// ZMP error after the filter.
#include <functional>

#include "wpg/dynamic_filter.hpp"
#include "wpg/multibody_validation.hpp"
#include "wpg/preview_control.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"
#include "wpg/walk_generator.hpp"
#include "wpg/walk_loop.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg::robots {

// The online loop's preview controller by default: filter_settings' Qe and preview time, and
// R = DynamicFilterLoopSettings::online_input_weight (1e-3; why: wpg/dynamic_filter.hpp).
PreviewControlSettings onlinePreviewSettings(const PreviewControlSettings& filter_settings,
                                             const DynamicFilterLoopSettings& loop = {});

struct OnlineFilterLoopSettings {
  // the filter's preview controller (Qe, R, preview time)
  PreviewControlSettings preview = onlinePreviewSettings(PreviewControlSettings());
  // Fig. 3 read literally: the WPG's initial CoM state := the filter's corrected state at
  // every NMPC iteration, the filter restarted from rest (measured unstable:
  // DynamicFilterLoopSettings); false: no such re-initialisation.
  bool reinitialize_wpg = false;
  // Fig. 3 in a stable form (mode closed_loop): at every NMPC iteration the WPG's CoM state :=
  // the CoM state sent to the robot (its own + the correction it has not absorbed yet), the
  // filter running on. Not with reinitialize_wpg (std::invalid_argument).
  bool closed_loop = false;
  // The walking IK's frames and posture (the robot folder's `multibody:`; HRP-2's by default).
  WalkingIkSettings ik;
};

struct OnlineFilterRun {
  WalkResult walk;                  // the WPG's walk (its CoM re-initialised when so set)
  MultibodyValidation validation;   // filter_mode "online", per-tick timings
};

// The walk the loop runs around: whoever commands it (generateWalk's velocity schedule, or
// planning/'s walk to a goal, whose path follower gives the NMPC its command at every
// iteration), it is runWalkLoop (walk_loop.hpp) with `observer`, called with the parameters
// and the request given to runOnlineFilterLoop; returns the loop's result.
using ObservedWalk = std::function<WalkResult(ControlLoopObserver& observer)>;

// The loop around `walk` (see ObservedWalk). Throws std::invalid_argument on invalid parameters
// (and what `walk` throws for its own input), and std::runtime_error when the walk is too short
// to replay (fewer than 3 samples).
OnlineFilterRun runOnlineFilterLoop(const RobotModel& model, const WalkingParameters& parameters,
                                    const WalkRequest& request,
                                    const OnlineFilterLoopSettings& settings,
                                    const ObservedWalk& walk);

// The loop around generateWalk (the request's velocity schedule). Throws std::invalid_argument
// on invalid parameters or request (as generateWalk), and std::runtime_error when the walk is
// too short to replay (fewer than 3 samples).
OnlineFilterRun runOnlineFilterLoop(const RobotModel& model, const WalkingParameters& parameters,
                                    const WalkRequest& request,
                                    const OnlineFilterLoopSettings& settings,
                                    const ConstraintFamilies& extra_families = {});

}  // namespace wpg::robots
