#pragma once
// The reactive walking pattern generator's controller (Fig. 3, "WPG" block): once per NMPC
// sample it turns a velocity command into the next sampling period's CoM jerk and swing-foot
// target. It ties together
//   GaitScheduler     (gait_scheduler.hpp)    the walking phase -> PhaseStructure,
//   ReferenceBuilder  (reference_builder.hpp) the J1 / J2 references,
//   ObstacleSelector  (obstacle_selector.hpp) the obstacles that enter the QP,
// the NMPC (or LMPC) solve, and the shift of the plan to the next sample (warm start).
// OnlineWalkingGenerator (online_walking_generator.hpp) adds the control-period
// interpolation of the CoM and the feet on top of it.
//
// Step timing (walking.step_timing: adaptive, wpg/step_timing.hpp): the NMPC's horizon is
// previewed_steps steps, so each cadence (single support) the gait may take has its own model,
// solver and problem, all built here; at a landing where the cadence changes the plan is handed
// over (the same steps, the jerks of the common samples) and the new solver starts without a
// warm-start active set. Nothing is allocated when the cadence changes.
#include <limits>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "wpg/gait_scheduler.hpp"
#include "wpg/nmpc.hpp"
#include "wpg/nmpc_plan.hpp"
#include "wpg/obstacle_selector.hpp"
#include "wpg/reference_builder.hpp"
#include "wpg/step_timing.hpp"
#include "wpg/swing_foot_trajectory.hpp"

namespace wpg {

using ConstraintFamilies = std::vector<std::shared_ptr<const ConstraintFamily>>;

class PatternGenerator {
 public:
  // `extra_families`: constraint families added after the paper's ones
  // (NmpcModel::addConstraintFamily), e.g. a new bound of the problem.
  PatternGenerator(const WalkingParameters& parameters, const GeneratorSettings& settings,
                   const ConstraintFamilies& extra_families = {});
  // Its solver is bound to its own model: a copy would solve with the original's.
  PatternGenerator(const PatternGenerator&) = delete;
  PatternGenerator& operator=(const PatternGenerator&) = delete;

  // Obstacles to avoid (eq. 18-19), taken by value, owned and validated (ObstacleSelector::set:
  // throws std::invalid_argument). Their distances are libwpg's exact 2-D ones (ObstacleSet).
  // May be called between samples; the next sample then starts without a warm-start active
  // set. Allocates.
  void setObstacles(std::vector<Obstacle> obstacles);
  const std::vector<Obstacle>& obstacles() const { return obstacles_.obstacles(); }
  // The obstacles with the distances the constraints use; null without obstacles.
  const ObstacleSet* obstacleDistance() const { return obstacles_.distance(); }

  // Standing with the ankles side by side (initial_foot_separation) about `pose` = (x, y, yaw)
  // of the point between them; CoM at rest above it at com_height.
  void reset(const Eigen::Vector3d& pose = Eigen::Vector3d::Zero());

  // Solves the problem of the sample at `time` for a robot-frame command [vx, vy, omega]
  // (clamped to the robot's limits). Does not allocate once warmed up.
  // `swing`: the swing foot's trajectory in force when a foot already swings (its state at
  // `time` bounds the landing: swing_reach family, wpg/swing_foot_reach.hpp); null at the
  // first sample of a swing, whose foot is at rest on the ground.
  const MpcIterationLog& update(double time, const Eigen::Vector3d& command,
                                const SwingFootTrajectory* swing = nullptr);

  // What to execute during the sampling period that starts at the last update().
  struct SamplePlan {
    double jerk_x = 0.0, jerk_y = 0.0;  // [m/s^3], first jerks of the solution
    SupportState support = SupportState::kDouble;
    bool swinging = false;
    FootSide swing_side = FootSide::kLeft;
    Eigen::Vector3d swing_target = Eigen::Vector3d::Zero();  // planned landing (x, y, yaw)
    double landing_time = 0.0;  // [s]
    double lift_off_time = 0.0;  // [s]
  };
  const SamplePlan& plan() const { return plan_; }

  // What the last update() predicts over its whole horizon (nmpc_plan.hpp), from the CoM
  // state it solved from: valid until advance() shifts the plan. Sizes `out` when it holds
  // fewer than maxPreviewSamples() samples or another count of steps or families (allocates);
  // else does not allocate. Costs nothing unless called (plan_preview.cpp).
  void previewPlan(NmpcPlan& out) const;
  // The longest horizon of the cadences (the parameters' own, the slowest steps).
  int maxPreviewSamples() const;

  // Ends the sampling period: the caller integrated the CoM (possibly pushed) and passes the
  // state at its end. Returns true when a foot landed at the end of the period (lastLanding()).
  bool advance(const Eigen::Vector3d& com_x, const Eigen::Vector3d& com_y);
  const Footstep& lastLanding() const { return gait_.lastLanding(); }

  const Eigen::Vector3d& comX() const { return com_x_; }
  const Eigen::Vector3d& comY() const { return com_y_; }
  // Replaces the CoM state (position, velocity, acceleration per axis) the next update()
  // starts from: the re-initialisation of the WPG by the dynamic filter (paper Fig. 3).
  void setComState(const Eigen::Vector3d& com_x, const Eigen::Vector3d& com_y) {
    com_x_ = com_x;
    com_y_ = com_y;
  }
  // Step `step` (0 = the landing of the current swing) of the plan in force: x, y, yaw.
  Eigen::Vector3d plannedStep(int step) const;
  const Eigen::Vector3d& footPose(FootSide side) const {  // on the ground (swing: lift-off pose)
    return gait_.footPose(side);
  }
  bool standing() const { return gait_.standing(); }
  double commandedHeading() const { return references_.commandedHeading(); }
  // The command of the last update(), clamped to the robot's limits, and the heading it was
  // turned into the world by (J1's frame at that sample: the commanded heading, or the feet's
  // mean yaw with heading_reference: support_foot): what the walk is asked to progress along
  // (progress_monitor.hpp).
  const Eigen::Vector3d& clampedCommand() const { return command_; }
  double commandFrameHeading() const { return references_.commandFrameHeading(); }
  bool starting() const { return gait_.starting(); }
  int phaseSample() const { return gait_.phaseSample(); }
  const GaitScheduler& gait() const { return gait_; }
  // The parameters given (the slowest cadence's); model().parameters() are those of the
  // cadence in force.
  const WalkingParameters& parameters() const { return cadences_.front()->model.parameters(); }
  // The NMPC of the cadence in force (the parameters' own unless the adaptive step timing
  // walks shorter steps: model().parameters().single_support_samples).
  const NmpcModel& model() const { return *model_; }
  const NmpcProblem& problem() const { return *problem_; }
  const NmpcSolver& solver() const { return *solver_; }
  int cadence() const { return active_; }  // 0: the parameters' single support
  const NmpcSolveResult& lastSolve() const { return last_solve_; }
  Eigen::Vector3d clampCommand(const Eigen::Vector3d& command) const;

 private:
  // At a landing, the cadence of the next step for the capture point's offset towards the
  // foot about to lift and that of the previous landing (NaN: none): 0 (no change) unless a
  // push has carried it past push_step_capture_offset, by a jump.
  int pushStepCadence(double capture_offset, double previous_offset) const;
  // --- update(), one concern each ----------------------------------------------------------
  // The command clamped, how long it has been held, the heading integrated up to `time`.
  Eigen::Vector3d takeCommand(double time, const Eigen::Vector3d& raw_command);
  // The cadence the steps from the next landing on should have (step timing, push steps).
  int wantedCadence(const Eigen::Vector3d& command, const Eigen::Vector2d& capture_point);
  // The gait's phase at this sample: the cadence switched, the plan seeded or its warm start
  // dropped as the phase asks.
  GaitScheduler::SampleStart beginSample(const Eigen::Vector3d& command);
  // The problem's phase, J1's references, the CoM state, the landing and swing-reach bounds.
  void fillProblem(double time, const Eigen::Vector3d& command,
                   const GaitScheduler::SampleStart& phase_start,
                   const SwingFootTrajectory* swing);
  // The obstacles of the QP (the nearest, in their slots) and the command_tangent borders.
  void placeObstacles(const Eigen::Vector3d& command);
  // --- the NMPC's plan and its warm start, owned by the solver: the only code that touches
  //     them ---------------------------------------------------------------------------------
  void seedStep(int step, const Eigen::Vector3d& pose);
  void seedPlanFromStanding(const Eigen::Vector3d& command, FootSide first_swing);
  void dropWarmStart();
  void clearPlan();
  void solve();
  void readPlan(double time);
  void shiftPlan(bool step_completed);
  void boundSwingReach(double time, const SwingFootTrajectory* swing);
  void switchCadence(int cadence);
  // ------------------------------------------------------------------------------------------

  // One NMPC per cadence (heap-allocated once: the solver is bound to its model's address).
  struct Cadence {
    Cadence(const WalkingParameters& parameters, const GeneratorSettings& settings,
            const ConstraintFamilies& extra_families, qp::HessianFactorCache& hessian_factors);
    NmpcModel model;
    NmpcSolver solver;
    NmpcProblem problem;
    // CoM velocities at the horizon's samples predicted by the warm start (J1's window)
    Eigen::VectorXd planned_velocity_x, planned_velocity_y;
  };
  std::vector<std::unique_ptr<Cadence>> cadences_;  // [c]: cadenceSingleSupport(c)
  int active_ = 0;
  // The cadence in force's.
  NmpcModel* model_ = nullptr;
  NmpcSolver* solver_ = nullptr;
  NmpcProblem* problem_ = nullptr;
  GeneratorSettings settings_;
  // The cadences' factors: settings_.hessian_factors, or this generator's own cache.
  std::shared_ptr<qp::HessianFactorCache> hessian_factors_;
  GaitScheduler gait_;
  ReferenceBuilder references_;
  CadenceChoice cadence_choice_;
  double omega0_ = 0.0;  // sqrt(g / h) of the LIPM (eq. 3), for the capture point
  // The capture point's offset towards the lifting foot at the previous swing landing (NaN
  // before the first of a walk), for the push step's jump.
  double previous_capture_offset_ = std::numeric_limits<double>::quiet_NaN();
  ObstacleSelector obstacles_;
  // How far inside each border of the sample the CoM is [m] (turnReferenceAlongBorders).
  Eigen::VectorXd border_room_;
  SamplePlan plan_;
  MpcIterationLog log_;
  NmpcSolveResult last_solve_;

  Eigen::Vector3d com_x_ = Eigen::Vector3d::Zero(), com_y_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d command_ = Eigen::Vector3d::Zero();  // the clamped command of time_
  int held_samples_ = 0;  // samples before time_'s with the same command
  double time_ = 0.0;
  bool obstacles_changed_ = false;
};

}  // namespace wpg
