// The constant part of the NMPC: prediction, Hessians per walking pattern, constraint families.
#include "wpg/nmpc/model.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

#include "nmpc_internal.hpp"
#include "wpg/nmpc/builtin_families.hpp"

namespace wpg {

const char* relaxationGroupName(RelaxationGroup group) {
  constexpr const char* kNames[] = {"obstacle", "kinematics", "balance"};  // enum order
  const auto index = static_cast<unsigned>(group);
  return index < 3 ? kNames[index] : "unknown";
}

NmpcModel::NmpcModel(const WalkingParameters& parameters, int obstacle_slots,
                     qp::HessianFactorCache* hessian_factors)
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
  // Mirror images (feasibilityVertices): the same edge count, the step feasibility rows' stride.
  eigen_assert(feasibility_left_.edgeCount() == feasibility_right_.edgeCount());
  layout_.horizon = N;
  layout_.steps = nf;
  obstacle_slots_ = obstacle_slots;
  prediction_ = LipmPrediction(N, parameters_.sampling_period, parameters_.com_height,
                               parameters_.gravity);

  // The paper's families. Their order is the order of the QP's rows, which breaks the active-set
  // method's ties between equally violated rows: another order walks differently in the last
  // bits.
  family_first_row_.push_back(0);
  appendFamily(makeCopConstraint());
  appendFamily(makeStepFeasibilityConstraint());
  appendFamily(makeYawBoundConstraint());
  appendFamily(makeObstacleConstraint());
  appendFamily(makeLandingBoundConstraint());
  appendFamily(makeLandingYawBoundConstraint());
  // wpg's swing reach only when on: a model holds at most kMaxConstraintFamilies (the 8 bits
  // of each iteration's relaxed-family mask), and the paper's formulation (both limits 0)
  // keeps its six families and room for two of the caller's.
  if (SwingReachRows::count(*this) > 0) appendFamily(makeSwingReachConstraint());
  updateJacobianProfile();

  // J1's velocity: the mean over a window of K samples of the predicted velocities (K = 1:
  // the paper's instantaneous C'_{k+1}); the window of sample j reaches back to j - K + 1.
  const int K = parameters_.trackedVelocityWindow();
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
      if (step_block(i, i) == 0.0) step_block(i, i) = nmpc_internal::kFixedStepRegularization;
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
    if (hessian_factors) {
      factors_[pattern] = hessian_factors->factor(Q);
    } else if (auto factor = std::make_shared<qp::HessianFactor>(); factor->compute(Q)) {
      factors_[pattern] = std::move(factor);
    }
    if (!factors_[pattern])
      throw std::invalid_argument("NMPC Hessian is not positive definite (check the weights)");
  }
}

void NmpcModel::addConstraintFamily(std::shared_ptr<const ConstraintFamily> family) {
  appendFamily(std::move(family));
  updateJacobianProfile();
}

void NmpcModel::appendFamily(std::shared_ptr<const ConstraintFamily> family) {
  if (!family) throw std::invalid_argument("constraint family: expected a family, got null");
  if (familyCount() >= kMaxConstraintFamilies) {
    throw std::invalid_argument("constraint family '" + std::string(family->name()) +
                                "': at most " + std::to_string(kMaxConstraintFamilies) +
                                " families per model");
  }
  const int rows = family->rowCount(*this);
  if (rows < 0) throw std::invalid_argument("constraint family: negative row count");
  families_.push_back(std::move(family));
  family_first_row_.push_back(family_first_row_.back() + rows);
}

void NmpcModel::addCostTerm(std::shared_ptr<const CostTerm> term) {
  if (!term) throw std::invalid_argument("cost term: expected a term, got null");
  const int residuals = term->residualCount(*this);
  if (residuals < 0) {
    throw std::invalid_argument("cost term '" + std::string(term->name()) +
                                "': negative residual count");
  }
  cost_terms_.push_back(std::move(term));
  term_first_residual_.push_back(term_first_residual_.back() + residuals);
}

int ConstraintFamily::jerkSamplesOfRow(const NmpcModel& model, int) const {
  return model.layout().horizon;
}

void NmpcModel::updateJacobianProfile() {
  const NmpcLayout& L = layout_;
  const int N = L.horizon, m = inequalityCount();
  // Steps: every row. Jerks: the rows that reach them, none to begin with ([m, 0) is empty).
  Eigen::VectorXi first = Eigen::VectorXi::Zero(L.variableCount());
  Eigen::VectorXi end = Eigen::VectorXi::Constant(L.variableCount(), m);
  Eigen::VectorXi jerk_first = Eigen::VectorXi::Constant(N, m), jerk_end = Eigen::VectorXi::Zero(N);
  for (int k = 0; k < familyCount(); ++k) {
    for (int local = 0; local < familyRowCount(k); ++local) {
      const int row = familyFirstRow(k) + local;
      const int samples = std::clamp(family(k).jerkSamplesOfRow(*this, local), 0, N);
      for (int j = 0; j < samples; ++j) {
        jerk_first(j) = std::min(jerk_first(j), row);
        jerk_end(j) = std::max(jerk_end(j), row + 1);
      }
    }
  }
  first.segment(L.jerkX(), N) = first.segment(L.jerkY(), N) = jerk_first;
  end.segment(L.jerkX(), N) = end.segment(L.jerkY(), N) = jerk_end;
  jacobian_profile_ = qp::ColumnProfile(m, first, end);
}

int NmpcModel::findFamily(const char* name) const {
  for (int k = 0; k < familyCount(); ++k)
    if (name && std::strcmp(families_[k]->name(), name) == 0) return k;
  return -1;
}

std::vector<ConstraintFamilyInfo> NmpcModel::familyInfo() const {
  std::vector<ConstraintFamilyInfo> info;
  for (const auto& family : families_)
    info.push_back({family->name(), family->unit(), relaxationGroupName(family->group())});
  return info;
}

void NmpcModel::checkProblem(const NmpcProblem& problem) const {
  const int N = layout_.horizon, nf = layout_.steps;
  auto require = [](bool ok, const char* field, long expected, long got) {
    if (!ok) {
      throw std::invalid_argument(std::string("NMPC problem: '") + field + "': expected " +
                                  std::to_string(expected) + " entries, got " +
                                  std::to_string(got));
    }
  };
  const PhaseStructure& phase = problem.phase;
  require(phase.row_step.size() == N, "phase.row_step", N, phase.row_step.size());
  require(phase.step_fixed.size() == nf, "phase.step_fixed", nf, phase.step_fixed.size());
  require(phase.fixed_step_pose.cols() == nf, "phase.fixed_step_pose (columns)", nf,
          phase.fixed_step_pose.cols());
  require(problem.velocity_x.size() == N, "velocity_x", N, problem.velocity_x.size());
  require(problem.velocity_y.size() == N, "velocity_y", N, problem.velocity_y.size());
  require(problem.velocity_past_x.size() == N, "velocity_past_x", N, problem.velocity_past_x.size());
  require(problem.velocity_past_y.size() == N, "velocity_past_y", N, problem.velocity_past_y.size());
  require(problem.yaw_reference.size() == nf, "yaw_reference", nf, problem.yaw_reference.size());
  require(problem.obstacle_slot.size() == obstacle_slots_, "obstacle_slot", obstacle_slots_,
          problem.obstacle_slot.size());
  require(problem.obstacle_normal.cols() == obstacle_slots_, "obstacle_normal (columns)",
          obstacle_slots_, problem.obstacle_normal.cols());
  require(problem.obstacle_offset.size() == obstacle_slots_, "obstacle_offset", obstacle_slots_,
          problem.obstacle_offset.size());
  require(problem.obstacle_landing_normal.cols() == obstacle_slots_,
          "obstacle_landing_normal (columns)", obstacle_slots_,
          problem.obstacle_landing_normal.cols());
  require(problem.obstacle_landing_offset.size() == obstacle_slots_, "obstacle_landing_offset",
          obstacle_slots_, problem.obstacle_landing_offset.size());
  if (phase.pattern < 0 || phase.pattern >= patternCount()) {
    throw std::invalid_argument("NMPC problem: 'phase.pattern': expected 0 to " +
                                std::to_string(patternCount() - 1) + ", got " +
                                std::to_string(phase.pattern));
  }
  const int obstacles = problem.obstacles ? problem.obstacles->obstacleCount() : 0;
  for (int k = 0; k < problem.obstacle_slot.size(); ++k) {
    const int index = problem.obstacle_slot(k);
    if (index >= obstacles) {
      throw std::invalid_argument("NMPC problem: 'obstacle_slot[" + std::to_string(k) +
                                  "]': expected -1 or an index below the " +
                                  std::to_string(obstacles) + " obstacles, got " +
                                  std::to_string(index));
    }
  }
}

int NmpcModel::familyOfRow(int row) const {
  for (int k = 0; k < familyCount(); ++k)
    if (row < family_first_row_[k + 1]) return k;
  return -1;
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
  problem.obstacle_slot = Eigen::VectorXi::Constant(obstacle_slots_, -1);
  problem.obstacle_normal = Eigen::Matrix2Xd::Zero(2, obstacle_slots_);
  problem.obstacle_offset = Eigen::VectorXd::Zero(obstacle_slots_);
  problem.obstacle_landing_normal = Eigen::Matrix2Xd::Zero(2, obstacle_slots_);
  problem.obstacle_landing_offset = Eigen::VectorXd::Zero(obstacle_slots_);
  return problem;
}

void evaluateConstraints(const NmpcModel& model, const NmpcProblem& problem,
                         const Eigen::Ref<const Eigen::VectorXd>& U,
                         Eigen::Ref<Eigen::VectorXd> g, Eigen::MatrixXd* jacobian) {
  const NmpcLayout& L = model.layout();
  const int m = model.inequalityCount();
  if (U.size() != L.variableCount() || g.size() != m ||
      (jacobian && (jacobian->rows() != m || jacobian->cols() != L.variableCount()))) {
    throw std::invalid_argument(
        "evaluateConstraints: expected U of " + std::to_string(L.variableCount()) + ", g of " +
        std::to_string(m) + " and a " + std::to_string(m) +
        " x " + std::to_string(L.variableCount()) + " Jacobian, got " +
        std::to_string(U.size()) + ", " + std::to_string(g.size()) +
        (jacobian ? " and " + std::to_string(jacobian->rows()) + " x " +
                        std::to_string(jacobian->cols())
                  : std::string()));
  }
  model.checkProblem(problem);
  nmpc_internal::stackConstraints(model, problem, U, g, jacobian);
}

void nmpc_internal::stackConstraints(const NmpcModel& model, const NmpcProblem& problem,
                                     const Eigen::Ref<const Eigen::VectorXd>& U,
                                     Eigen::Ref<Eigen::VectorXd> g, Eigen::MatrixXd* jacobian,
                                     bool jacobian_is_previous) {
  if (jacobian && !jacobian_is_previous) jacobian->setZero();
  for (int k = 0; k < model.familyCount(); ++k) {
    const int first = model.familyFirstRow(k), rows = model.familyRowCount(k);
    if (rows == 0) continue;
    if (jacobian) {
      JacobianRows block(jacobian->middleRows(first, rows));
      if (jacobian_is_previous && !model.family(k).rewritesJacobianRows()) block.setZero();
      model.family(k).evaluate(model, problem, U, g.segment(first, rows), &block);
    } else {
      model.family(k).evaluate(model, problem, U, g.segment(first, rows), nullptr);
    }
    eigen_assert(g.segment(first, rows).allFinite() && "a family wrote a non-finite row");
  }
}

void evaluateCostTerms(const NmpcModel& model, const NmpcProblem& problem,
                       const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> r,
                       Eigen::MatrixXd* jacobian) {
  const int n = model.layout().variableCount(), m = model.residualCount();
  if (U.size() != n || r.size() != m ||
      (jacobian && (jacobian->rows() != m || jacobian->cols() != n))) {
    throw std::invalid_argument("evaluateCostTerms: expected U of " + std::to_string(n) +
                                ", r of " + std::to_string(m) + " and a " + std::to_string(m) +
                                " x " + std::to_string(n) + " Jacobian");
  }
  model.checkProblem(problem);
  nmpc_internal::stackResiduals(model, problem, U, r, jacobian);
}

void nmpc_internal::stackResiduals(const NmpcModel& model, const NmpcProblem& problem,
                                   const Eigen::Ref<const Eigen::VectorXd>& U,
                                   Eigen::Ref<Eigen::VectorXd> r, Eigen::MatrixXd* jacobian) {
  if (jacobian) jacobian->setZero();
  for (int k = 0; k < model.costTermCount(); ++k) {
    const int first = model.costTermFirstResidual(k), count = model.costTermResidualCount(k);
    if (count == 0) continue;
    if (jacobian) {
      Eigen::Ref<Eigen::MatrixXd> block(jacobian->middleRows(first, count));
      model.costTerm(k).evaluate(model, problem, U, r.segment(first, count), &block);
    } else {
      model.costTerm(k).evaluate(model, problem, U, r.segment(first, count), nullptr);
    }
    eigen_assert(r.segment(first, count).allFinite() && "a cost term wrote a non-finite residual");
  }
}

int buildStepEqualities(const NmpcModel& model, const NmpcProblem& problem,
                        Eigen::Ref<Eigen::MatrixXd> E, Eigen::Ref<Eigen::VectorXd> e) {
  const NmpcLayout& L = model.layout();
  int rows = 0;
  for (int i = 0; i < L.steps; ++i) {
    if (!problem.phase.step_fixed(i)) continue;
    const int columns[3] = {L.stepX() + i, L.stepY() + i, L.stepYaw() + i};
    for (int k = 0; k < 3; ++k, ++rows) {
      E.row(rows).setZero();
      E(rows, columns[k]) = 1.0;
      e(rows) = problem.phase.fixed_step_pose(k, i);
    }
  }
  return rows;
}

}  // namespace wpg
