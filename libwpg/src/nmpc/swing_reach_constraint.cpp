// Swing-foot reach (wpg/swing_foot_reach.hpp): while a foot swings, its landing (previewed
// step 0) stays where the swing foot can still get to with its speed and acceleration
// bounded (walking parameters max_swing_speed, max_swing_acceleration),
//     swing_reach_lower(k) <= d_k . (F_0^x, F_0^y) <= swing_reach_upper(k),   k = 0..7,
// bounds the pattern generator computes before the solve from the foot's state. A physical
// form of the paper's landing bound (Sec. III-C3, last paragraph: "the velocity of the foot is
// limited by bounding the feasible foot step area that corresponds to a maximum velocity"):
// the area follows from the foot's actual state and the polynomial that will take it there,
// not from a rate times the time left, so a late change cannot need a faster foot than the
// limits. 16 rows (upper then lower per direction), linear in U, inactive (g = -1) when no
// foot swings and when step 0 is fixed (landed, final step). Relaxed with the kinematic rows.
#include "nmpc_internal.hpp"
#include "wpg/nmpc/builtin_families.hpp"
#include "wpg/nmpc/model.hpp"
#include "wpg/swing_foot_reach.hpp"

namespace wpg {
namespace {

static_assert(SwingReach::kDirections * 2 == SwingReachRows::kRows &&
                  SwingReach::Bounds::RowsAtCompileTime ==
                      decltype(NmpcProblem::swing_reach_lower)::RowsAtCompileTime,
              "one upper and one lower row per direction of the reach");

class SwingReachConstraint final : public NamedConstraintFamily {
 public:
  SwingReachConstraint() : NamedConstraintFamily("swing_reach", "m", RelaxationGroup::kKinematics) {}
  int rowCount(const NmpcModel& model) const override { return SwingReachRows::count(model); }

  void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> g,
                JacobianRows* jacobian) const override {
    const NmpcLayout& L = model.layout();
    g.setConstant(-1.0);
    if (rowCount(model) == 0 || !problem.swing_reach_bounded || L.steps == 0 ||
        problem.phase.step_fixed(0))
      return;
    const Eigen::Vector2d landing(U(L.stepX()), U(L.stepY()));
    for (int k = 0; k < SwingReach::kDirections; ++k) {
      const Eigen::Vector2d d = SwingReach::direction(k);
      const int upper = SwingReachRows::row(k, true), lower = SwingReachRows::row(k, false);
      g(upper) = d.dot(landing) - problem.swing_reach_upper(k);
      g(lower) = problem.swing_reach_lower(k) - d.dot(landing);
      if (!jacobian) continue;
      (*jacobian)(upper, L.stepX()) = d.x();
      (*jacobian)(upper, L.stepY()) = d.y();
      (*jacobian)(lower, L.stepX()) = -d.x();
      (*jacobian)(lower, L.stepY()) = -d.y();
    }
  }

  // The rows keep their meaning during a swing; a completed step changes the swing foot.
  int jerkSamplesOfRow(const NmpcModel&, int) const override { return 0; }  // steps only

  int shiftedRow(const NmpcModel&, int row, bool step_completed) const override {
    return step_completed ? -1 : row;
  }
};

}  // namespace

std::unique_ptr<ConstraintFamily> makeSwingReachConstraint() {
  return std::make_unique<SwingReachConstraint>();
}

}  // namespace wpg
