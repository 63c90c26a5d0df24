#pragma once
// Constant description of a walking robot for the pattern generator: timings, template-model
// constants, foot geometry, step feasibility, cost weights. Defaults are HRP-2's, from the
// paper (Naveau et al., RA-L 2017, Sec. V) and the authors' code; robots/<name>/walking.yaml
// restates them and scenarios may override any field (datasets/SCENARIOS.md). Six defaults
// differ from the paper's text, on measurement (docs/formulation.md,
// docs/command_tracking.md, docs/obstacle_passing.md): velocity_tracking, heading_reference,
// weight_yaw, max_step_yaw_change (the authors' code's value), obstacle_distance_form and
// obstacle_linearization.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/walk_trajectory.hpp"

namespace wpg {

// The heading that the velocity command is expressed in (J1) and that the step yaws track (J2).
enum class HeadingReference {
  // The paper (eq. 8's p^theta and the authors' code): J2 asks each previewed step to turn by
  // T_step * omega from the current support foot's yaw, and J1 turns the command by the feet's
  // yaw. Whatever yaw the robot takes (pushed aside by an obstacle, or by the yaw bound) becomes
  // its new heading: after going round an obstacle it walks on in whatever direction it faces.
  kSupportFoot,
  // The command's own heading: the robot's yaw when the walk started plus the integral of the
  // commanded omega. J2 tracks it and J1 turns the command by it, so a robot that had to turn
  // returns to the commanded heading (wpg; the default: straight walks, tracked turns, going
  // round obstacles on the path).
  kCommand,
};
// Parses "support_foot" / "command"; returns false on anything else.
bool parseHeadingReference(const std::string& name, HeadingReference* out);
const char* headingReferenceName(HeadingReference reference);

// What J1 (eq. 5's linear velocity tracking) compares with the command at each previewed
// sample (docs/command_tracking.md).
enum class VelocityTracking {
  // The paper's J1 as written: the instantaneous CoM velocity C'_{k+1} of every sample
  // against the command. The CoM's sway from foot to foot is charged as a tracking error, and
  // walking sideways needs alternating wide and narrow steps, whose sway costs more than the
  // missing velocity: the robot hardly walks sideways (5 % of 0.1 m/s).
  kInstantaneous,
  // The mean of the velocity over the velocity_window_samples samples ending at each sample
  // (the walked ones from the history), and of the command over the same samples, in the
  // robot's frame (wpg's earlier option for obstacles).
  kWindow,
  // wpg default: the velocity of kWindow (velocity_window_samples = 1: the paper's
  // instantaneous velocity) against a command whose lateral (robot-frame y) part also holds
  // the sway the robot walked at the same phase one gait cycle (two steps) earlier: the sway
  // from foot to foot, that walking sideways needs, is not charged; the mean velocity over the
  // cycle is, and so is any change from the last cycle's sway (a push).
  kWithSway,
};
bool parseVelocityTracking(const std::string& name, VelocityTracking* out);
const char* velocityTrackingName(VelocityTracking tracking);

// What the gait does with a zero velocity command.
enum class ZeroCommandGait {
  // Slow down with one free step, put the feet side by side with a final step, then stand
  // (the authors' code). A standing robot with a zero command stays standing.
  kStop,
  // Step in place: the steps go on at the gait's pace with the feet where the NMPC puts them
  // (the paper's on-the-spot pushes, Sec. V-B, are applied to a robot stepping in place). A
  // standing robot with a zero command starts stepping.
  kStepInPlace,
};
bool parseZeroCommandGait(const std::string& name, ZeroCommandGait* out);  // stop / step_in_place
const char* zeroCommandGaitName(ZeroCommandGait gait);

// What a standing robot does when a perturbation carries its capture point c + c'/omega0 out of
// the region its CoP can reach (the double-support rectangle of the standing NMPC): with the
// CoP alone it cannot stop the CoM any more (LIPM, eq. 3), only a step can.
enum class StandingPushResponse {
  kStep,   // start stepping at once (push_start_double_support_samples), then stop again
  kStand,  // keep standing: the CoP constraints alone (a large enough push makes it fall)
};
bool parseStandingPushResponse(const std::string& name, StandingPushResponse* out);  // step / stand
const char* standingPushResponseName(StandingPushResponse response);

// The bound the obstacle rows (eq. 18-19, nmpc/obstacle_constraint.cpp) put on a step centre f
// for an obstacle of radius R and security margin m.
enum class ObstacleDistanceForm {
  // wpg default: the step centre stays m + obstacle_foot_radius beyond the obstacle, for a
  // circle |f - c| >= R + m + obstacle_foot_radius, i.e. (f - c)^2 >= (R + m + r_sole)^2: the
  // whole sole stays out of the margin circle (radius R + m) of the paper's Fig. 8.
  kSoleClearance,
  // The paper's eq. (18) as written: (f - c)^2 >= R^2 + m^2, the step a point
  // (obstacle_foot_radius unused). Its circle, radius sqrt(R^2 + m^2), is smaller than R + m:
  // the step centre may land inside the margin circle, the sole further in. The paper has only
  // circles; for boxes and polygons this form keeps the point step m from the shape.
  kPaper,
};
// Parses "sole_clearance" / "paper"; returns false on anything else.
bool parseObstacleDistanceForm(const std::string& name, ObstacleDistanceForm* out);
const char* obstacleDistanceFormName(ObstacleDistanceForm form);

// Which half-plane stands for a circle obstacle's row (eq. 18-19) in the QP. Both are inner
// approximations of eq. (18): a step in the half-plane is outside the grown circle.
enum class ObstacleLinearization {
  // The paper (Sec. III-E, eq. 21-22): eq. (18) linearized by the solver at the previewed step
  // of the previous plan, a half-plane facing that step. With an obstacle on the path its
  // border is perpendicular to the command and the robot marks time in front of it.
  kStep,
  // wpg: for every obstacle in the QP (circle, box or polygon, alone or with others), a
  // supporting half-plane of the obstacle grown by its margin, turned as far towards the
  // command's direction as the robot's CoM (and the way round the obstacle before it) allows,
  // on the side the robot passes, and J1's reference turned along the borders
  // (libwpg/include/wpg/obstacle_tangent.hpp). Fixed during a sample (exact Jacobian: constant).
  // With heading_reference: command and a large weight_yaw the robot slides round an obstacle on
  // the path and walks on (paper_experiment_a); with the support-foot heading it turns while it
  // slides and circles the obstacle. The default (docs/obstacle_passing.md,
  // docs/obstacle_scenes.md).
  kCommandTangent,
};
bool parseObstacleLinearization(const std::string& name, ObstacleLinearization* out);
const char* obstacleLinearizationName(ObstacleLinearization linearization);

// How long the steps last (docs/command_tracking.md, "Step timing").
enum class StepTiming {
  // The paper's fixed timing (Sec. V-A): every step single_support_samples + 1 samples
  // (0.7 s single + 0.1 s double support for HRP-2).
  kFixed,
  // wpg default: at each landing the gait takes the slowest single support, from
  // single_support_samples down to min_single_support_samples, whose regular two-step gait
  // reaches the command inside the step feasibility polygon (wpg/gait_reach.hpp); the
  // paper's timing for every command it can walk, shorter steps beyond (HRP-2: 0.125 m/s
  // sideways at 0.8 s steps, 0.2 m/s at 0.5 s).
  kAdaptive,
};
bool parseStepTiming(const std::string& name, StepTiming* out);  // fixed / adaptive
const char* stepTimingName(StepTiming timing);

// The adaptive step timing builds one NMPC per cadence: at most this many (the slowest).
constexpr int kMaxCadences = 8;

struct WalkingParameters {
  // --- template model (Sec. II) -------------------------------------------------------------
  double com_height = 0.814;           // h [m], CoM height above the ground, eq. (3)
  double gravity = 9.81;               // g [m/s^2]
  // --- MPC timing (Sec. V-A) ----------------------------------------------------------------
  double sampling_period = 0.1;        // T [s], NMPC sample; also the double-support duration
  int horizon_length = 16;             // N samples (1.6 s = two steps)
  int single_support_samples = 7;      // 0.7 s single support per step
  int double_support_samples = 1;      // 0.1 s double support per step
  int previewed_steps = 2;             // nf, free footsteps in the horizon
  // Step timing (see the enum): adaptive by default, a departure from the paper; `fixed` is
  // the paper's. With adaptive timing the single support of a step may be any number of
  // samples from single_support_samples (the paper's, for every command it reaches) down to
  // min_single_support_samples, and the horizon is previewed_steps such steps.
  StepTiming step_timing = StepTiming::kAdaptive;
  int min_single_support_samples = 4;  // 0.4 s: 0.5 s steps (HRP-2's swing peaks 1.9 m/s)
  // With adaptive timing, a push across the gait: at a landing where the capture point lies
  // further than push_step_capture_offset from the landed foot's ankle towards the foot about
  // to lift (the side it must step to; regular walking lands with 40-68 mm) and has jumped by
  // more than push_step_capture_jump since the previous landing (a push is sudden; a closed
  // filter loop drifts there by at most 7.3 mm a landing), the next step's single support is
  // push_step_single_support_samples, so that this foot lands before the capture point runs
  // away (e^(omega0 t), eq. 3). push_step_capture_offset 0 = off.
  double push_step_capture_offset = 0.075;  // [m]
  double push_step_capture_jump = 0.02;     // [m]
  int push_step_single_support_samples = 5;  // 0.5 s, in [min_single_support_samples, single]
  // Double support before the first lift-off when starting from standing: the CoP may use
  // both feet while the CoM moves over the first support foot (at most one step's samples).
  int start_double_support_samples = 8;
  ZeroCommandGait zero_command = ZeroCommandGait::kStop;
  StandingPushResponse standing_push_response = StandingPushResponse::kStep;
  // Double support before the first lift-off when a push starts the steps of a standing robot
  // (standing_push_response: step): short, because the capture point diverges from the
  // support as e^(omega0 t) (a full start_double_support_samples would let it run away).
  int push_start_double_support_samples = 2;
  // Swing duration (samples) of the first step after a push start: shorter than a regular
  // step's single support, so that the foot lands before the capture point has run away.
  int push_step_swing_samples = 3;
  double control_period = 0.005;       // [s], interpolation (robot control) period
  // --- feet (Fig. 4) ------------------------------------------------------------------------
  double foot_length = 0.2172;         // sole length along the foot x axis [m], ankle centred
  double foot_width = 0.138;           // sole width [m]
  double ankle_height = 0.105;         // ankle above the sole [m]
  double cop_margin_x = 0.09;          // security margin removed from each end of the sole [m]
  double cop_margin_y = 0.05;          // security margin removed from each side of the sole [m]
  double initial_foot_separation = 0.19;  // ankle-to-ankle distance when standing [m]
  double stop_foot_separation = 0.20;     // lateral distance of the final side-by-side step [m]
  // Obstacle constraint (eq. 18-19) on the step centre grown by this radius, so that the whole
  // sole stays out of the obstacle's margin: the sole's half diagonal for HRP-2. The paper
  // treats steps as points (0). Used by the sole_clearance form only.
  double obstacle_foot_radius = 0.1287;   // [m]
  // Which bound the obstacle rows enforce: sole_clearance (wpg) or the paper's eq. (18) as
  // written (see ObstacleDistanceForm).
  ObstacleDistanceForm obstacle_distance_form = ObstacleDistanceForm::kSoleClearance;
  // How the obstacle rows are linearized (see the enum), for every shape.
  ObstacleLinearization obstacle_linearization = ObstacleLinearization::kCommandTangent;
  // With obstacle_linearization command_tangent: the row of the foot in the air. kStep
  // (default): while the capture point predicted at touchdown lies beyond a border, the
  // half-plane of the same shape that faces the landing planned at the previous sample, the
  // paper's linearization, so that the step catching a push may land beyond the slanted
  // border, where the obstacle is not (PatternGenerator::placeObstacles,
  // ObstacleSelector::landingRows; docs/obstacle_scenes.md, "Pushes while avoiding");
  // kCommandTangent: the border, as the later steps.
  ObstacleLinearization obstacle_landing_linearization = ObstacleLinearization::kStep;
  // --- step feasibility polygon for a LEFT step, in the right (support) foot frame (Fig. 5);
  //     a right step uses the mirror image (y -> -y). Counter-clockwise order not required.
  std::array<double, 5> feasibility_x{-0.28, -0.2, 0.0, 0.2, 0.28};  // [m]
  std::array<double, 5> feasibility_y{0.2, 0.3, 0.4, 0.3, 0.2};      // [m]
  // --- orientation, eq. (16): |yaw(step) - yaw(previous step)| <= bound. The authors' code's
  //     0.17 rad: the reference clamp max_angular_velocity (0.2 rad/s, the paper's experiment
  //     B) needs 0.2 * stepDuration() = 0.16 rad per step. The paper's text states 0.05 rad
  //     (Sec. III-C), which caps turning at 0.0625 rad/s (docs/formulation.md, "The yaw
  //     bound"); max_angular_velocity = 0.0625 makes the clamp agree with it.
  double max_step_yaw_change = 0.17;   // [rad]
  // --- swing-foot landing bound (Sec. III-C3, last paragraph; landing_bound and landing_yaw_bound
  //     families): while a
  //     foot swings, its landing may move from the one planned at the previous sample by at
  //     most what the foot can travel at this speed in the time left before touchdown. Values
  //     of the authors' code (jrl-umi3218/jrl-walkgen, src/ZMPRefTrajectoryGeneration/
  //     nmpc_generator.cpp, updateFootVelIneqConstraint: xvmax = yvmax = 0.4 m/s,
  //     yawvmax = 1.5 rad/s). 0 switches the bound off (x and y, or yaw). Off by default: with
  //     the authors' values on HRP-2's `push` the swing foot's peak acceleration rises (18 ->
  //     30 m/s^2, the correction is pushed to the last sample) and a push at 3.9 s that is
  //     rejected without the bound makes the robot fall (docs/formulation.md).
  double max_landing_speed = 0.0;      // [m/s]
  double max_landing_yaw_rate = 0.0;   // [rad/s]
  // --- swing-foot reach (wpg; swing_reach family, wpg/swing_foot_reach.hpp): while a foot
  //     swings, its landing stays where the foot's re-planned quintic reaches it with the
  //     ankle's speed and acceleration within these limits. 0 switches a limit off (both 0: no
  //     rows, the paper's formulation). Without them a push late in the swing is recovered by
  //     a swing foot at up to 8 m/s and 250 m/s^2 (docs/formulation.md, "Swing-foot reach").
  double max_swing_speed = 0.0;         // [m/s]
  double max_swing_acceleration = 0.0;  // [m/s^2]
  // --- cost weights, eq. (5) and Sec. V-D ----------------------------------------------------
  double weight_velocity = 2.5;        // alpha: linear velocity tracking (J1)
  // What J1 tracks (see the enum); kInstantaneous is the paper's eq. (5).
  VelocityTracking velocity_tracking = VelocityTracking::kWithSway;
  // Samples of J1's mean (kWindow, kWithSway; the current one and those before it, walked
  // samples from the walk's history). 1 by default: the paper's instantaneous velocity. Longer
  // windows track the forward speed closer (95 % with 4, 99 % with 8, 93 % with 1) but
  // charge a push's velocity for longer (docs/command_tracking.md has the measurements).
  int velocity_window_samples = 1;
  // J1 frame and J2 target. kCommand by default (wpg): with the paper's kSupportFoot any yaw a
  // step takes becomes the next step's reference, so a straight walk drifts sideways and a
  // curve falls behind omega (docs/formulation.md, "Straight walks and turning").
  HeadingReference heading_reference = HeadingReference::kCommand;
  // Weight of the angular tracking J2. The paper uses alpha = 2.5 for both (Sec. III-B: "a
  // different weight ... was not necessary"); with it the optimum of (5) yaws the feet towards
  // the yaw bound on straight walks (rotating a foot rotates the next step's feasibility
  // polygon, eq. 14, and lets the feet come closer), 0.05 rad every other foot with the
  // paper's bound, up to 0.13 rad with 0.17. 100 keeps the toe-out below 0.005 rad and the
  // walk straight (measured in docs/formulation.md); 2.5 is the paper's.
  double weight_yaw = 100.0;
  double weight_cop = 1e3;             // beta: CoP close to the support ankle (J3)
  double weight_jerk = 1e-5;           // gamma: jerk regularization (J4)
  // --- swing foot -------------------------------------------------------------------------
  double step_height = 0.05;           // apex height of the swing foot sole [m]
  // --- reference clamp (authors' code), applied to the command before the NMPC -------------
  double max_forward_velocity = 0.4;   // |vx| [m/s]
  double max_lateral_velocity = 0.3;   // |vy| [m/s]
  double max_angular_velocity = 0.2;   // |omega| [rad/s]

  int stepSamples() const { return single_support_samples + double_support_samples; }
  // The parameters of the gait with `single_support` samples of single support (a cadence of
  // the adaptive step timing): horizon previewed_steps steps, and the start, push-start and
  // window lengths clamped to the shorter step. Itself for single_support_samples.
  WalkingParameters withSingleSupport(int single_support) const;
  // The single supports the gait may take, slowest first: single_support_samples only with
  // fixed timing, else down to min_single_support_samples (at most kMaxCadences of them).
  int cadenceCount() const {
    if (step_timing == StepTiming::kFixed) return 1;
    const int count = single_support_samples - min_single_support_samples + 1;
    return count < kMaxCadences ? count : kMaxCadences;
  }
  int cadenceSingleSupport(int cadence) const { return single_support_samples - cadence; }
  // Samples of J1's mean: 1 with the paper's instantaneous velocity.
  int trackedVelocityWindow() const {
    return velocity_tracking == VelocityTracking::kInstantaneous ? 1 : velocity_window_samples;
  }
  double stepDuration() const { return stepSamples() * sampling_period; }
  double copHalfLength() const { return 0.5 * foot_length - cop_margin_x; }
  double copHalfWidth() const { return 0.5 * foot_width - cop_margin_y; }

  // Feasibility polygon vertices for a step of `side`, in the previous (support) foot frame.
  std::vector<Eigen::Vector2d> feasibilityVertices(FootSide side) const;
  // The fastest the gait walks sideways on average [m/s]: over a gait cycle (two steps) the
  // outward step reaches the polygon's widest lateral offset, the inward one comes back to its
  // narrowest (0.4 - 0.2 m in 1.6 s: 0.125 m/s for HRP-2).
  double gaitSidewaysSpeed() const;
  // [m] The least distance across its heading between two consecutive feet of the walk the
  // generator plans: its feet face the heading (J2 keeps them along it), so a step lands at
  // least the feasibility polygon's nearest vertex across, min |y| (eq. 14: 0.2 m for HRP-2,
  // its minimal step width). Feet toed in and out in turn by half the yaw bound (eq. 16) could
  // come min |y| cos(a) - |x| sin(a) close (0.1755 m for HRP-2), but the NMPC plans no such
  // gait. A gap narrower than this between two obstacles grown by their step-centre margins
  // lets none of its walks through (ObstacleSelector's groups; docs/obstacle_scenes.md).
  double leastStepWidth() const;

  // Throws std::invalid_argument naming the first bad field and what was expected.
  void validate() const;
};

}  // namespace wpg
