#pragma once
// Constraint families defined by tests: one class and one registration each, as a new family
// of the library is one file and one line (wpg/nmpc/constraint_family.hpp).
#include <Eigen/Core>

#include "wpg/nmpc.hpp"

namespace wpg_test {

using Eigen::Vector2d;
using Eigen::VectorXd;
using wpg::ConstraintFamily;
using wpg::JacobianRows;
using wpg::NmpcLayout;
using wpg::NmpcModel;
using wpg::NmpcProblem;
using wpg::RelaxationGroup;

// A test-only nonlinear family: every free previewed step within `radius` of the current
// support, |F_i - f_support|^2 <= radius^2, written (|d|^2 - r^2) / (2 r) <= 0 [m].
class StepReach final : public ConstraintFamily {
 public:
  explicit StepReach(double radius) : radius_(radius) {}
  const char* name() const override { return "step_reach"; }
  const char* unit() const override { return "m"; }
  RelaxationGroup group() const override { return RelaxationGroup::kKinematics; }
  int rowCount(const NmpcModel& model) const override { return model.layout().steps; }
  void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                const Eigen::Ref<const VectorXd>& U, Eigen::Ref<VectorXd> g,
                JacobianRows* jacobian) const override {
    const NmpcLayout& L = model.layout();
    for (int i = 0; i < L.steps; ++i) {
      if (problem.phase.step_fixed(i)) {
        g(i) = -1.0;
        continue;
      }
      const Vector2d d(U(L.stepX() + i) - problem.phase.support_pose.x(),
                       U(L.stepY() + i) - problem.phase.support_pose.y());
      g(i) = (d.squaredNorm() - radius_ * radius_) / (2.0 * radius_);
      if (!jacobian) continue;
      (*jacobian)(i, L.stepX() + i) = d.x() / radius_;
      (*jacobian)(i, L.stepY() + i) = d.y() / radius_;
    }
  }
  int shiftedRow(const NmpcModel&, int row, bool step_completed) const override {
    return step_completed ? row - 1 : row;  // step i becomes step i - 1; -1 for step 0
  }

 private:
  double radius_;
};

// A family that cannot hold: one row g = 1 with a zero Jacobian, in the given group. Its
// linearized row 0'U <= -1 makes every QP infeasible; its slack must be exactly 1.
class NeverHolds final : public ConstraintFamily {
 public:
  explicit NeverHolds(RelaxationGroup group) : group_(group) {}
  const char* name() const override { return "never_holds"; }
  const char* unit() const override { return "m"; }
  RelaxationGroup group() const override { return group_; }
  int rowCount(const NmpcModel&) const override { return 1; }
  void evaluate(const NmpcModel&, const NmpcProblem&, const Eigen::Ref<const VectorXd>&,
                Eigen::Ref<VectorXd> g, JacobianRows*) const override {
    g(0) = 1.0;
  }
  int shiftedRow(const NmpcModel&, int row, bool) const override { return row; }

 private:
  RelaxationGroup group_;
};

}  // namespace wpg_test
