// Gauss-Newton SQP of the NMPC (Sec. III-E) with staged relaxation of infeasible QPs (the LMPC
// baseline is in lmpc.cpp).
#include "wpg/nmpc/solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "nmpc_internal.hpp"
#include "wpg/nmpc/cost.hpp"

namespace wpg {
namespace {

// A family counts as relaxed when its slack exceeds this (in its unit, m or rad): below it the
// violation is at the QP's rounding level.
constexpr double kRelaxedSlack = 1e-9;

// The more severe of two statuses of one sample's QPs (its status reports the worst).
int severity(IterationStatus status) {
  switch (status) {
    case IterationStatus::kSolved: return 0;
    case IterationStatus::kNotConverged: return 1;
    case IterationStatus::kRelaxedObstacle: return 2;
    case IterationStatus::kRelaxedKinematics: return 3;
    case IterationStatus::kRelaxedBalance: return 4;
    case IterationStatus::kIterationLimit: return 5;
    case IterationStatus::kFallback: return 6;
    case IterationStatus::kFallen: return 7;
  }
  return 7;
}

void raise(NmpcSolveResult& result, IterationStatus status) {
  if (severity(status) > severity(result.status)) result.status = status;
}

IterationStatus relaxedStatus(RelaxationGroup group) {
  switch (group) {
    case RelaxationGroup::kObstacle: return IterationStatus::kRelaxedObstacle;
    case RelaxationGroup::kKinematics: return IterationStatus::kRelaxedKinematics;
    case RelaxationGroup::kBalance: return IterationStatus::kRelaxedBalance;
  }
  return IterationStatus::kRelaxedBalance;
}

}  // namespace

NmpcWorkspace::NmpcWorkspace(const NmpcModel& model)
    : solver(model.layout().variableCount(), model.layout().maxEqualityCount(),
             model.inequalityCount()),
      relaxed_solver(model.layout().variableCount() + model.familyCount(),
                     model.layout().maxEqualityCount(),
                     model.inequalityCount() + model.familyCount()),
      orientation_solver(model.layout().steps, model.layout().steps, 2 * model.layout().steps) {
  const NmpcLayout& L = model.layout();
  const int n = L.variableCount(), mi = model.inequalityCount(), me = L.maxEqualityCount();
  const int nf = L.steps, F = model.familyCount();
  linearization = Eigen::VectorXd::Zero(n);
  gradient = Eigen::VectorXd::Zero(n);
  jacobian = Eigen::MatrixXd::Zero(mi, n);
  constraints = Eigen::VectorXd::Zero(mi);
  upper = Eigen::VectorXd::Zero(mi);
  equality_matrix = Eigen::MatrixXd::Zero(me, n);
  equality_vector = Eigen::VectorXd::Zero(me);
  qp_solution = Eigen::VectorXd::Zero(n);
  relaxed_factor.inverse_factor_transposed = Eigen::MatrixXd::Zero(n + F, n + F);
  relaxed_factor.size = n + F;
  relaxed_jacobian = Eigen::MatrixXd::Zero(mi + F, n + F);
  relaxed_equality_matrix = Eigen::MatrixXd::Zero(me, n + F);
  relaxed_gradient = Eigen::VectorXd::Zero(n + F);
  relaxed_upper = Eigen::VectorXd::Zero(mi + F);
  relaxed_solution = Eigen::VectorXd::Zero(n + F);
  orientation_factor.compute(model.parameters().weight_yaw * Eigen::MatrixXd::Identity(nf, nf));
  orientation_inequalities = Eigen::MatrixXd::Zero(2 * nf, nf);
  orientation_equalities = Eigen::MatrixXd::Zero(nf, nf);
  orientation_upper = Eigen::VectorXd::Zero(2 * nf);
  orientation_equality_vector = Eigen::VectorXd::Zero(nf);
  orientation_gradient = Eigen::VectorXd::Zero(nf);
  orientation_solution = Eigen::VectorXd::Zero(nf);
  const int r = model.residualCount();
  residuals = Eigen::VectorXd::Zero(r);
  shifted_residuals = Eigen::VectorXd::Zero(r);
  residual_jacobian = Eigen::MatrixXd::Zero(r, n);
  if (model.costTermCount() > 0) {
    term_gradient = Eigen::VectorXd::Zero(n);
    term_hessian = model.hessian(0);
    term_cholesky.compute(term_hessian);  // sizes its storage
    term_factor.compute(term_hessian, term_cholesky);
  }
  solver.setInequalityProfile(model.jacobianProfile());
}

NmpcSolver::NmpcSolver(const NmpcModel& model)
    : model_(&model),
      plan_(Eigen::VectorXd::Zero(model.layout().variableCount())),
      active_set_(Eigen::VectorXi::Zero(model.inequalityCount() + model.familyCount())),
      workspace_(model) {}

void NmpcSolver::shiftActiveSet(bool step_completed) {
  const NmpcModel& model = *model_;
  int kept = 0;
  for (int k = 0; k < active_count_; ++k) {
    const int row = active_set_(k);
    const int family = model.familyOfRow(row);  // each family shifts its own rows
    if (family < 0) continue;
    const int first = model.familyFirstRow(family);
    const int local = model.family(family).shiftedRow(model, row - first, step_completed);
    if (local >= 0 && local < model.familyRowCount(family)) active_set_(kept++) = first + local;
  }
  active_count_ = kept;
}

void NmpcSolver::rememberActiveSet(const qp::DenseQpSolver& solver, int inequality_rows) {
  active_count_ = 0;
  for (int k = 0; k < solver.activeInequalityCount(); ++k) {
    const int row = solver.activeInequalities()[k];
    if (row < inequality_rows) active_set_(active_count_++) = row;
  }
}

bool NmpcSolver::linearizeCostTerms(const NmpcProblem& problem) {
  const NmpcModel& model = *model_;
  NmpcWorkspace& ws = workspace_;
  // 1/2 |r(U0) + R (U - U0)|^2 = 1/2 U'R'RU + (R'(r - R U0))'U + const
  nmpc_internal::stackResiduals(model, problem, ws.linearization, ws.residuals,
                                &ws.residual_jacobian);
  ws.shifted_residuals = ws.residuals;
  ws.shifted_residuals.noalias() -= ws.residual_jacobian * ws.linearization;
  ws.term_gradient = ws.gradient;
  ws.term_gradient.noalias() += ws.residual_jacobian.transpose() * ws.shifted_residuals;
  ws.term_hessian = model.hessian(problem.phase.pattern);
  ws.term_hessian.noalias() += ws.residual_jacobian.transpose() * ws.residual_jacobian;
  return ws.term_factor.compute(ws.term_hessian, ws.term_cholesky);
}

double NmpcSolver::totalCost(const NmpcProblem& problem, const Eigen::VectorXd& U) {
  double cost = nmpc_internal::cost(*model_, problem, U);
  if (model_->costTermCount() == 0) return cost;
  nmpc_internal::stackResiduals(*model_, problem, U, workspace_.residuals, nullptr);
  return cost + 0.5 * workspace_.residuals.squaredNorm();
}

qp::QpStatus NmpcSolver::solveRelaxed(const qp::HessianFactor& factor,
                                      const Eigen::VectorXd& gradient, int me, double rho,
                                      RelaxationGroup relaxed_up_to, NmpcSolveResult& result) {
  const NmpcModel& model = *model_;
  NmpcWorkspace& ws = workspace_;
  const int n = static_cast<int>(ws.gradient.size());
  const int mi = static_cast<int>(ws.upper.size());
  const int F = model.familyCount();
  // min 1/2 U'QU + p'U + sum_k (rho s_k + rho/2 s_k^2)  s.t.  g_k(U) <= s_k on the rows of
  // each relaxed family k, s >= 0; the other families' slacks have no rows (they stay 0).
  auto& J = ws.relaxed_factor.inverse_factor_transposed;
  J.topLeftCorner(n, n) = factor.inverse_factor_transposed;
  J.diagonal().tail(F).setConstant(1.0 / std::sqrt(rho));
  ws.relaxed_gradient.head(n) = gradient;
  ws.relaxed_gradient.tail(F).setConstant(rho);
  ws.relaxed_jacobian.topLeftCorner(mi, n) = ws.jacobian;
  ws.relaxed_jacobian.topRightCorner(mi, F).setZero();
  for (int k = 0; k < F; ++k) {
    if (model.family(k).group() > relaxed_up_to) continue;
    ws.relaxed_jacobian.col(n + k).segment(model.familyFirstRow(k), model.familyRowCount(k))
        .setConstant(-1.0);
  }
  ws.relaxed_jacobian.bottomRightCorner(F, F).diagonal().setConstant(-1.0);  // -s_k <= 0
  ws.relaxed_upper.head(mi) = ws.upper;
  ws.relaxed_upper.tail(F).setZero();
  ws.relaxed_equality_matrix.topLeftCorner(me, n) = ws.equality_matrix.topRows(me);
  ws.relaxed_solver.setActiveSetGuess(active_set_.data(), active_count_);
  const qp::QpStatus status = ws.relaxed_solver.solve(
      ws.relaxed_factor, ws.relaxed_gradient, ws.relaxed_equality_matrix.topRows(me),
      ws.equality_vector.head(me), ws.relaxed_jacobian, ws.relaxed_upper, ws.relaxed_solution);
  result.qp_iterations += ws.relaxed_solver.iterations();
  result.qp_warm_start_updates += ws.relaxed_solver.warmStartUpdates();
  if (status != qp::QpStatus::kOptimal) return status;
  if (!ws.relaxed_solution.allFinite()) return qp::QpStatus::kInvalidInput;

  // Which families gave way, and by how much: the status names the most severe group.
  RelaxationGroup worst = RelaxationGroup::kObstacle;
  int largest = -1;
  for (int k = 0; k < F; ++k) {
    const double s = std::max(0.0, ws.relaxed_solution(n + k));
    result.slack[k] = std::max(result.slack[k], s);
    if (largest < 0 || s > ws.relaxed_solution(n + largest)) largest = k;
    if (s > kRelaxedSlack) {
      result.relaxed_families |= 1u << k;
      worst = std::max(worst, model.family(k).group());
    }
  }
  // Infeasible by a hair only (every slack at rounding level): the family with the largest one.
  if (!(result.relaxed_families) && largest >= 0) worst = model.family(largest).group();
  raise(result, relaxedStatus(worst));
  rememberActiveSet(ws.relaxed_solver, mi);
  ws.qp_solution = ws.relaxed_solution.head(n);
  return qp::QpStatus::kOptimal;
}

NmpcSolveResult NmpcSolver::runSqp(const NmpcProblem& problem, const GeneratorSettings& settings,
                                   int iterations, const Eigen::VectorXd* fixed_yaws) {
  const NmpcModel& model = *model_;
  NmpcWorkspace& ws = workspace_;
  const NmpcLayout& L = model.layout();
  const int mi = model.inequalityCount();
  const bool has_terms = model.costTermCount() > 0;
  // Without cost terms the Hessian is the model's constant one, its factor precomputed.
  const qp::HessianFactor& factor =
      has_terms ? ws.term_factor : model.hessianFactor(problem.phase.pattern);
  const Eigen::VectorXd& gradient = has_terms ? ws.term_gradient : ws.gradient;
  NmpcSolveResult result;
  // A QP that cannot be used: keep the time-shifted previous plan (plan_ is untouched).
  auto fall_back = [&](IterationStatus status) {
    raise(result, status);
    result.cost = totalCost(problem, plan_);
    return result;
  };

  nmpc_internal::costGradient(model, problem, ws.gradient);
  int me = buildStepEqualities(model, problem, ws.equality_matrix, ws.equality_vector);
  ws.linearization = plan_;
  for (int i = 0; i < L.steps; ++i) {
    if (problem.phase.step_fixed(i)) {
      ws.linearization(L.stepX() + i) = problem.phase.fixed_step_pose(0, i);
      ws.linearization(L.stepY() + i) = problem.phase.fixed_step_pose(1, i);
      ws.linearization(L.stepYaw() + i) = problem.phase.fixed_step_pose(2, i);
    } else if (fixed_yaws) {
      ws.linearization(L.stepYaw() + i) = (*fixed_yaws)(i);
      ws.equality_matrix.row(me).setZero();
      ws.equality_matrix(me, L.stepYaw() + i) = 1.0;
      ws.equality_vector(me) = (*fixed_yaws)(i);
      ++me;
    }
  }
  ws.solver.settings().max_iterations = settings.max_qp_iterations;
  ws.relaxed_solver.settings().max_iterations = settings.max_qp_iterations;

  const int max_iterations = iterations > 0 ? iterations : settings.max_sqp_iterations;
  for (int it = 0; it < max_iterations; ++it) {
    // eq. (21b)/(22b): g(U_lin) + G (U - U_lin) <= 0  <=>  G U <= G U_lin - g(U_lin), the
    // product skipping G's zeros (the jerks a row does not depend on; the same bits)
    nmpc_internal::stackConstraints(model, problem, ws.linearization, ws.constraints,
                                    &ws.jacobian, true);
    model.jacobianProfile().multiplySubtract(ws.jacobian, ws.linearization, ws.constraints,
                                             ws.upper);
    if (has_terms && !linearizeCostTerms(problem)) return fall_back(IterationStatus::kFallback);
    ws.solver.setActiveSetGuess(active_set_.data(), active_count_);
    const qp::QpStatus status =
        ws.solver.solve(factor, gradient, ws.equality_matrix.topRows(me),
                        ws.equality_vector.head(me), ws.jacobian, ws.upper, ws.qp_solution);
    result.qp_iterations += ws.solver.iterations();
    result.qp_warm_start_updates += ws.solver.warmStartUpdates();
    ++result.sqp_iterations;
    if (status == qp::QpStatus::kOptimal && ws.qp_solution.allFinite()) {
      rememberActiveSet(ws.solver, mi);
    } else if (status == qp::QpStatus::kInfeasible) {
      // Relax in stages (Sec. III-D: the robot may get blocked, never unbalanced): obstacle
      // rows first, then kinematics too, balance last; each stage starts over from the QP.
      qp::QpStatus relaxed = qp::QpStatus::kInfeasible;
      for (RelaxationGroup stage : {RelaxationGroup::kObstacle, RelaxationGroup::kKinematics,
                                    RelaxationGroup::kBalance}) {
        bool any = false;
        for (int k = 0; k < model.familyCount() && !any; ++k)
          any = model.family(k).group() == stage && model.familyRowCount(k) > 0;
        if (!any) continue;
        relaxed = solveRelaxed(factor, gradient, me, settings.slack_weight, stage, result);
        if (relaxed != qp::QpStatus::kInfeasible) break;
      }
      if (relaxed == qp::QpStatus::kIterationLimit)
        return fall_back(IterationStatus::kIterationLimit);
      if (relaxed != qp::QpStatus::kOptimal) return fall_back(IterationStatus::kFallback);
    } else if (status == qp::QpStatus::kIterationLimit) {
      // The iterate at the cap is dual- but not primal-feasible: never execute it.
      return fall_back(IterationStatus::kIterationLimit);
    } else {
      return fall_back(IterationStatus::kFallback);  // invalid input or non-finite solution
    }
    result.last_step_norm = (ws.qp_solution - ws.linearization).cwiseAbs().maxCoeff();
    ws.linearization = ws.qp_solution;
    if (iterations == 0 && result.last_step_norm < settings.sqp_tolerance) break;
  }
  // To convergence but stopped by max_sqp_iterations: say so (a relaxed QP says more).
  if (iterations == 0 && result.last_step_norm >= settings.sqp_tolerance)
    raise(result, IterationStatus::kNotConverged);
  plan_ = ws.linearization;
  result.cost = totalCost(problem, plan_);
  return result;
}

NmpcSolveResult NmpcSolver::solve(const NmpcProblem& problem, const GeneratorSettings& settings) {
  model_->checkProblem(problem);
  return runSqp(problem, settings, settings.sqp_iterations, nullptr);
}

}  // namespace wpg
