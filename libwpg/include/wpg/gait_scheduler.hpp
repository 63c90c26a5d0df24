#pragma once
// The walking phase bookkeeping of the pattern generator: standing, the starting double
// support, the steps, the final side-by-side step, the phase time within a step, which foot
// supports and where the feet stand. It turns them into the PhaseStructure of one NMPC sample
// (which support each CoP sample uses, which previewed steps are fixed).
//
//  * A step lasts S = single + double support samples (8 x 0.1 s). The support foot of a
//    step owns the CoP samples at phase times 0 .. S-1; the swing foot lifts at phase time 0
//    and lands at S-1; the last period (S-1 -> S) is the double support in which the CoP
//    passes to the landed foot. NMPC samples thus never fall inside a double support
//    (paper Sec. III-C1), and at phase time S-1 the landed step is fixed in the problem.
//  * Standing: double support with the CoP kept in the hull of both feet. A non-zero
//    command starts walking: a double support of start_double_support_samples in which the
//    CoP samples may use both feet (the CoM must first move towards the first support foot,
//    which needs the CoP on the other side of it), then the first lift-off. A zero command is
//    followed by one free step to slow down, then a side-by-side step, then standing again
//    (zero_command: stop), or keeps the robot stepping in place (zero_command: step_in_place,
//    which also starts a standing robot).
//  * Pushed while standing (standing_push_response: step): when the capture point leaves the
//    standing double-support rectangle, the CoP can no longer stop the CoM (LIPM, eq. 3) and
//    the robot starts stepping after push_start_double_support_samples, the foot on the
//    capture point's side first, with a short first swing (push_step_swing_samples: the
//    capture point runs away from the CoP as e^(omega0 t), ~11x in a 0.7 s swing); with a zero
//    command it then stops again as above.
//  * Step timing (walking.step_timing: adaptive): the number of samples per step may change
//    at a landing, when the landed foot is fixed and the whole horizon lies in the steps to
//    come (requestStepSamples; wpg/step_timing.hpp chooses it). A standing robot takes the
//    parameters' own step (its start is the paper's).
#include <Eigen/Core>

#include "wpg/nmpc.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

inline FootSide otherSide(FootSide side) {
  return side == FootSide::kLeft ? FootSide::kRight : FootSide::kLeft;
}

// `local` (x, y, yaw) expressed in the frame of `base` (x, y, yaw), in the world frame.
Eigen::Vector3d composePose(const Eigen::Vector3d& base, const Eigen::Vector3d& local);

// Where a step of `side` would land from `previous` when following the robot-frame `command`
// for one step duration: an initial guess for the linearization only (the NMPC chooses it).
Eigen::Vector3d nominalStep(const WalkingParameters& parameters, const Eigen::Vector3d& previous,
                            FootSide side, const Eigen::Vector3d& command);

class GaitScheduler {
 public:
  explicit GaitScheduler(const WalkingParameters& parameters);

  // Standing with the ankles side by side (initial_foot_separation) about `pose` = (x, y, yaw)
  // of the point between them.
  void reset(const Eigen::Vector3d& pose);

  // What changed at the start of a sample.
  struct SampleStart {
    bool started = false;  // walking starts at this sample (the previewed steps need a guess)
    FootSide first_swing = FootSide::kLeft;  // when started: the foot that lifts first
    // The phase structure changed meaning (start, cancelled start, stop, reset): the rows
    // of the previous active set do not describe this sample's problem.
    bool structure_changed = false;
    // The steps from here on have another number of samples (stepSamples()): the NMPC of
    // this sample is another model's (structure_changed is set too).
    bool cadence_changed = false;
  };
  // Phase bookkeeping at the start of an NMPC sample for the clamped robot-frame command and
  // the CoM's capture point (x, y) c + c'/omega0 at that instant (world frame).
  SampleStart beginSample(const Eigen::Vector3d& command, const Eigen::Vector2d& capture_point);

  // The capture point is outside the rectangle in which a standing robot keeps its CoP (the
  // hull of both margin-reduced soles, as fillPhase gives it to the NMPC).
  bool outsideStandingSupport(const Eigen::Vector2d& capture_point) const;

  // At a landing (atSwingLanding()): the capture point's distance from the landed foot's ankle
  // along that foot's lateral axis, positive towards the foot that lifts next [m]. The CoP can
  // hold the capture point only up to copHalfWidth() on that side; beyond, it runs away from
  // the landed sole as e^(omega0 t) (eq. 3) until the lifting foot lands under it.
  double captureOffsetTowardsLiftingFoot(const Eigen::Vector2d& capture_point) const;

  // The phase structure of the current sample (and its CoP rows' steps, from the model).
  void fillPhase(const NmpcModel& model, PhaseStructure& phase) const;

  struct SampleEnd {
    bool landed = false;          // the swing foot landed at the end of the period
    bool step_completed = false;  // the landed foot became the support: steps move up one
  };
  // Ends the sampling period. `planned_landing` is the first previewed step of the solution
  // (where a landing swing foot is put); `end_time` the time at the end of the period.
  SampleEnd endSample(const Eigen::Vector3d& planned_landing, double end_time);

  // Steps of `samples` samples (single + double support) from the next landing on (at once
  // when standing: then the parameters' own, as a start expects). Applied by beginSample.
  void requestStepSamples(int samples) { requested_samples_ = samples; }
  int stepSamples() const { return samples_per_step_; }  // S of the current step
  // This sample is a step boundary: the swing foot has landed (or a start's first support foot
  // stands), the steps to come are all free of the current one.
  bool atLanding() const {
    return !standing_ && start_remaining_ == 0 && phase_sample_ == samples_per_step_ - 1;
  }

  // atLanding() after the swing foot landed (not the end of a start, where no foot did).
  bool atSwingLanding() const { return atLanding() && swing_landed_; }

  bool standing() const { return standing_; }
  bool starting() const { return start_remaining_ > 0; }
  // The swing foot is in the air during the period that starts at this sample.
  bool swinging() const {
    return !standing_ && start_remaining_ == 0 && phase_sample_ <= samples_per_step_ - 2;
  }
  SupportState supportState() const;
  FootSide supportSide() const { return support_side_; }
  int phaseSample() const { return phase_sample_; }
  // Phase time at which the current step's swing foot lifted off: 0, or later for the short
  // first swing of a push start (S - 1 - push_step_swing_samples).
  int liftOffSample() const { return lift_off_sample_; }
  // Pose (x, y, yaw) on the ground; for the swing foot, its lift-off pose.
  const Eigen::Vector3d& footPose(FootSide side) const {
    return side == FootSide::kLeft ? left_ : right_;
  }
  // The free-flyer yaw of the feet on the ground: the mean of their yaws [rad].
  double feetMeanYaw() const { return 0.5 * (left_.z() + right_.z()); }
  const Footstep& lastLanding() const { return last_landing_; }

 private:
  Eigen::Vector3d& foot(FootSide side) { return side == FootSide::kLeft ? left_ : right_; }
  struct StandingRectangle {
    Eigen::Vector3d centre;  // the point between the ankles (x, y, yaw)
    double half_length, half_width;
  };
  StandingRectangle standingRectangle() const;
  void setDoubleSupport(PhaseStructure& phase) const;

  WalkingParameters parameters_;
  int samples_per_step_ = 0;  // S of the current step
  int requested_samples_ = 0;  // S of the steps from the next landing on
  Eigen::Vector3d left_ = Eigen::Vector3d::Zero(), right_ = Eigen::Vector3d::Zero();
  Footstep last_landing_;
  bool standing_ = true;
  FootSide support_side_ = FootSide::kRight;
  int phase_sample_ = 0;        // 0 .. S-1 within the current step
  int start_remaining_ = 0;     // > 0: starting double support, samples left before S-1
  int zero_command_steps_ = 0;  // consecutive step starts with a zero command
  bool stop_step_ = false;      // the current swing is the final side-by-side step
  bool push_start_ = false;     // the current start was triggered by a push, not a command
  bool short_first_swing_ = false;  // the next swing is a push start's short one
  int lift_off_sample_ = 0;     // phase time at which the current step's swing lifted off
  bool swing_landed_ = false;   // the swing foot of the current step has landed
  bool structure_changed_ = false;
};

}  // namespace wpg
