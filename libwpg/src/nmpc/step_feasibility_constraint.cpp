// Step feasibility, paper eq. (14)-(15): each previewed step inside the polygon of reachable
// placements attached to the step before it (5 rows per step for HRP-2's polygon).
#include <cmath>

#include "nmpc_internal.hpp"
#include "wpg/nmpc/builtin_families.hpp"
#include "wpg/nmpc/model.hpp"

namespace wpg {
namespace {

using nmpc_internal::PoseRef;
using nmpc_internal::RotatedEdge;

class StepFeasibilityConstraint final : public NamedConstraintFamily {
 public:
  StepFeasibilityConstraint() : NamedConstraintFamily("step_feasibility", "m", RelaxationGroup::kKinematics) {}
  int rowCount(const NmpcModel& model) const override {
    return StepFeasibilityRows::of(model).count(model);
  }

  // a_e' R(theta_prev) (F_i - F_prev) <= b_e; rows of fixed steps are inactive.
  void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> g,
                JacobianRows* jacobian) const override {
    const NmpcLayout& L = model.layout();
    const PhaseStructure& phase = problem.phase;
    const StepFeasibilityRows rows = StepFeasibilityRows::of(model);
    if (jacobian) nmpc_internal::clearStepColumns(*jacobian, L);  // rewritesJacobianRows
    for (int i = 0; i < L.steps; ++i) {
      const ConvexPolygon& polygon = model.feasibilityPolygon(phase.stepSide(i));
      if (phase.step_fixed(i)) {
        for (int e = 0; e < rows.edges; ++e) g(rows.row(i, e)) = -1.0;
        continue;
      }
      const PoseRef prev = nmpc_internal::previousOfStep(L, problem, U, i);
      const double dx = U(L.stepX() + i) - prev.x, dy = U(L.stepY() + i) - prev.y;
      const double c = std::cos(prev.yaw), s = std::sin(prev.yaw);  // once for every edge
      for (int e = 0; e < rows.edges; ++e) {
        const RotatedEdge edge(polygon.normals()(e, 0), polygon.normals()(e, 1), c, s);
        const int row = rows.row(i, e);
        g(row) = edge.value(dx, dy, polygon.offsets()(e));
        if (!jacobian) continue;
        (*jacobian)(row, L.stepX() + i) = edge.wx;
        (*jacobian)(row, L.stepY() + i) = edge.wy;
        edge.writeFrameJacobian(*jacobian, row, L, prev, dx, dy);
      }
    }
  }

  bool rewritesJacobianRows() const override { return true; }

  // Step i becomes step i - 1 when a step was completed (step 0 has landed: its rows leave).
  int jerkSamplesOfRow(const NmpcModel&, int) const override { return 0; }  // steps only

  int shiftedRow(const NmpcModel& model, int row, bool step_completed) const override {
    if (!step_completed) return row;
    const StepFeasibilityRows rows = StepFeasibilityRows::of(model);
    const int step = row / rows.edges, edge = row % rows.edges;
    return step == 0 ? -1 : rows.row(step - 1, edge);
  }
};

}  // namespace

std::unique_ptr<ConstraintFamily> makeStepFeasibilityConstraint() {
  return std::make_unique<StepFeasibilityConstraint>();
}

}  // namespace wpg
