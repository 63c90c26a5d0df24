#pragma once
// The NMPC's solver (paper Sec. III-E): Gauss-Newton SQP on the model's constant Hessian, one
// QP per sample (real-time iteration) or to convergence, with the relaxation of infeasible
// QPs and the Herdt et al. 2010 linear MPC as baseline. The solver owns its state across
// samples, the plan U (the iterate, and the warm start once shifted) and the warm-start active
// set; NmpcWorkspace is scratch, sized once from the model (no allocation per sample).
#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "wpg/nmpc/model.hpp"
#include "wpg/nmpc/problem.hpp"
#include "wpg/qp/dense_qp_solver.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walk_trajectory.hpp"

namespace wpg {

struct NmpcSolveResult {
  IterationStatus status = IterationStatus::kSolved;
  int qp_iterations = 0;   // working-set updates of every QP, warm starts included
  int qp_warm_start_updates = 0;  // the part of qp_iterations spent loading the warm start
  int sqp_iterations = 0;  // QPs of the Gauss-Newton iterations
  double cost = 0.0;       // cost (5) at the executed plan
  double last_step_norm = 0.0;  // max |U_{i+1} - U_i| of the last SQP iteration
  // Relaxation, per constraint family of the model (see MpcIterationLog)
  std::uint32_t relaxed_families = 0;
  std::array<double, kMaxConstraintFamilies> slack{};
};

// Scratch buffers of one NMPC instance, sized once from the model (no allocation per sample).
class NmpcWorkspace {
 public:
  explicit NmpcWorkspace(const NmpcModel& model);

  Eigen::VectorXd linearization;  // current SQP iterate
  Eigen::VectorXd gradient;
  Eigen::MatrixXd jacobian;       // mi x n
  Eigen::VectorXd constraints;    // g at the linearization point
  Eigen::VectorXd upper;          // right-hand side of the linearized rows
  Eigen::MatrixXd equality_matrix;
  Eigen::VectorXd equality_vector;
  Eigen::VectorXd qp_solution;
  qp::DenseQpSolver solver;
  // Relaxed problem [U; s_1 .. s_F]: one slack per constraint family (in its unit), on the
  // rows of the families relaxed at that stage, each with s_k >= 0.
  qp::DenseQpSolver relaxed_solver;
  qp::HessianFactor relaxed_factor;
  Eigen::MatrixXd relaxed_jacobian, relaxed_equality_matrix;
  Eigen::VectorXd relaxed_gradient, relaxed_upper, relaxed_solution;
  // Cost terms (wpg/nmpc/cost_term.hpp; sized 0 when the model has none): their residuals r
  // and Jacobian R at the linearization point, the Gauss-Newton Hessian Q + R'R with its
  // factor, and the linear term p + R'(r - R U_lin) of each QP.
  Eigen::VectorXd residuals, shifted_residuals, term_gradient;
  Eigen::MatrixXd residual_jacobian, term_hessian;
  Eigen::LLT<Eigen::MatrixXd> term_cholesky;
  qp::HessianFactor term_factor;
  // LMPC orientation QP (nf yaws)
  qp::DenseQpSolver orientation_solver;
  qp::HessianFactor orientation_factor;
  Eigen::MatrixXd orientation_inequalities, orientation_equalities;
  Eigen::VectorXd orientation_upper, orientation_equality_vector, orientation_gradient,
      orientation_solution;
};

class NmpcSolver {
 public:
  // Bound to `model` for good: it must outlive the solver (PatternGenerator owns both). Its
  // workspace and active set are sized from the model's layout and rows.
  explicit NmpcSolver(const NmpcModel& model);
  const NmpcModel& model() const { return *model_; }

  // The plan U = [jerk_x, F_x, jerk_y, F_y, F_theta] (eq. 6): on entry to solve() the initial
  // guess (the previous plan shifted by the caller), afterwards the plan to execute. When an
  // iteration falls back (kFallback, kIterationLimit) it is left as it was on entry.
  Eigen::VectorXd& plan() { return plan_; }
  const Eigen::VectorXd& plan() const { return plan_; }

  // Gauss-Newton SQP from plan(): settings.sqp_iterations QPs (1 = real-time iteration), or to
  // convergence when 0 (bounded by max_sqp_iterations). Throws std::invalid_argument when the
  // problem does not have the sizes of the model (NmpcModel::checkProblem).
  NmpcSolveResult solve(const NmpcProblem& problem, const GeneratorSettings& settings);
  // Herdt et al. 2010 baseline: the step yaws from an orientation QP (J2 with the yaw bounds),
  // then the position QP with those yaws (linear once the yaws are fixed: one QP is exact).
  NmpcSolveResult solveLmpc(const NmpcProblem& problem, const GeneratorSettings& settings);

  // Warm start: moves the active set one sample forward (and one step when a step was
  // completed), each family shifting its own rows (ConstraintFamily::shiftedRow); rows that
  // leave the horizon are dropped.
  void shiftActiveSet(bool step_completed);
  // Forget the active set (the rows change meaning: start or stop of a walk).
  void clearActiveSet() { active_count_ = 0; }
  int activeCount() const { return active_count_; }
  const int* activeRows() const { return active_set_.data(); }

  const NmpcWorkspace& workspace() const { return workspace_; }

 private:
  NmpcSolveResult runSqp(const NmpcProblem& problem, const GeneratorSettings& settings,
                         int iterations, const Eigen::VectorXd* fixed_yaws);
  // Solves the QP with slacks on the families of the groups up to `relaxed_up_to`; on kOptimal
  // the solution is in the workspace's qp_solution and `result` records the relaxation.
  qp::QpStatus solveRelaxed(const qp::HessianFactor& factor, const Eigen::VectorXd& gradient,
                            int equalities, double slack_weight, RelaxationGroup relaxed_up_to,
                            NmpcSolveResult& result);
  // The QP's Hessian factor and linear term with the model's cost terms linearized at the
  // workspace's linearization point (into the workspace); false when Q + R'R cannot be
  // factored.
  bool linearizeCostTerms(const NmpcProblem& problem);
  // cost (5) at `U` plus the cost terms' 1/2 |r(U)|^2.
  double totalCost(const NmpcProblem& problem, const Eigen::VectorXd& U);
  void rememberActiveSet(const qp::DenseQpSolver& solver, int inequality_rows);

  const NmpcModel* model_;
  Eigen::VectorXd plan_;
  Eigen::VectorXi active_set_;  // active inequality rows of the last solve (warm start)
  int active_count_ = 0;
  NmpcWorkspace workspace_;
};

}  // namespace wpg
