#include "wpg/nmpc.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

namespace wpg {
namespace {

// Stack storage for per-sample temporaries (the horizon is at most 200 samples, validated).
using HorizonVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 200, 1>;

// Rectangle CoP polygon, Fig. 4: outward normals (+x, -x, +y, -y) of a_e' R(theta)(z - f) <= b_e.
constexpr double kCopNormal[4][2] = {{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}};

// Weight of 1/2 |F - F_fixed|^2 on the position of a fixed step that owns no CoP sample
// (standing): keeps the Hessian positive definite; zero at the solution (F = F_fixed).
constexpr double kFixedStepRegularization = 1.0;

// Pose (x, y, yaw) of a reference used by CoP sample rows and by step feasibility.
struct PoseRef {
  double x, y, yaw;
  int step;  // -1 = fixed (not a variable), else 0-based step index
};

PoseRef supportOfRow(const NmpcLayout& L, const NmpcProblem& problem,
                     const Eigen::Ref<const Eigen::VectorXd>& U, int row) {
  const int step = problem.phase.row_step(row) - 1;
  if (step < 0) {
    const auto& p = problem.phase.support_pose;
    return {p.x(), p.y(), p.z(), -1};
  }
  return {U(L.stepX() + step), U(L.stepY() + step), U(L.stepYaw() + step), step};
}

PoseRef previousOfStep(const NmpcLayout& L, const NmpcProblem& problem,
                       const Eigen::Ref<const Eigen::VectorXd>& U, int step) {
  if (step == 0) {
    const auto& p = problem.phase.support_pose;
    return {p.x(), p.y(), p.z(), -1};
  }
  return {U(L.stepX() + step - 1), U(L.stepY() + step - 1), U(L.stepYaw() + step - 1), step - 1};
}

bool hasRows(const PhaseStructure& phase, int step) {
  for (int j = 0; j < phase.row_step.size(); ++j)
    if (phase.row_step(j) == step + 1) return true;
  return false;
}

}  // namespace

// ------------------------------------------------------------------------------- model --

NmpcModel::NmpcModel(const WalkingParameters& parameters, int obstacle_slots)
    : parameters_(parameters) {
  if (obstacle_slots < 0) throw std::invalid_argument("obstacle slots: expected >= 0");
  parameters_.validate();
  const int N = parameters_.horizon_length;
  const int nf = parameters_.previewed_steps;
  std::string why;
  if (!feasibility_left_.setVertices(parameters_.feasibilityVertices(FootSide::kLeft), &why) ||
      !feasibility_right_.setVertices(parameters_.feasibilityVertices(FootSide::kRight), &why)) {
    throw std::invalid_argument("step feasibility polygon is " + why);
  }
  layout_.horizon = N;
  layout_.steps = nf;
  layout_.feasibility_edges = feasibility_left_.edgeCount();
  layout_.obstacle_slots = obstacle_slots;
  prediction_ = LipmPrediction(N, parameters_.sampling_period, parameters_.com_height,
                               parameters_.gravity);

  // J1's velocity: the mean over a window of K samples of the predicted velocities (K = 1:
  // the paper's instantaneous C'_{k+1}); the window of sample j reaches back to j - K + 1.
  const int K = parameters_.velocity_window_samples;
  Eigen::MatrixXd window = Eigen::MatrixXd::Zero(N, N);
  for (int j = 0; j < N; ++j)
    for (int i = std::max(0, j - K + 1); i <= j; ++i) window(j, i) = 1.0 / K;
  tracked_velocity_state_ = window * prediction_.velocity_state;
  tracked_velocity_jerk_ = window * prediction_.velocity_jerk;

  const double alpha = parameters_.weight_velocity;
  const double beta = parameters_.weight_cop;
  const double gamma = parameters_.weight_jerk;
  const int n = layout_.variableCount();
  const Eigen::MatrixXd& Pvu = tracked_velocity_jerk_;
  const Eigen::MatrixXd& Pzu = prediction_.cop_jerk;
  // Jerk block of J1, J3, J4 (eq. 5), the same for both axes and every pattern.
  const Eigen::MatrixXd jerk_block = alpha * Pvu.transpose() * Pvu +
                                     beta * Pzu.transpose() * Pzu +
                                     gamma * Eigen::MatrixXd::Identity(N, N);

  const int pattern_count = parameters_.stepSamples() + 1;
  hessians_.resize(pattern_count);
  factors_.resize(pattern_count);
  Eigen::VectorXi row_step(N);
  for (int pattern = 0; pattern < pattern_count; ++pattern) {
    rowStepsOf(pattern, row_step);
    Eigen::MatrixXd V = Eigen::MatrixXd::Zero(N, nf);  // eq. (4): samples x steps
    for (int j = 0; j < N; ++j)
      if (row_step(j) > 0) V(j, row_step(j) - 1) = 1.0;
    Eigen::MatrixXd step_block = beta * V.transpose() * V;
    for (int i = 0; i < nf; ++i)
      if (step_block(i, i) == 0.0) step_block(i, i) = kFixedStepRegularization;
    const Eigen::MatrixXd cross = -beta * Pzu.transpose() * V;  // J3 couples jerks and steps

    Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(n, n);
    for (int axis = 0; axis < 2; ++axis) {
      const int oj = axis == 0 ? layout_.jerkX() : layout_.jerkY();
      const int of = axis == 0 ? layout_.stepX() : layout_.stepY();
      Q.block(oj, oj, N, N) = jerk_block;
      Q.block(oj, of, N, nf) = cross;
      Q.block(of, oj, nf, N) = cross.transpose();
      Q.block(of, of, nf, nf) = step_block;
    }
    Q.block(layout_.stepYaw(), layout_.stepYaw(), nf, nf) =
        parameters_.weight_yaw * Eigen::MatrixXd::Identity(nf, nf);  // Q^theta of eq. (8)
    hessians_[pattern] = Q;
    if (!factors_[pattern].compute(Q))
      throw std::invalid_argument("NMPC Hessian is not positive definite (check the weights)");
  }
}

void NmpcModel::rowStepsOf(int pattern, Eigen::Ref<Eigen::VectorXi> row_step) const {
  const int S = parameters_.stepSamples();
  for (int j = 1; j <= layout_.horizon; ++j) {
    if (pattern == S) {
      row_step(j - 1) = 0;  // standing: every sample on the fixed double support
    } else {
      const int r = pattern;  // samples left on the current support, eq. (4)'s v selection
      row_step(j - 1) = j <= r ? 0 : (j - r - 1) / S + 1;
    }
  }
}

NmpcProblem NmpcModel::makeProblem() const {
  NmpcProblem problem;
  problem.phase.row_step = Eigen::VectorXi::Zero(layout_.horizon);
  problem.phase.step_fixed = Eigen::VectorXi::Zero(layout_.steps);
  problem.phase.fixed_step_pose = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, layout_.steps);
  problem.velocity_x = Eigen::VectorXd::Zero(layout_.horizon);
  problem.velocity_y = Eigen::VectorXd::Zero(layout_.horizon);
  problem.velocity_past_x = Eigen::VectorXd::Zero(layout_.horizon);
  problem.velocity_past_y = Eigen::VectorXd::Zero(layout_.horizon);
  problem.yaw_reference = Eigen::VectorXd::Zero(layout_.steps);
  problem.obstacle_slot = Eigen::VectorXi::Constant(layout_.obstacle_slots, -1);
  return problem;
}

// --------------------------------------------------------------------------------- cost --

void buildCostGradient(const NmpcModel& model, const NmpcProblem& problem,
                       Eigen::Ref<Eigen::VectorXd> gradient) {
  const NmpcLayout& L = model.layout();
  const LipmPrediction& P = model.prediction();
  const WalkingParameters& w = model.parameters();
  const int N = L.horizon, nf = L.steps;
  const PhaseStructure& phase = problem.phase;
  HorizonVector velocity_error(N), cop_offset(N);
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
        gradient(of + i) = -kFixedStepRegularization * phase.fixed_step_pose(axis, i);
  }
  // J2 with Q^theta = alpha I (eq. 8; weight_yaw): alpha/2 |F_theta - theta_ref|^2.
  gradient.segment(L.stepYaw(), nf) = -w.weight_yaw * problem.yaw_reference;
}

double evaluateCost(const NmpcModel& model, const NmpcProblem& problem,
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
      if (!hasRows(problem.phase, i)) {
        const double e = U(of + i) - problem.phase.fixed_step_pose(axis, i);
        fixed += e * e;
      }
  }
  j2 = (U.segment(L.stepYaw(), nf) - problem.yaw_reference).squaredNorm();
  return 0.5 * w.weight_velocity * j1 + 0.5 * w.weight_yaw * j2 + 0.5 * w.weight_cop * j3 +
         0.5 * w.weight_jerk * j4 + 0.5 * kFixedStepRegularization * fixed;
}

// -------------------------------------------------------------------------- constraints --

void evaluateObstacleConstraints(const NmpcModel& model, const NmpcProblem& problem,
                                 const Eigen::Ref<const Eigen::VectorXd>& U,
                                 Eigen::Ref<Eigen::VectorXd> g, Eigen::MatrixXd* jacobian);

void evaluateConstraints(const NmpcModel& model, const NmpcProblem& problem,
                         const Eigen::Ref<const Eigen::VectorXd>& U,
                         Eigen::Ref<Eigen::VectorXd> g, Eigen::MatrixXd* jacobian) {
  const NmpcLayout& L = model.layout();
  const LipmPrediction& P = model.prediction();
  const WalkingParameters& w = model.parameters();
  const PhaseStructure& phase = problem.phase;
  const int N = L.horizon, nf = L.steps;
  if (jacobian) jacobian->setZero();
  const auto jerk_x = U.segment(L.jerkX(), N);
  const auto jerk_y = U.segment(L.jerkY(), N);

  // CoP in the support polygon, eq. (9)-(13): a_e' R(theta_j) (z_j - f_j) <= b_e with
  // R(theta) = [c s; -s c] (eq. 11). Writing w = R(theta)' a_e,
  //   g = w_x dx + w_y dy - b_e,  d = z_j - f_j = Pzs c_hat + Pzu jerk - f_j,
  //   dg/dtheta = w'_x dx + w'_y dy, which depends on the current CoM state through z_j.
  for (int j = 0; j < N; ++j) {
    const double zx = P.cop_state.row(j).dot(problem.com_x) +
                      P.cop_jerk.row(j).head(j + 1).dot(jerk_x.head(j + 1));
    const double zy = P.cop_state.row(j).dot(problem.com_y) +
                      P.cop_jerk.row(j).head(j + 1).dot(jerk_y.head(j + 1));
    const PoseRef f = supportOfRow(L, problem, U, j);
    const double half_length = f.step < 0 ? phase.support_half_length : w.copHalfLength();
    const double half_width = f.step < 0 ? phase.support_half_width : w.copHalfWidth();
    const double bound[4] = {half_length, half_length, half_width, half_width};
    const double dx = zx - f.x, dy = zy - f.y;
    const double c = std::cos(f.yaw), s = std::sin(f.yaw);
    for (int e = 0; e < NmpcLayout::kCopEdges; ++e) {
      const double a1 = kCopNormal[e][0], a2 = kCopNormal[e][1];
      const double wx = a1 * c - a2 * s, wy = a1 * s + a2 * c;
      const int row = L.copRow(j, e);
      g(row) = wx * dx + wy * dy - bound[e];
      if (!jacobian) continue;
      auto G = jacobian->row(row);
      G.segment(L.jerkX(), j + 1) = wx * P.cop_jerk.row(j).head(j + 1);
      G.segment(L.jerkY(), j + 1) = wy * P.cop_jerk.row(j).head(j + 1);
      if (f.step >= 0) {
        const double dwx = -a1 * s - a2 * c, dwy = a1 * c - a2 * s;
        G(L.stepX() + f.step) = -wx;
        G(L.stepY() + f.step) = -wy;
        G(L.stepYaw() + f.step) = dwx * dx + dwy * dy;
      }
    }
  }

  // Step feasibility, eq. (14)-(15): a_e' R(theta_prev) (F_i - F_prev) <= b_e, and the yaw
  // bound (16)-(17): |theta_i - theta_prev| <= theta_max. Rows of fixed steps are inactive.
  for (int i = 0; i < nf; ++i) {
    const ConvexPolygon& polygon = model.feasibilityPolygon(phase.stepSide(i));
    if (phase.step_fixed(i)) {
      for (int e = 0; e < L.feasibility_edges; ++e) g(L.feasibilityRow(i, e)) = -1.0;
      g(L.yawRow(i, true)) = -1.0;
      g(L.yawRow(i, false)) = -1.0;
      continue;
    }
    const PoseRef prev = previousOfStep(L, problem, U, i);
    const double dx = U(L.stepX() + i) - prev.x, dy = U(L.stepY() + i) - prev.y;
    const double c = std::cos(prev.yaw), s = std::sin(prev.yaw);
    for (int e = 0; e < L.feasibility_edges; ++e) {
      const double a1 = polygon.normals()(e, 0), a2 = polygon.normals()(e, 1);
      const double wx = a1 * c - a2 * s, wy = a1 * s + a2 * c;
      const int row = L.feasibilityRow(i, e);
      g(row) = wx * dx + wy * dy - polygon.offsets()(e);
      if (!jacobian) continue;
      auto G = jacobian->row(row);
      G(L.stepX() + i) = wx;
      G(L.stepY() + i) = wy;
      if (prev.step >= 0) {
        const double dwx = -a1 * s - a2 * c, dwy = a1 * c - a2 * s;
        G(L.stepX() + prev.step) = -wx;
        G(L.stepY() + prev.step) = -wy;
        G(L.stepYaw() + prev.step) = dwx * dx + dwy * dy;
      }
    }
    const double yaw_change = U(L.stepYaw() + i) - prev.yaw;
    g(L.yawRow(i, true)) = yaw_change - w.max_step_yaw_change;
    g(L.yawRow(i, false)) = -yaw_change - w.max_step_yaw_change;
    if (jacobian) {
      (*jacobian)(L.yawRow(i, true), L.stepYaw() + i) = 1.0;
      (*jacobian)(L.yawRow(i, false), L.stepYaw() + i) = -1.0;
      if (prev.step >= 0) {
        (*jacobian)(L.yawRow(i, true), L.stepYaw() + prev.step) = -1.0;
        (*jacobian)(L.yawRow(i, false), L.stepYaw() + prev.step) = 1.0;
      }
    }
  }
  if (L.obstacle_slots > 0) evaluateObstacleConstraints(model, problem, U, g, jacobian);
}

// Obstacle rows (18)-(19), one per previewed step and obstacle slot.
void evaluateObstacleConstraints(const NmpcModel& model, const NmpcProblem& problem,
                                 const Eigen::Ref<const Eigen::VectorXd>& U,
                                 Eigen::Ref<Eigen::VectorXd> g, Eigen::MatrixXd* jacobian) {
  const NmpcLayout& L = model.layout();
  for (int i = 0; i < L.steps; ++i) {
    for (int k = 0; k < L.obstacle_slots; ++k) {
      const int row = L.obstacleRow(i, k);
      const int index = problem.obstacle_slot(k);
      if (index < 0 || problem.phase.step_fixed(i)) {
        g(row) = -1.0;  // empty slot, or a step that can no longer move
        continue;
      }
      const Obstacle& obstacle = (*problem.obstacles)[index];
      const Eigen::Vector2d F(U(L.stepX() + i), U(L.stepY() + i));
      Eigen::Vector2d dg;
      const double margin = obstacle.margin + model.parameters().obstacle_foot_radius;
      if (obstacle.type == ObstacleType::kCircle) {
        // eq. (18): (F - c)^2 >= (R + m)^2  <=>  g = (R + m)^2 - |F - c|^2 <= 0, with m the
        // obstacle's margin grown by the sole's radius (obstacle_foot_radius)
        const Eigen::Vector2d d = F - obstacle.center;
        const double r = obstacle.radius + margin;
        g(row) = r * r - d.squaredNorm();
        dg = -2.0 * d;
      } else {
        // d(F) >= m  <=>  g = m - d(F) <= 0, with d the signed distance to the convex shape
        Eigen::Vector2d gradient;
        g(row) = margin - problem.distance->signedDistance(index, F, &gradient);
        dg = -gradient;
      }
      if (jacobian) {
        (*jacobian)(row, L.stepX() + i) = dg.x();
        (*jacobian)(row, L.stepY() + i) = dg.y();
      }
    }
  }
}

int buildStepEqualities(const NmpcModel& model, const NmpcProblem& problem,
                        Eigen::Ref<Eigen::MatrixXd> E, Eigen::Ref<Eigen::VectorXd> e) {
  const NmpcLayout& L = model.layout();
  int rows = 0;
  for (int i = 0; i < L.steps; ++i) {
    if (!problem.phase.step_fixed(i)) continue;
    const int columns[3] = {L.stepX() + i, L.stepY() + i, L.stepYaw() + i};
    for (int k = 0; k < 3; ++k) {
      E.row(rows).setZero();
      E(rows, columns[k]) = 1.0;
      e(rows) = problem.phase.fixed_step_pose(k, i);
      ++rows;
    }
  }
  return rows;
}

// ---------------------------------------------------------------------------- workspace --

NmpcWorkspace::NmpcWorkspace(const NmpcModel& model)
    : solver(model.layout().variableCount(), model.layout().maxEqualityCount(),
             model.layout().inequalityCount()),
      relaxed_solver(model.layout().variableCount() + 1, model.layout().maxEqualityCount(),
                     model.layout().inequalityCount() + 1),
      orientation_solver(model.layout().steps, model.layout().steps, 2 * model.layout().steps) {
  const NmpcLayout& L = model.layout();
  const int n = L.variableCount(), mi = L.inequalityCount(), me = L.maxEqualityCount();
  const int nf = L.steps;
  U = Eigen::VectorXd::Zero(n);
  linearization = Eigen::VectorXd::Zero(n);
  gradient = Eigen::VectorXd::Zero(n);
  jacobian = Eigen::MatrixXd::Zero(mi, n);
  constraints = Eigen::VectorXd::Zero(mi);
  upper = Eigen::VectorXd::Zero(mi);
  equality_matrix = Eigen::MatrixXd::Zero(me, n);
  equality_vector = Eigen::VectorXd::Zero(me);
  qp_solution = Eigen::VectorXd::Zero(n);
  relaxed_factor.inverse_factor_transposed = Eigen::MatrixXd::Zero(n + 1, n + 1);
  relaxed_factor.size = n + 1;
  relaxed_jacobian = Eigen::MatrixXd::Zero(mi + 1, n + 1);
  relaxed_equality_matrix = Eigen::MatrixXd::Zero(me, n + 1);
  relaxed_gradient = Eigen::VectorXd::Zero(n + 1);
  relaxed_upper = Eigen::VectorXd::Zero(mi + 1);
  relaxed_solution = Eigen::VectorXd::Zero(n + 1);
  orientation_factor.compute(model.parameters().weight_yaw * Eigen::MatrixXd::Identity(nf, nf));
  orientation_inequalities = Eigen::MatrixXd::Zero(2 * nf, nf);
  orientation_equalities = Eigen::MatrixXd::Zero(nf, nf);
  orientation_upper = Eigen::VectorXd::Zero(2 * nf);
  orientation_equality_vector = Eigen::VectorXd::Zero(nf);
  orientation_gradient = Eigen::VectorXd::Zero(nf);
  orientation_solution = Eigen::VectorXd::Zero(nf);
  active_set = Eigen::VectorXi::Zero(mi + 1);
}

void NmpcWorkspace::shiftActiveSet(const NmpcLayout& L, bool step_completed) {
  const int cop_rows = NmpcLayout::kCopEdges * L.horizon;
  const int feasibility_rows = L.feasibility_edges * L.steps;
  const int obstacle_start = L.firstObstacleRow();
  int kept = 0;
  for (int k = 0; k < active_count; ++k) {
    int row = active_set(k);
    if (row < cop_rows) {
      row -= NmpcLayout::kCopEdges;  // the sample j becomes sample j - 1
    } else if (step_completed && row < cop_rows + feasibility_rows) {
      row -= L.feasibility_edges;    // step i becomes step i - 1
      if (row < cop_rows) row = -1;
    } else if (step_completed && row < obstacle_start) {
      row -= 2;
      if (row < cop_rows + feasibility_rows) row = -1;
    } else if (step_completed) {
      row -= L.obstacle_slots;
      if (row < obstacle_start) row = -1;
    }
    if (row >= 0) active_set(kept++) = row;
  }
  active_count = kept;
}

// ---------------------------------------------------------------------------------- SQP --
namespace {

void rememberActiveSet(const qp::DenseQpSolver& solver, int inequality_rows, NmpcWorkspace& ws) {
  ws.active_count = 0;
  for (int k = 0; k < solver.activeInequalityCount(); ++k) {
    const int row = solver.activeInequalities()[k];
    if (row < inequality_rows) ws.active_set(ws.active_count++) = row;
  }
}

// One slack s >= 0 on the soft rows (from first_soft_row on), cost rho s + rho/2 s^2. With
// every row soft the relaxed QP is always feasible; s = 0 whenever the original QP is.
qp::QpStatus solveRelaxed(const qp::HessianFactor& factor, int me, double rho, int first_soft_row,
                          NmpcWorkspace& ws, double* slack) {
  const int n = static_cast<int>(ws.gradient.size());
  const int mi = static_cast<int>(ws.upper.size());
  auto& J = ws.relaxed_factor.inverse_factor_transposed;
  J.topLeftCorner(n, n) = factor.inverse_factor_transposed;
  J(n, n) = 1.0 / std::sqrt(rho);
  ws.relaxed_gradient.head(n) = ws.gradient;
  ws.relaxed_gradient(n) = rho;
  ws.relaxed_jacobian.topLeftCorner(mi, n) = ws.jacobian;
  ws.relaxed_jacobian.col(n).head(first_soft_row).setZero();
  ws.relaxed_jacobian.col(n).segment(first_soft_row, mi - first_soft_row).setConstant(-1.0);
  ws.relaxed_jacobian(mi, n) = -1.0;
  ws.relaxed_upper.head(mi) = ws.upper;
  ws.relaxed_upper(mi) = 0.0;
  ws.relaxed_equality_matrix.topLeftCorner(me, n) = ws.equality_matrix.topRows(me);
  ws.relaxed_solver.setActiveSetGuess(ws.active_set.data(), ws.active_count);
  const qp::QpStatus status = ws.relaxed_solver.solve(
      ws.relaxed_factor, ws.relaxed_gradient, ws.relaxed_equality_matrix.topRows(me),
      ws.equality_vector.head(me), ws.relaxed_jacobian, ws.relaxed_upper, ws.relaxed_solution);
  *slack = ws.relaxed_solution(n);
  return status;
}

// Gauss-Newton iterations; when fixed_yaws is given, the free step yaws are fixed to it by
// equalities (the LMPC position QP).
NmpcSolveResult runSqp(const NmpcModel& model, const NmpcProblem& problem,
                       const GeneratorSettings& settings, NmpcWorkspace& ws, int iterations,
                       const Eigen::VectorXd* fixed_yaws) {
  const NmpcLayout& L = model.layout();
  const int mi = L.inequalityCount();
  const qp::HessianFactor& factor = model.hessianFactor(problem.phase.pattern);
  NmpcSolveResult result;

  buildCostGradient(model, problem, ws.gradient);
  int me = buildStepEqualities(model, problem, ws.equality_matrix, ws.equality_vector);
  ws.linearization = ws.U;
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
    // eq. (21b)/(22b): g(U_lin) + G (U - U_lin) <= 0  <=>  G U <= G U_lin - g(U_lin)
    evaluateConstraints(model, problem, ws.linearization, ws.constraints, &ws.jacobian);
    ws.upper.noalias() = ws.jacobian * ws.linearization;
    ws.upper -= ws.constraints;
    ws.solver.setActiveSetGuess(ws.active_set.data(), ws.active_count);
    qp::QpStatus status =
        ws.solver.solve(factor, ws.gradient, ws.equality_matrix.topRows(me),
                        ws.equality_vector.head(me), ws.jacobian, ws.upper, ws.qp_solution);
    result.qp_iterations += ws.solver.iterations();
    ++result.sqp_iterations;
    if (status == qp::QpStatus::kOptimal) {
      rememberActiveSet(ws.solver, mi, ws);
    } else if (status == qp::QpStatus::kInfeasible) {
      // Relax the obstacle rows first (paper: the robot may get blocked, never unbalanced),
      // then every row.
      double slack = 0.0;
      status = qp::QpStatus::kInfeasible;
      if (L.obstacle_slots > 0) {
        status = solveRelaxed(factor, me, settings.slack_weight, L.firstObstacleRow(), ws, &slack);
        result.qp_iterations += ws.relaxed_solver.iterations();
      }
      if (status != qp::QpStatus::kOptimal) {
        status = solveRelaxed(factor, me, settings.slack_weight, 0, ws, &slack);
        result.qp_iterations += ws.relaxed_solver.iterations();
      }
      if (status != qp::QpStatus::kOptimal || !ws.relaxed_solution.allFinite()) {
        result.status = IterationStatus::kFallback;  // keep the time-shifted previous plan
        result.cost = evaluateCost(model, problem, ws.U);
        return result;
      }
      rememberActiveSet(ws.relaxed_solver, mi, ws);
      ws.qp_solution = ws.relaxed_solution.head(L.variableCount());
      result.status = IterationStatus::kRelaxed;
      result.slack = std::max(result.slack, slack);
    } else {
      if (!ws.qp_solution.allFinite()) {
        result.status = IterationStatus::kFallback;
        result.cost = evaluateCost(model, problem, ws.U);
        return result;
      }
      if (result.status == IterationStatus::kSolved)
        result.status = IterationStatus::kIterationLimit;
    }
    result.last_step_norm = (ws.qp_solution - ws.linearization).cwiseAbs().maxCoeff();
    ws.linearization = ws.qp_solution;
    if (iterations == 0 && result.last_step_norm < settings.sqp_tolerance) break;
  }
  // To convergence but stopped by max_sqp_iterations: say so (a relaxed or failed QP says more).
  if (iterations == 0 && result.last_step_norm >= settings.sqp_tolerance &&
      result.status == IterationStatus::kSolved)
    result.status = IterationStatus::kNotConverged;
  ws.U = ws.linearization;
  result.cost = evaluateCost(model, problem, ws.U);
  return result;
}

}  // namespace

NmpcSolveResult solveNmpc(const NmpcModel& model, const NmpcProblem& problem,
                          const GeneratorSettings& settings, NmpcWorkspace& workspace) {
  return runSqp(model, problem, settings, workspace, settings.sqp_iterations, nullptr);
}

NmpcSolveResult solveLmpc(const NmpcModel& model, const NmpcProblem& problem,
                          const GeneratorSettings& settings, NmpcWorkspace& ws) {
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
    ws.orientation_solution = ws.U.segment(L.stepYaw(), nf);
  }
  // Position QP with those yaws: constraints are linear in (jerks, positions) once the yaws
  // are fixed, so one QP linearized at theta = theta* is exact.
  NmpcSolveResult result = runSqp(model, problem, settings, ws, 1, &ws.orientation_solution);
  result.qp_iterations += orientation_iterations;
  return result;
}

}  // namespace wpg
