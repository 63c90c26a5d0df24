// CoP in the support polygon, paper eq. (9)-(13): 4 rows per sample of the horizon.
#include <cmath>

#include "nmpc_internal.hpp"
#include "wpg/nmpc/builtin_families.hpp"
#include "wpg/nmpc/model.hpp"

namespace wpg {
namespace {

using nmpc_internal::PoseRef;
using nmpc_internal::RotatedEdge;

// Rectangle CoP polygon, Fig. 4: outward normals (+x, -x, +y, -y) of a_e' R(theta)(z - f) <= b_e.
constexpr double kCopNormal[4][2] = {{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}};

class CopConstraint final : public NamedConstraintFamily {
 public:
  CopConstraint() : NamedConstraintFamily("cop", "m", RelaxationGroup::kBalance) {}
  int rowCount(const NmpcModel& model) const override { return CopRows::count(model); }

  // a_e' R(theta_j) (z_j - f_j) <= b_e with R(theta) = [c s; -s c] (eq. 11). Writing
  // w = R(theta)' a_e: g = w_x dx + w_y dy - b_e, d = z_j - f_j = Pzs c_hat + Pzu jerk - f_j,
  // dg/dtheta = w'_x dx + w'_y dy, which depends on the current CoM state through z_j.
  void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> g,
                JacobianRows* jacobian) const override {
    const NmpcLayout& L = model.layout();
    const LipmPrediction& P = model.prediction();
    const WalkingParameters& w = model.parameters();
    const PhaseStructure& phase = problem.phase;
    const auto jerk_x = U.segment(L.jerkX(), L.horizon);
    const auto jerk_y = U.segment(L.jerkY(), L.horizon);
    // Its rows rewrite their jerk entries whole (columns 0..j of sample j); of the step
    // columns only the frame's, so the others are cleared first (rewritesJacobianRows).
    if (jacobian) nmpc_internal::clearStepColumns(*jacobian, L);
    // The samples come in runs on one frame (the support, then each previewed step): its
    // rotation is computed once per run, not per edge and sample.
    int frame = -2;
    double c = 1.0, s = 0.0;
    for (int j = 0; j < L.horizon; ++j) {
      const double zx = P.cop_state.row(j).dot(problem.com_x) +
                        P.cop_jerk.row(j).head(j + 1).dot(jerk_x.head(j + 1));
      const double zy = P.cop_state.row(j).dot(problem.com_y) +
                        P.cop_jerk.row(j).head(j + 1).dot(jerk_y.head(j + 1));
      const PoseRef f = nmpc_internal::supportOfSample(L, problem, U, j);
      if (f.step != frame) {  // -1 = the current support
        frame = f.step;
        c = std::cos(f.yaw);
        s = std::sin(f.yaw);
      }
      const double half_length = f.step < 0 ? phase.support_half_length : w.copHalfLength();
      const double half_width = f.step < 0 ? phase.support_half_width : w.copHalfWidth();
      const double bound[4] = {half_length, half_length, half_width, half_width};
      const double dx = zx - f.x, dy = zy - f.y;
      RotatedEdge edges[CopRows::kEdges] = {
          {kCopNormal[0][0], kCopNormal[0][1], c, s}, {kCopNormal[1][0], kCopNormal[1][1], c, s},
          {kCopNormal[2][0], kCopNormal[2][1], c, s}, {kCopNormal[3][0], kCopNormal[3][1], c, s}};
      const int first_row = CopRows::row(j, 0);
      for (int e = 0; e < CopRows::kEdges; ++e)
        g(first_row + e) = edges[e].value(dx, dy, bound[e]);
      if (!jacobian) continue;
      // The 4 rows of the sample are adjacent in each column: fill column by column.
      JacobianRows& G = *jacobian;
      for (int k = 0; k <= j; ++k) {
        const double pzu = P.cop_jerk(j, k);
        for (int e = 0; e < CopRows::kEdges; ++e) {
          G(first_row + e, L.jerkX() + k) = edges[e].wx * pzu;
          G(first_row + e, L.jerkY() + k) = edges[e].wy * pzu;
        }
      }
      for (int e = 0; e < CopRows::kEdges; ++e)
        edges[e].writeFrameJacobian(G, first_row + e, L, f, dx, dy);
    }
  }
  bool rewritesJacobianRows() const override { return true; }
  // Sample j's rows: the jerks of samples 0..j (the lower-triangular Pzu of eq. 3).
  int jerkSamplesOfRow(const NmpcModel&, int row) const override {
    return row / CopRows::kEdges + 1;
  }

  // Sample j becomes sample j - 1 (the same instant, one sample nearer); the first sample's
  // rows leave the horizon.
  int shiftedRow(const NmpcModel&, int row, bool) const override {
    const int sample = row / CopRows::kEdges, edge = row % CopRows::kEdges;
    return sample == 0 ? -1 : CopRows::row(sample - 1, edge);
  }
};

}  // namespace

std::unique_ptr<ConstraintFamily> makeCopConstraint() { return std::make_unique<CopConstraint>(); }

}  // namespace wpg
