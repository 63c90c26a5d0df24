// The NMPC's cost, eq. (5)-(8): its linear term per sample and its value.
#include "wpg/nmpc/cost.hpp"

#include <stdexcept>
#include <string>

#include "nmpc_internal.hpp"

namespace wpg {
namespace {

// The public entry points below: a vector of one entry per variable of U, and a problem of
// the model's sizes (NmpcModel::checkProblem); else std::invalid_argument.
void checkSizes(const char* function, const char* vector, Eigen::Index size,
                const NmpcModel& model, const NmpcProblem& problem) {
  if (size != model.layout().variableCount()) {
    throw std::invalid_argument(std::string(function) + ": expected " + vector + " of " +
                                std::to_string(model.layout().variableCount()) +
                                " entries, got " + std::to_string(size));
  }
  model.checkProblem(problem);
}

}  // namespace

void buildCostGradient(const NmpcModel& model, const NmpcProblem& problem,
                       Eigen::Ref<Eigen::VectorXd> gradient) {
  checkSizes("buildCostGradient", "a gradient", gradient.size(), model, problem);
  nmpc_internal::costGradient(model, problem, gradient);
}

double evaluateCost(const NmpcModel& model, const NmpcProblem& problem,
                    const Eigen::Ref<const Eigen::VectorXd>& U) {
  checkSizes("evaluateCost", "U", U.size(), model, problem);
  const double cost = nmpc_internal::cost(model, problem, U);
  if (model.costTermCount() == 0) return cost;
  Eigen::VectorXd residuals(model.residualCount());  // allocates: not the solver's path
  nmpc_internal::stackResiduals(model, problem, U, residuals, nullptr);
  return cost + 0.5 * residuals.squaredNorm();
}

void nmpc_internal::costGradient(const NmpcModel& model, const NmpcProblem& problem,
                                 Eigen::Ref<Eigen::VectorXd> gradient) {
  const NmpcLayout& L = model.layout();
  const LipmPrediction& P = model.prediction();
  const WalkingParameters& w = model.parameters();
  const int N = L.horizon, nf = L.steps;
  const PhaseStructure& phase = problem.phase;
  nmpc_internal::HorizonVector velocity_error(N), cop_offset(N);
  for (int axis = 0; axis < 2; ++axis) {
    const Eigen::Vector3d& c_hat = axis == 0 ? problem.com_x : problem.com_y;
    const Eigen::VectorXd& v_ref = axis == 0 ? problem.velocity_x : problem.velocity_y;
    const double support = phase.support_pose(axis);
    // J1 residual: Pvu jerk - (v_ref - Pvs c_hat - past) with the tracked (windowed)
    // velocity rows; J3 residual: Pzu jerk - V F - t with t = v f_k - Pzs c_hat (eq. 12).
    velocity_error = v_ref;
    velocity_error -= axis == 0 ? problem.velocity_past_x : problem.velocity_past_y;
    velocity_error.noalias() -= model.trackedVelocityState() * c_hat;
    cop_offset.noalias() = -P.cop_state * c_hat;
    for (int j = 0; j < N; ++j)
      if (phase.row_step(j) == 0) cop_offset(j) += support;
    const int oj = axis == 0 ? L.jerkX() : L.jerkY();
    const int of = axis == 0 ? L.stepX() : L.stepY();
    auto g_jerk = gradient.segment(oj, N);
    g_jerk.noalias() = -w.weight_velocity * model.trackedVelocityJerk().transpose() * velocity_error;
    g_jerk.noalias() -= w.weight_cop * P.cop_jerk.transpose() * cop_offset;
    for (int i = 0; i < nf; ++i) gradient(of + i) = 0.0;
    bool has_rows[16] = {false};
    for (int j = 0; j < N; ++j) {
      const int step = phase.row_step(j) - 1;
      if (step >= 0) {
        gradient(of + step) += w.weight_cop * cop_offset(j);
        has_rows[step] = true;
      }
    }
    for (int i = 0; i < nf; ++i)
      if (!has_rows[i])
        gradient(of + i) = -nmpc_internal::kFixedStepRegularization * phase.fixed_step_pose(axis, i);
  }
  // J2 with Q^theta = alpha I (eq. 8; weight_yaw): alpha/2 |F_theta - theta_ref|^2.
  gradient.segment(L.stepYaw(), nf) = -w.weight_yaw * problem.yaw_reference;
}

double nmpc_internal::cost(const NmpcModel& model, const NmpcProblem& problem,
                           const Eigen::Ref<const Eigen::VectorXd>& U) {
  const NmpcLayout& L = model.layout();
  const LipmPrediction& P = model.prediction();
  const WalkingParameters& w = model.parameters();
  const int N = L.horizon, nf = L.steps;
  double j1 = 0.0, j2 = 0.0, j3 = 0.0, j4 = 0.0, fixed = 0.0;
  for (int axis = 0; axis < 2; ++axis) {
    const Eigen::Vector3d& c_hat = axis == 0 ? problem.com_x : problem.com_y;
    const Eigen::VectorXd& v_ref = axis == 0 ? problem.velocity_x : problem.velocity_y;
    const int oj = axis == 0 ? L.jerkX() : L.jerkY();
    const int of = axis == 0 ? L.stepX() : L.stepY();
    const auto jerk = U.segment(oj, N);
    for (int j = 0; j < N; ++j) {
      const Eigen::VectorXd& past = axis == 0 ? problem.velocity_past_x : problem.velocity_past_y;
      const double velocity =
          model.trackedVelocityState().row(j).dot(c_hat) +
          model.trackedVelocityJerk().row(j).head(j + 1).dot(jerk.head(j + 1)) + past(j);
      const double cop = P.cop_state.row(j).dot(c_hat) +
                         P.cop_jerk.row(j).head(j + 1).dot(jerk.head(j + 1));
      const int step = problem.phase.row_step(j) - 1;
      const double foot = step < 0 ? problem.phase.support_pose(axis) : U(of + step);
      j1 += (velocity - v_ref(j)) * (velocity - v_ref(j));
      j3 += (cop - foot) * (cop - foot);
    }
    j4 += jerk.squaredNorm();
    for (int i = 0; i < nf; ++i)
      if (!problem.phase.stepOwnsSamples(i)) {
        const double e = U(of + i) - problem.phase.fixed_step_pose(axis, i);
        fixed += e * e;
      }
  }
  j2 = (U.segment(L.stepYaw(), nf) - problem.yaw_reference).squaredNorm();
  return 0.5 * w.weight_velocity * j1 + 0.5 * w.weight_yaw * j2 + 0.5 * w.weight_cop * j3 +
         0.5 * w.weight_jerk * j4 + 0.5 * nmpc_internal::kFixedStepRegularization * fixed;
}

}  // namespace wpg
