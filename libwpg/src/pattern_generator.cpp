#include "wpg/pattern_generator.hpp"

#include <algorithm>
#include <stdexcept>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "wpg/obstacle_tangent.hpp"
#include "wpg/nmpc/builtin_families.hpp"
#include "wpg/nmpc/extension_registry.hpp"
#include "wpg/swing_foot_reach.hpp"

namespace wpg {

namespace {

NmpcModel makeModel(const WalkingParameters& parameters, const GeneratorSettings& settings,
                    const ConstraintFamilies& extra_families,
                    qp::HessianFactorCache& hessian_factors) {
  // The LMPC baseline fixes the step yaws in its own orientation QP before the position QP
  // (Herdt et al. 2010), so a cost term on the steps would act on their positions alone: a
  // look-at point then drags the feet sideways instead of turning them.
  if (settings.algorithm == GeneratorAlgorithm::kLmpc && !settings.costs.empty()) {
    throw std::invalid_argument("GeneratorSettings::costs: expected none with the lmpc "
                                "algorithm (its step yaws are fixed before the position QP)");
  }
  NmpcModel model(parameters, settings.max_obstacles_in_qp, &hessian_factors);
  for (const auto& family : extra_families) model.addConstraintFamily(family);
  // The registered extensions the settings name (extension_registry.hpp), for each cadence's
  // parameters; walks start at the origin (reset()'s default; a checked start elsewhere is the
  // caller's: checkConstraintFamily / checkCostTerm).
  ExtensionContext context;
  context.walking = parameters;
  for (const ExtensionUse& use : settings.constraints)
    model.addConstraintFamily(makeConstraintFamily(use, context));
  for (const ExtensionUse& use : settings.costs) model.addCostTerm(makeCostTerm(use, context));
  return model;
}

// The CoM's clearance from a new command_tangent border: 1.5 side-by-side step widths (0.3 m
// for HRP-2), so that the inner foot, a half width beside the CoM, still has a step's length of
// room along the command (measured on paper_experiment_a: 0.1 and 0.2 m block the robot earlier;
// docs/formulation.md, "Obstacles on the path").
double tangentClearance(const WalkingParameters& w) { return 1.5 * w.stop_foot_separation; }

}  // namespace

PatternGenerator::Cadence::Cadence(const WalkingParameters& parameters,
                                   const GeneratorSettings& settings,
                                   const ConstraintFamilies& extra_families,
                                   qp::HessianFactorCache& hessian_factors)
    : model(makeModel(parameters, settings, extra_families, hessian_factors)),
      solver(model),
      problem(model.makeProblem()),
      planned_velocity_x(Eigen::VectorXd::Zero(parameters.horizon_length)),
      planned_velocity_y(Eigen::VectorXd::Zero(parameters.horizon_length)) {}

PatternGenerator::PatternGenerator(const WalkingParameters& parameters,
                                   const GeneratorSettings& settings,
                                   const ConstraintFamilies& extra_families)
    : settings_(settings),
      hessian_factors_(settings.hessian_factors
                           ? settings.hessian_factors
                           : std::make_shared<qp::HessianFactorCache>()),
      gait_(parameters),
      references_(parameters),
      cadence_choice_(parameters),
      omega0_(std::sqrt(parameters.gravity / parameters.com_height)) {
  for (int c = 0; c < parameters.cadenceCount(); ++c) {
    cadences_.push_back(std::make_unique<Cadence>(
        c == 0 ? parameters : parameters.withSingleSupport(parameters.cadenceSingleSupport(c)),
        settings, extra_families, *hessian_factors_));
  }
  border_room_.setZero(cadences_.front()->problem.obstacle_offset.size());
  reset();
}

void PatternGenerator::setObstacles(std::vector<Obstacle> obstacles) {
  obstacles_.set(std::move(obstacles));
  for (auto& cadence : cadences_) cadence->problem.obstacle_slot.setConstant(-1);
  obstacles_changed_ = true;
}

void PatternGenerator::reset(const Eigen::Vector3d& pose) {
  active_ = 0;
  model_ = &cadences_[0]->model;
  solver_ = &cadences_[0]->solver;
  problem_ = &cadences_[0]->problem;
  for (auto& cadence : cadences_) cadence->solver.clearActiveSet();
  gait_.reset(pose);
  previous_capture_offset_ = std::numeric_limits<double>::quiet_NaN();
  references_.setCadence(model_->parameters());
  references_.reset(pose.z());
  obstacles_.forgetSides();
  com_x_ = Eigen::Vector3d(pose.x(), 0.0, 0.0);
  com_y_ = Eigen::Vector3d(pose.y(), 0.0, 0.0);
  command_.setZero();
  held_samples_ = 0;
  time_ = 0.0;
  clearPlan();
  plan_ = SamplePlan();
}

Eigen::Vector3d PatternGenerator::clampCommand(const Eigen::Vector3d& command) const {
  const WalkingParameters& w = model_->parameters();
  return {std::clamp(command.x(), -w.max_forward_velocity, w.max_forward_velocity),
          std::clamp(command.y(), -w.max_lateral_velocity, w.max_lateral_velocity),
          std::clamp(command.z(), -w.max_angular_velocity, w.max_angular_velocity)};
}

// From a landing, the CoP can hold the capture point only up to copHalfWidth() from the landed
// ankle towards the lifting foot; beyond, it runs away as e^(omega0 t) (eq. 3) until that foot
// lands, a whole step later. Past push_step_capture_offset, and suddenly (more than
// push_step_capture_jump above the previous landing's offset, or the first landing of a walk),
// the next step is the cadence of push_step_single_support_samples; docs/formulation.md,
// "Pushes across the gait", has the push table for each choice.
int PatternGenerator::pushStepCadence(double capture_offset, double previous_offset) const {
  const WalkingParameters& p = parameters();
  if (!(capture_offset > p.push_step_capture_offset)) return 0;
  if (capture_offset - previous_offset <= p.push_step_capture_jump) return 0;  // NaN: a jump
  return std::min(p.single_support_samples - p.push_step_single_support_samples,
                  p.cadenceCount() - 1);
}

// One NMPC sample, concern by concern: the command, the step timing and the phase, the
// problem's references and state, the obstacles, then the solve.
const MpcIterationLog& PatternGenerator::update(double time, const Eigen::Vector3d& raw_command,
                                                const SwingFootTrajectory* swing) {
  const auto start = std::chrono::steady_clock::now();
  const Eigen::Vector3d command = takeCommand(time, raw_command);
  const GaitScheduler::SampleStart phase_start = beginSample(command);
  fillProblem(time, command, phase_start, swing);
  placeObstacles(command);
  references_.addSway(*problem_);

  solve();
  readPlan(time);

  const NmpcSolveResult& r = last_solve_;
  log_ = MpcIterationLog{time,          0.0,    r.qp_iterations,      r.sqp_iterations,
                         r.status,      r.cost, r.relaxed_families,   r.slack};
  log_.solve_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return log_;
}

Eigen::Vector3d PatternGenerator::takeCommand(double time, const Eigen::Vector3d& raw_command) {
  const Eigen::Vector3d command = clampCommand(raw_command);
  held_samples_ = command == command_ ? held_samples_ + 1 : 0;
  // The previous command held since the previous sample.
  if (!gait_.standing()) references_.integrateHeading(command_.z(), time - time_);
  time_ = time;
  command_ = command;
  return command;
}

int PatternGenerator::wantedCadence(const Eigen::Vector3d& command,
                                    const Eigen::Vector2d& capture_point) {
  // Step timing: the cadence of the steps from the next landing on, for a steady command, one
  // held for the whole step before that landing: the reach is that of a periodic gait, and a
  // command that changes every sample (a path follower's) keeps the cadence in force. A
  // standing robot starts with the parameters' own steps. The NMPC changes at the landing.
  int wanted = gait_.standing()                                ? 0
               : held_samples_ + 1 >= gait_.stepSamples() ? cadence_choice_.choose(command)
                                                           : active_;
  // Longer steps come one cadence a step: the CoM runs further during a longer step, and a
  // robot walking fast needs the shorter steps to slow down (stopping at once from 0.5 s to
  // 0.8 s steps made HRP-2 fall).
  if (!gait_.standing()) wanted = std::max(wanted, active_ - 1);
  // A push across the gait (towards the foot about to lift) is caught by that foot: at a
  // landing where the capture point is out that far, and got there by a jump, the next step
  // is shortened (pushStepCadence).
  if (gait_.standing()) previous_capture_offset_ = std::numeric_limits<double>::quiet_NaN();
  if (parameters().step_timing == StepTiming::kAdaptive &&
      parameters().push_step_capture_offset > 0.0 && gait_.atSwingLanding()) {
    const double offset = gait_.captureOffsetTowardsLiftingFoot(capture_point);
    wanted = std::max(wanted, pushStepCadence(offset, previous_capture_offset_));
    previous_capture_offset_ = offset;
  }
  return wanted;
}

GaitScheduler::SampleStart PatternGenerator::beginSample(const Eigen::Vector3d& command) {
  // The capture point c + c'/omega0 of the LIPM (eq. 3): where the CoP would have to be to
  // bring the CoM to rest; out of a standing robot's reach it must step.
  const Eigen::Vector2d capture_point(com_x_(0) + com_x_(1) / omega0_,
                                      com_y_(0) + com_y_(1) / omega0_);
  const int wanted = wantedCadence(command, capture_point);
  gait_.requestStepSamples(parameters().cadenceSingleSupport(wanted) +
                           parameters().double_support_samples);
  const GaitScheduler::SampleStart phase_start = gait_.beginSample(command, capture_point);
  if (phase_start.cadence_changed) {
    switchCadence(parameters().stepSamples() - gait_.stepSamples());
  }
  if (phase_start.started) {
    references_.restartHeading(gait_.feetMeanYaw());
    seedPlanFromStanding(command, phase_start.first_swing);
  }
  if (phase_start.structure_changed || obstacles_changed_) dropWarmStart();
  obstacles_changed_ = false;
  return phase_start;
}

void PatternGenerator::fillProblem(double time, const Eigen::Vector3d& command,
                                   const GaitScheduler::SampleStart& phase_start,
                                   const SwingFootTrajectory* swing) {
  const WalkingParameters& w = model_->parameters();  // the cadence in force's
  // The problem of this sample: phase structure, cost references, CoM state.
  gait_.fillPhase(*model_, problem_->phase);
  if (gait_.standing() || gait_.starting()) references_.forgetWalkedSamples();
  // The CoM velocities the warm start (the previous plan, shifted) predicts: J1's window
  // takes its turn there (reference_builder.hpp).
  const LipmPrediction& P = model_->prediction();
  const NmpcLayout& L = model_->layout();
  Eigen::VectorXd& planned_velocity_x = cadences_[active_]->planned_velocity_x;
  Eigen::VectorXd& planned_velocity_y = cadences_[active_]->planned_velocity_y;
  planned_velocity_x.noalias() = P.velocity_state * com_x_;
  planned_velocity_x.noalias() += P.velocity_jerk * solver_->plan().segment(L.jerkX(), L.horizon);
  planned_velocity_y.noalias() = P.velocity_state * com_y_;
  planned_velocity_y.noalias() += P.velocity_jerk * solver_->plan().segment(L.jerkY(), L.horizon);
  references_.build(command, gait_.phaseSample(), gait_.feetMeanYaw(),
                    Eigen::Vector2d(com_x_(1), com_y_(1)), planned_velocity_x,
                    planned_velocity_y, *problem_);
  problem_->com_x = com_x_;
  problem_->com_y = com_y_;
  // Landing bound (landing_bound family): the landing planned at the previous sample is the
  // warm start's step 0 (shiftPlan moved step 1 there when the step before was completed).
  problem_->landing_bounded = gait_.swinging() && !phase_start.structure_changed;
  problem_->previous_landing = plannedStep(0);
  problem_->landing_time_left =
      (w.stepSamples() - 1 - gait_.phaseSample()) * w.sampling_period;
  boundSwingReach(time, swing);
}

void PatternGenerator::placeObstacles(const Eigen::Vector3d& command) {
  const WalkingParameters& w = model_->parameters();
  problem_->obstacles = obstacles_.distance();
  if (gait_.standing()) {
    problem_->obstacle_slot.setConstant(-1);
  } else {
    obstacles_.select(problem_->phase.support_pose.head<2>(), settings_.obstacle_reach,
                      problem_->obstacle_slot);
  }
  problem_->obstacle_normal.setZero();
  problem_->obstacle_landing_normal.setZero();
  if (w.obstacle_linearization != ObstacleLinearization::kCommandTangent || gait_.standing()) {
    return;
  }
  // The obstacles' half-planes of this sample (wpg/obstacle_tangent.hpp): from the CoM, the
  // command's direction at this sample (J1's world reference) and each obstacle's passing
  // side, chosen from the point between the feet; then J1's reference turned along the
  // borders it drives into, so that sliding round is what the cost asks for.
  const Eigen::Vector2d feet_middle =
      0.5 * (gait_.footPose(FootSide::kLeft) + gait_.footPose(FootSide::kRight)).head<2>();
  obstacles_.borderNormals(Eigen::Vector2d(com_x_(0), com_y_(0)), feet_middle,
                           Eigen::Vector2d(problem_->velocity_x(0), problem_->velocity_y(0)),
                           w, tangentClearance(w), settings_.max_detour, problem_->obstacle_slot,
                           problem_->obstacle_normal, problem_->obstacle_offset);
  if (w.obstacle_landing_linearization == ObstacleLinearization::kStep && gait_.swinging()) {
    // Where the robot will have to be caught when the foot in the air lands: the capture point
    // at touchdown with the CoP held on the support foot (the LIPM's xi(T) = p + (xi - p)
    // e^(omega0 T)). A border that keeps it out keeps the catching step out too; that landing
    // gets its own half-plane (ObstacleSelector::landingRows). In a steady slide along a
    // border it lies inside (measured: 0.17 m inside in docs/python.md's online example
    // before its push, 0.06-0.09 m outside after 25-30 N); everywhere else the border stays,
    // as a landing beyond it walks the feet into the corner of two borders (obstacle_boxes's
    // closed loop was blocked between its first two boxes with the landing's row always on).
    const Eigen::Vector2d support = gait_.footPose(gait_.supportSide()).head<2>();
    const Eigen::Vector2d capture(com_x_(0) + com_x_(1) / omega0_,
                                  com_y_(0) + com_y_(1) / omega0_);
    const Eigen::Vector2d at_landing =
        support + (capture - support) * std::exp(omega0_ * problem_->landing_time_left);
    // Beyond a border: n.xi < offset (an empty slot's zero row never holds it out).
    const auto beyond = [&](int k) {
      return problem_->obstacle_normal.col(k).dot(at_landing) < problem_->obstacle_offset(k);
    };
    bool any_beyond = false;
    for (int k = 0; k < problem_->obstacle_slot.size(); ++k) any_beyond = any_beyond || beyond(k);
    if (any_beyond) {  // the common sample (no push) computes no landing row at all
      obstacles_.landingRows(plannedStep(0).head<2>(), w, problem_->obstacle_slot,
                             problem_->obstacle_landing_normal,
                             problem_->obstacle_landing_offset);
      for (int k = 0; k < problem_->obstacle_slot.size(); ++k) {
        if (beyond(k)) continue;
        problem_->obstacle_landing_normal.col(k).setZero();
        problem_->obstacle_landing_offset(k) = 0.0;
      }
    }
  }
  // Sideways no faster than the gait walks (in the robot's frame, where its reach is), or
  // than the command itself asks.
  const double sideways_limit = std::max(w.gaitSidewaysSpeed(), std::abs(command.y()));
  const Eigen::Vector2d com(com_x_(0), com_y_(0));
  border_room_.resize(problem_->obstacle_offset.size());  // the same size every sample
  for (int k = 0; k < border_room_.size(); ++k)
    border_room_(k) = problem_->obstacle_normal.col(k).dot(com) - problem_->obstacle_offset(k);
  turnReferenceAlongBorders(problem_->obstacle_normal, obstacles_.slides(),
                            references_.headingCos(), references_.headingSin(), sideways_limit,
                            border_room_, w.horizon_length * w.sampling_period,
                            problem_->velocity_x, problem_->velocity_y);
}

bool PatternGenerator::advance(const Eigen::Vector3d& com_x, const Eigen::Vector3d& com_y) {
  com_x_ = com_x;
  com_y_ = com_y;
  const GaitScheduler::SampleEnd end =
      gait_.endSample(plannedStep(0), time_ + model_->parameters().sampling_period);
  shiftPlan(end.step_completed);
  return end.landed;
}

// Swing-foot reach (swing_reach family): the landings the swing foot reaches from its state
// at this sample within max_swing_speed and max_swing_acceleration. At the first sample of a
// swing the foot is at rest on the ground: its trajectory starts here.
void PatternGenerator::boundSwingReach(double time, const SwingFootTrajectory* swing) {
  const WalkingParameters& w = model_->parameters();
  problem_->swing_reach_bounded = false;
  if (SwingReachRows::count(*model_) == 0 || !gait_.swinging()) return;
  const int m = gait_.phaseSample();
  SwingFootTrajectory resting;
  // The landing the foot heads for now stays inside the reach (the rows never make the QP
  // infeasible on their own). Before this swing's first plan the foot heads nowhere: the
  // warm start's landing was planned for the step before, under no reach of this swing (and,
  // after a cadence switch, for a longer one), so the reach is the resting foot's own, which
  // holds its lift-off pose.
  Eigen::Vector2d heading_for = plannedStep(0).head<2>();
  if (!swing) {
    const Eigen::Vector3d& lift_off = gait_.footPose(otherSide(gait_.supportSide()));
    resting.start(lift_off, time - (m - gait_.liftOffSample()) * w.sampling_period,
                  time + (w.stepSamples() - 1 - m) * w.sampling_period, w.step_height);
    swing = &resting;
    heading_for = lift_off.head<2>();
  }
  const SwingReach reach = swingReach(*swing, time, heading_for, w.max_swing_speed,
                                      w.max_swing_acceleration, w.control_period);
  problem_->swing_reach_bounded = true;
  problem_->swing_reach_lower = reach.lower;
  problem_->swing_reach_upper = reach.upper;
}

// --- the NMPC's plan and its warm start (owned by the solver) ------------------------------

// At a landing where the step timing changes: the plan of the cadence in force becomes the
// new cadence's initial guess (the same previewed steps; the jerks of the samples both
// horizons have, the last one held beyond the shorter), without a warm-start active set (its
// rows are another model's), and the references take the new timing.
void PatternGenerator::switchCadence(int cadence) {
  Cadence& to = *cadences_[cadence];
  if (cadence != active_) {
    const NmpcLayout& from_layout = model_->layout();
    const NmpcLayout& to_layout = to.model.layout();
    const Eigen::VectorXd& from = solver_->plan();
    Eigen::VectorXd& U = to.solver.plan();
    for (int axis = 0; axis < 2; ++axis) {
      const int of = axis == 0 ? from_layout.jerkX() : from_layout.jerkY();
      const int ot = axis == 0 ? to_layout.jerkX() : to_layout.jerkY();
      for (int j = 0; j < to_layout.horizon; ++j)
        U(ot + j) = from(of + std::min(j, from_layout.horizon - 1));
    }
    for (int i = 0; i < to_layout.steps; ++i) {
      U(to_layout.stepX() + i) = from(from_layout.stepX() + i);
      U(to_layout.stepY() + i) = from(from_layout.stepY() + i);
      U(to_layout.stepYaw() + i) = from(from_layout.stepYaw() + i);
    }
    active_ = cadence;
    model_ = &to.model;
    solver_ = &to.solver;
    problem_ = &to.problem;
  }
  solver_->clearActiveSet();
  references_.setCadence(model_->parameters());
}

Eigen::Vector3d PatternGenerator::plannedStep(int step) const {
  const NmpcLayout& L = model_->layout();
  const Eigen::VectorXd& U = solver_->plan();
  return {U(L.stepX() + step), U(L.stepY() + step), U(L.stepYaw() + step)};
}

void PatternGenerator::seedStep(int step, const Eigen::Vector3d& pose) {
  const NmpcLayout& L = model_->layout();
  Eigen::VectorXd& U = solver_->plan();
  U(L.stepX() + step) = pose.x();
  U(L.stepY() + step) = pose.y();
  U(L.stepYaw() + step) = pose.z();
}

// Walking starts: step 1 is the first support foot (on the ground), the later ones nominal
// steps from it (the linearization point of the first iteration).
void PatternGenerator::seedPlanFromStanding(const Eigen::Vector3d& command, FootSide first_swing) {
  Eigen::Vector3d previous = gait_.footPose(otherSide(first_swing));
  seedStep(0, previous);
  FootSide side = first_swing;
  for (int i = 1; i < model_->layout().steps; ++i, side = otherSide(side)) {
    previous = nominalStep(model_->parameters(), previous, side, command);
    seedStep(i, previous);
  }
}

// The rows change meaning: no warm start across it.
void PatternGenerator::dropWarmStart() { solver_->clearActiveSet(); }

void PatternGenerator::clearPlan() {
  solver_->plan().setZero();
  solver_->clearActiveSet();
}

void PatternGenerator::solve() {
  last_solve_ = settings_.algorithm == GeneratorAlgorithm::kLmpc
                    ? solver_->solveLmpc(*problem_, settings_)
                    : solver_->solve(*problem_, settings_);
}

void PatternGenerator::readPlan(double time) {
  const WalkingParameters& w = model_->parameters();
  const NmpcLayout& L = model_->layout();
  const int S = w.stepSamples();
  const int m = gait_.phaseSample();
  plan_.jerk_x = solver_->plan()(L.jerkX());
  plan_.jerk_y = solver_->plan()(L.jerkY());
  plan_.swinging = gait_.swinging();
  plan_.support = gait_.supportState();
  plan_.swing_side = otherSide(gait_.supportSide());
  plan_.swing_target = plannedStep(0);
  plan_.landing_time = time + (S - 1 - m) * w.sampling_period;
  plan_.lift_off_time = time - (m - gait_.liftOffSample()) * w.sampling_period;
}

// The warm start of the next real-time iteration: the jerks one sample earlier and, when a
// step was completed, the steps one place up with a nominal step appended.
void PatternGenerator::shiftPlan(bool step_completed) {
  const NmpcLayout& L = model_->layout();
  Eigen::VectorXd& U = solver_->plan();
  for (int axis = 0; axis < 2; ++axis) {
    const int o = axis == 0 ? L.jerkX() : L.jerkY();
    for (int j = 0; j + 1 < L.horizon; ++j) U(o + j) = U(o + j + 1);
  }
  if (step_completed) {
    for (int i = 0; i + 1 < L.steps; ++i) seedStep(i, plannedStep(i + 1));
    FootSide last_side = gait_.supportSide();
    for (int i = 0; i < L.steps; ++i) last_side = otherSide(last_side);
    const Eigen::Vector3d previous =
        L.steps >= 2 ? plannedStep(L.steps - 2) : gait_.footPose(gait_.supportSide());
    seedStep(L.steps - 1, nominalStep(model_->parameters(), previous, last_side, command_));
  }
  solver_->shiftActiveSet(step_completed);
}

}  // namespace wpg
