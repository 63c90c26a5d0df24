#pragma once
// Pieces shared by the NMPC's sources (not installed).
#include <cmath>

#include <Eigen/Core>

#include "wpg/nmpc/constraint_family.hpp"
#include "wpg/nmpc/layout.hpp"
#include "wpg/nmpc/problem.hpp"

namespace wpg {
class NmpcModel;
}

namespace wpg::nmpc_internal {

// The bodies of evaluateConstraints, buildCostGradient and evaluateCost without their size
// checks: for the solver, whose entry point has checked the model and the problem once.
// `jacobian_is_previous`: the Jacobian holds zeros or an earlier result of stackConstraints on
// this model (the solver's workspace), so that only the rows of the families that do not
// rewrite their rows (ConstraintFamily::rewritesJacobianRows) are zeroed; else all of it is.
void stackConstraints(const NmpcModel& model, const NmpcProblem& problem,
                      const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> g,
                      Eigen::MatrixXd* jacobian, bool jacobian_is_previous = false);

// Zeroes the step columns (F_x, F_y, F_theta of every previewed step) of a family's Jacobian
// rows: the only columns the built-in families write besides the CoP rows' jerks, which those
// rows rewrite whole (ConstraintFamily::rewritesJacobianRows).
inline void clearStepColumns(JacobianRows& G, const NmpcLayout& L) {
  G.middleCols(L.stepX(), L.steps).setZero();
  G.middleCols(L.stepY(), 2 * L.steps).setZero();  // F_y and F_theta are adjacent
}
// The residuals of the model's cost terms (wpg/nmpc/cost_term.hpp), stacked, with their
// Jacobian (zeroed first) when not null.
void stackResiduals(const NmpcModel& model, const NmpcProblem& problem,
                    const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> r,
                    Eigen::MatrixXd* jacobian);
void costGradient(const NmpcModel& model, const NmpcProblem& problem,
                  Eigen::Ref<Eigen::VectorXd> gradient);
double cost(const NmpcModel& model, const NmpcProblem& problem,
            const Eigen::Ref<const Eigen::VectorXd>& U);

// Stack storage for per-sample temporaries (the horizon is at most 200 samples, validated).
using HorizonVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 200, 1>;

// Weight of 1/2 |F - F_fixed|^2 on the position of a fixed step that owns no CoP sample
// (standing): keeps the Hessian positive definite; zero at the solution (F = F_fixed).
constexpr double kFixedStepRegularization = 1.0;

// Pose (x, y, yaw) of the frame a polygon row is written in: the support of a CoP sample, or
// the previous step of a step feasibility row.
struct PoseRef {
  double x, y, yaw;
  int step;  // -1 = fixed (not a variable), else 0-based step index
};

// The support of CoP sample `row`: the current support (fixed) or a previewed step.
inline PoseRef supportOfSample(const NmpcLayout& L, const NmpcProblem& problem,
                               const Eigen::Ref<const Eigen::VectorXd>& U, int sample) {
  const int step = problem.phase.row_step(sample) - 1;
  if (step < 0) {
    const auto& p = problem.phase.support_pose;
    return {p.x(), p.y(), p.z(), -1};
  }
  return {U(L.stepX() + step), U(L.stepY() + step), U(L.stepYaw() + step), step};
}

// The step before previewed step `step`: the current support for the first one.
inline PoseRef previousOfStep(const NmpcLayout& L, const NmpcProblem& problem,
                              const Eigen::Ref<const Eigen::VectorXd>& U, int step) {
  if (step == 0) {
    const auto& p = problem.phase.support_pose;
    return {p.x(), p.y(), p.z(), -1};
  }
  return {U(L.stepX() + step - 1), U(L.stepY() + step - 1), U(L.stepYaw() + step - 1), step - 1};
}

// An edge row a' R(theta) d - b of a polygon expressed in the frame of `frame` (eq. 11 and
// 15, R(theta) = [c s; -s c]), with d = p - f the point relative to the frame's origin:
// w = R(theta)' a and its derivative w' = dw/dtheta.
struct RotatedEdge {
  double wx, wy, dwx, dwy;
  RotatedEdge(double a1, double a2, double yaw) : RotatedEdge(a1, a2, std::cos(yaw), std::sin(yaw)) {}
  // With c = cos(theta), s = sin(theta) computed once for every edge of a frame.
  RotatedEdge(double a1, double a2, double c, double s) {
    wx = a1 * c - a2 * s;
    wy = a1 * s + a2 * c;
    dwx = -a1 * s - a2 * c;
    dwy = a1 * c - a2 * s;
  }
  double value(double dx, double dy, double bound) const { return wx * dx + wy * dy - bound; }
  // The frame's part of the row's Jacobian when the frame is a previewed step: d moves
  // against the frame's position, and the rotation turns with its yaw (w'_x dx + w'_y dy,
  // the term public implementations drop for the CoP rows).
  void writeFrameJacobian(JacobianRows& G, int row, const NmpcLayout& L, const PoseRef& frame,
                          double dx, double dy) const {
    if (frame.step < 0) return;
    G(row, L.stepX() + frame.step) = -wx;
    G(row, L.stepY() + frame.step) = -wy;
    G(row, L.stepYaw() + frame.step) = dwx * dx + dwy * dy;
  }
};

}  // namespace wpg::nmpc_internal
