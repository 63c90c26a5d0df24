// The Herdt et al. 2010 linear MPC, the paper's baseline: the step yaws first (an orientation
// QP on J2 with the yaw bounds), then the position QP with those yaws fixed, through the same
// SQP machinery as the NMPC (one QP: linear once the yaws are fixed).
#include "wpg/nmpc/solver.hpp"

namespace wpg {

NmpcSolveResult NmpcSolver::solveLmpc(const NmpcProblem& problem,
                                      const GeneratorSettings& settings) {
  const NmpcModel& model = *model_;
  model.checkProblem(problem);
  NmpcWorkspace& ws = workspace_;
  const NmpcLayout& L = model.layout();
  const PhaseStructure& phase = problem.phase;
  const double bound = model.parameters().max_step_yaw_change;
  const int nf = L.steps;
  // Orientation QP: min alpha/2 |theta - theta_ref|^2 s.t. |theta_i - theta_{i-1}| <= bound.
  ws.orientation_gradient = -model.parameters().weight_yaw * problem.yaw_reference;
  ws.orientation_inequalities.setZero();
  ws.orientation_upper.setConstant(1.0);  // inactive rows: 0 <= 1
  int me = 0;
  for (int i = 0; i < nf; ++i) {
    if (phase.step_fixed(i)) {
      ws.orientation_equalities.row(me).setZero();
      ws.orientation_equalities(me, i) = 1.0;
      ws.orientation_equality_vector(me) = phase.fixed_step_pose(2, i);
      ++me;
      continue;
    }
    const double previous_fixed = i == 0 ? phase.support_pose.z() : 0.0;
    ws.orientation_inequalities(2 * i, i) = 1.0;
    ws.orientation_inequalities(2 * i + 1, i) = -1.0;
    if (i > 0) {
      ws.orientation_inequalities(2 * i, i - 1) = -1.0;
      ws.orientation_inequalities(2 * i + 1, i - 1) = 1.0;
    }
    ws.orientation_upper(2 * i) = bound + previous_fixed;
    ws.orientation_upper(2 * i + 1) = bound - previous_fixed;
  }
  ws.orientation_solver.settings().max_iterations = settings.max_qp_iterations;
  const qp::QpStatus status = ws.orientation_solver.solve(
      ws.orientation_factor, ws.orientation_gradient, ws.orientation_equalities.topRows(me),
      ws.orientation_equality_vector.head(me), ws.orientation_inequalities, ws.orientation_upper,
      ws.orientation_solution);
  const int orientation_iterations = ws.orientation_solver.iterations();
  if (status != qp::QpStatus::kOptimal) {
    // Cannot happen with consistent fixed yaws; keep the previous yaws rather than fail.
    ws.orientation_solution = plan_.segment(L.stepYaw(), nf);
  }
  // Position QP with those yaws: constraints are linear in (jerks, positions) once the yaws
  // are fixed, so one QP linearized at theta = theta* is exact.
  NmpcSolveResult result = runSqp(problem, settings, 1, &ws.orientation_solution);
  result.qp_iterations += orientation_iterations;
  return result;
}

}  // namespace wpg
