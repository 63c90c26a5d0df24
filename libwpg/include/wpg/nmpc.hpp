#pragma once
// The nonlinear MPC of Naveau et al. 2017 (Sec. III), as functions over a constant model, a
// per-sample problem instance and a preallocated workspace (../shared/STYLE.md, items 1-3).
//
// Decision variables (eq. 6), for a horizon of N samples and nf previewed steps:
//   U = [jerk_x (N), F_x (nf), jerk_y (N), F_y (nf), F_theta (nf)].
// Cost (5)-(8) is quadratic in U, so the Gauss-Newton Hessian is constant for a given walking
// phase; the constraints are nonlinear through the step yaws:
//   CoP in the rotated support polygon          (9)-(13)   4 rows per sample
//   step inside the previous step's polygon     (14)-(15)  5 rows per step
//   yaw change between consecutive steps        (16)-(17)  2 rows per step
//   obstacle avoidance                          (18)-(19)  1 row per step and obstacle slot
// all written g(U) <= 0 and linearized at the previous iterate as in (21b).
#include <vector>

#include <Eigen/Core>

#include "wpg/convex_polygon.hpp"
#include "wpg/lipm_prediction.hpp"
#include "wpg/obstacles.hpp"
#include "wpg/qp/dense_qp_solver.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

// Index layout of U and of the inequality rows.
struct NmpcLayout {
  int horizon = 0;         // N
  int steps = 0;           // nf
  int feasibility_edges = 0;
  int obstacle_slots = 0;  // obstacles that may enter the QP at once

  int jerkX() const { return 0; }
  int stepX() const { return horizon; }
  int jerkY() const { return horizon + steps; }
  int stepY() const { return 2 * horizon + steps; }
  int stepYaw() const { return 2 * horizon + 2 * steps; }
  int variableCount() const { return 2 * horizon + 3 * steps; }

  static constexpr int kCopEdges = 4;
  int copRow(int sample, int edge) const { return kCopEdges * sample + edge; }
  int feasibilityRow(int step, int edge) const {
    return kCopEdges * horizon + feasibility_edges * step + edge;
  }
  int yawRow(int step, bool upper) const {
    return kCopEdges * horizon + feasibility_edges * steps + 2 * step + (upper ? 0 : 1);
  }
  int obstacleRow(int step, int slot) const {
    return kCopEdges * horizon + feasibility_edges * steps + 2 * steps + obstacle_slots * step + slot;
  }
  int firstObstacleRow() const { return obstacleRow(0, 0); }
  int inequalityCount() const { return obstacleRow(steps, 0); }
  int maxEqualityCount() const { return 3 * steps; }
};

// Shape of the problem at one sample: which support each CoP sample uses, which steps are free.
struct PhaseStructure {
  FootSide first_step_side = FootSide::kLeft;  // previewed steps alternate from this side
  // Fixed reference of the samples on the current support: the support foot (x, y, yaw), or
  // the point between the feet when standing; and the CoP rectangle there (half sizes).
  Eigen::Vector3d support_pose = Eigen::Vector3d::Zero();
  double support_half_length = 0.0;
  double support_half_width = 0.0;
  Eigen::VectorXi row_step;        // N: 0 = current support, i = previewed step i (1-based)
  Eigen::VectorXi step_fixed;      // nf: 1 = pose fixed by equality (landed, or final step)
  Eigen::Matrix<double, 3, Eigen::Dynamic> fixed_step_pose;  // 3 x nf
  // Hessian pattern (NmpcModel::rowStepsOf): r = the CoP samples j = 1..r on the current
  // support while walking, or the standing pattern (every sample on both feet)
  int pattern = 0;

  FootSide stepSide(int step) const {  // 0-based step index
    const bool same = (step % 2) == 0;
    return same ? first_step_side
                : (first_step_side == FootSide::kLeft ? FootSide::kRight : FootSide::kLeft);
  }
};

// Everything that changes from one sample to the next.
struct NmpcProblem {
  PhaseStructure phase;
  // Obstacles (eq. 18-19): slot k holds the index of an obstacle in *obstacles, or -1.
  // Circles use the paper's form (F - c)^2 >= (R + m)^2; other shapes d(F) >= m with d and
  // its gradient from *distance (planning/'s FCL world, or AnalyticObstacleDistance).
  const std::vector<Obstacle>* obstacles = nullptr;
  const ObstacleDistanceOracle* distance = nullptr;
  Eigen::VectorXi obstacle_slot;
  Eigen::Vector3d com_x = Eigen::Vector3d::Zero();  // [c, c', c''] along world x
  Eigen::Vector3d com_y = Eigen::Vector3d::Zero();
  Eigen::VectorXd velocity_x, velocity_y;  // N: world reference velocity per sample (J1)
  // N: the part of each sample's windowed mean velocity that comes from samples already
  // walked (0 with the paper's instantaneous tracking, velocity_window_samples = 1)
  Eigen::VectorXd velocity_past_x, velocity_past_y;
  Eigen::VectorXd yaw_reference;           // nf: reference yaw of each step (J2)
};

class NmpcModel {
 public:
  explicit NmpcModel(const WalkingParameters& parameters, int obstacle_slots = 0);

  const WalkingParameters& parameters() const { return parameters_; }
  const NmpcLayout& layout() const { return layout_; }
  const LipmPrediction& prediction() const { return prediction_; }
  // The velocity J1 tracks: (windowed mean of) C' = tracked_state c_hat + tracked_jerk jerks
  // + the problem's velocity_past (prediction's velocity rows with window 1).
  const Eigen::Matrix<double, Eigen::Dynamic, 3>& trackedVelocityState() const {
    return tracked_velocity_state_;
  }
  const Eigen::MatrixXd& trackedVelocityJerk() const { return tracked_velocity_jerk_; }
  const ConvexPolygon& feasibilityPolygon(FootSide side) const {
    return side == FootSide::kLeft ? feasibility_left_ : feasibility_right_;
  }
  double stepDuration() const { return parameters_.stepDuration(); }

  // Patterns: walking with r = 0 .. S-1 remaining samples (S = samples per step), standing = S.
  int patternCount() const { return static_cast<int>(hessians_.size()); }
  int standingPattern() const { return patternCount() - 1; }
  void rowStepsOf(int pattern, Eigen::Ref<Eigen::VectorXi> row_step) const;
  const Eigen::MatrixXd& hessian(int pattern) const { return hessians_[pattern]; }
  const qp::HessianFactor& hessianFactor(int pattern) const { return factors_[pattern]; }

  // Allocates a problem with the right sizes (not for the hot loop).
  NmpcProblem makeProblem() const;

 private:
  WalkingParameters parameters_;
  NmpcLayout layout_;
  LipmPrediction prediction_;
  Eigen::Matrix<double, Eigen::Dynamic, 3> tracked_velocity_state_;
  Eigen::MatrixXd tracked_velocity_jerk_;
  ConvexPolygon feasibility_left_, feasibility_right_;
  std::vector<Eigen::MatrixXd> hessians_;
  std::vector<qp::HessianFactor> factors_;
};

// Linear term p of the canonical cost (8): cost = 1/2 U'QU + p'U + const.
void buildCostGradient(const NmpcModel& model, const NmpcProblem& problem,
                       Eigen::Ref<Eigen::VectorXd> gradient);
// The cost (5) itself (with its constant), alpha/2 J1 + alpha/2 J2 + beta/2 J3 + gamma/2 J4.
double evaluateCost(const NmpcModel& model, const NmpcProblem& problem,
                    const Eigen::Ref<const Eigen::VectorXd>& U);

// g(U) (inequality rows, <= 0 when satisfied) and, when jacobian != nullptr, its exact
// Jacobian dg/dU (every term, including the yaw derivative of the CoP rows through the
// current CoM state). Rows of fixed steps are inactive (g = -1, zero Jacobian row).
void evaluateConstraints(const NmpcModel& model, const NmpcProblem& problem,
                         const Eigen::Ref<const Eigen::VectorXd>& U,
                         Eigen::Ref<Eigen::VectorXd> g, Eigen::MatrixXd* jacobian);

// Equality rows fixing the fixed steps (x, y, yaw); returns their count.
int buildStepEqualities(const NmpcModel& model, const NmpcProblem& problem,
                        Eigen::Ref<Eigen::MatrixXd> E, Eigen::Ref<Eigen::VectorXd> e);

struct NmpcSolveResult {
  IterationStatus status = IterationStatus::kSolved;
  int qp_iterations = 0;
  int sqp_iterations = 0;
  double slack = 0.0;
  double cost = 0.0;
  double last_step_norm = 0.0;  // max |U_{i+1} - U_i| of the last SQP iteration
};

// Buffers of one NMPC instance, sized once from the model.
class NmpcWorkspace {
 public:
  explicit NmpcWorkspace(const NmpcModel& model);

  Eigen::VectorXd U;             // solution; on entry the initial guess (shifted plan)
  Eigen::VectorXd linearization;  // current SQP iterate
  Eigen::VectorXd gradient;
  Eigen::MatrixXd jacobian;      // mi x n
  Eigen::VectorXd constraints;   // g at the linearization point
  Eigen::VectorXd upper;         // right-hand side of the linearized rows
  Eigen::MatrixXd equality_matrix;
  Eigen::VectorXd equality_vector;
  Eigen::VectorXd qp_solution;
  qp::DenseQpSolver solver;
  // relaxed problem: [U; s] with one slack on the obstacle rows, else on every row
  qp::DenseQpSolver relaxed_solver;
  qp::HessianFactor relaxed_factor;
  Eigen::MatrixXd relaxed_jacobian, relaxed_equality_matrix;
  Eigen::VectorXd relaxed_gradient, relaxed_upper, relaxed_solution;
  // LMPC orientation QP (nf yaws)
  qp::DenseQpSolver orientation_solver;
  qp::HessianFactor orientation_factor;
  Eigen::MatrixXd orientation_inequalities, orientation_equalities;
  Eigen::VectorXd orientation_upper, orientation_equality_vector, orientation_gradient,
      orientation_solution;
  // warm start: active inequality rows of the last solve
  Eigen::VectorXi active_set;
  int active_count = 0;

  // Moves the warm-start active set one sample forward (and one step when a step was
  // completed), dropping rows that leave the horizon.
  void shiftActiveSet(const NmpcLayout& layout, bool step_completed);
};

// Gauss-Newton SQP (Sec. III-E) from workspace.U: `iterations` QPs (1 = real-time iteration),
// or to convergence when iterations == 0. Result in workspace.U.
NmpcSolveResult solveNmpc(const NmpcModel& model, const NmpcProblem& problem,
                          const GeneratorSettings& settings, NmpcWorkspace& workspace);

// Herdt et al. 2010 baseline: the step yaws from an orientation QP (J2 with the yaw bounds),
// then the position QP with those yaws of the same sample (linear: one QP is exact).
NmpcSolveResult solveLmpc(const NmpcModel& model, const NmpcProblem& problem,
                          const GeneratorSettings& settings, NmpcWorkspace& workspace);

}  // namespace wpg
