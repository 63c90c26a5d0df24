// Yaw change between consecutive steps, paper eq. (16)-(17): |theta_i - theta_prev| <= bound
// (walking parameter max_step_yaw_change), 2 rows per step.
#include "nmpc_internal.hpp"
#include "wpg/nmpc/builtin_families.hpp"
#include "wpg/nmpc/model.hpp"

namespace wpg {
namespace {

class YawBoundConstraint final : public NamedConstraintFamily {
 public:
  YawBoundConstraint() : NamedConstraintFamily("yaw_bound", "rad", RelaxationGroup::kKinematics) {}
  int rowCount(const NmpcModel& model) const override { return YawBoundRows::count(model); }

  void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> g,
                JacobianRows* jacobian) const override {
    const NmpcLayout& L = model.layout();
    const double bound = model.parameters().max_step_yaw_change;
    if (jacobian) nmpc_internal::clearStepColumns(*jacobian, L);  // rewritesJacobianRows
    for (int i = 0; i < L.steps; ++i) {
      const int upper = YawBoundRows::row(i, true), lower = YawBoundRows::row(i, false);
      if (problem.phase.step_fixed(i)) {
        g(upper) = -1.0;
        g(lower) = -1.0;
        continue;
      }
      const nmpc_internal::PoseRef prev = nmpc_internal::previousOfStep(L, problem, U, i);
      const double yaw_change = U(L.stepYaw() + i) - prev.yaw;
      g(upper) = yaw_change - bound;
      g(lower) = -yaw_change - bound;
      if (!jacobian) continue;
      (*jacobian)(upper, L.stepYaw() + i) = 1.0;
      (*jacobian)(lower, L.stepYaw() + i) = -1.0;
      if (prev.step >= 0) {
        (*jacobian)(upper, L.stepYaw() + prev.step) = -1.0;
        (*jacobian)(lower, L.stepYaw() + prev.step) = 1.0;
      }
    }
  }

  bool rewritesJacobianRows() const override { return true; }

  // Step i becomes step i - 1 when a step was completed (step 0 has landed: its rows leave).
  int jerkSamplesOfRow(const NmpcModel&, int) const override { return 0; }  // steps only

  int shiftedRow(const NmpcModel&, int row, bool step_completed) const override {
    if (!step_completed) return row;
    const int step = row / 2;
    return step == 0 ? -1 : YawBoundRows::row(step - 1, row % 2 == 0);
  }
};

}  // namespace

std::unique_ptr<ConstraintFamily> makeYawBoundConstraint() {
  return std::make_unique<YawBoundConstraint>();
}

}  // namespace wpg
