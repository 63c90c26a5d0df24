// Swing-foot landing bound, paper Sec. III-C3, last paragraph: "In [5] (Herdt et al. 2010),
// the velocity of the foot is limited by bounding the feasible foot step area that
// corresponds to a maximum velocity. We chose to use the same idea extended to all the foot
// steps degrees of freedom. This significantly decreases the variation of accelerations
// before foot landing."
//
// The form is the one of the authors' code (jrl-walkgen, nmpc_generator.cpp,
// updateFootVelIneqConstraint): while a foot swings, its landing (previewed step 0) may move
// from the landing planned at the previous sample by at most what the foot can still travel
// at the maximum foot speed before touchdown,
//     |F_0^a - F_0,prev^a| <= v_max^a * T_left,     a = x, y (max_landing_speed),
//                                                   a = yaw (max_landing_yaw_rate),
// with T_left the time left before touchdown (NmpcProblem::landing_time_left: one sampling
// period at the last sample of the swing). Differences with that code, chosen here: both
// signs of every axis are bounded (theirs bounds one sign, along the command's direction),
// and T_left is the exact time to touchdown of our schedule (theirs adds one period).
// Since the swing foot is re-planned at every sample by a quintic that reaches the landing
// at rest in T_left, a landing change d adds at most ~1.9 d / T_left <= 1.9 v_max to its
// speed, however late the change comes.
//
// 6 rows (x, y, yaw; upper then lower), linear in U. Inactive (g = -1) when no foot swings,
// when step 0 is fixed (landed, final step) and for an axis whose bound is 0 (off).
#include "nmpc_internal.hpp"
#include "wpg/nmpc/model.hpp"

namespace wpg {
namespace {

class LandingBoundConstraint final : public NamedConstraintFamily {
 public:
  // Rows mix metres (x, y) and radians (yaw); the family's slack is reported in metres.
  LandingBoundConstraint()
      : NamedConstraintFamily("landing_bound", "m", RelaxationGroup::kKinematics) {}
  // No rows when the bound is off (both rates 0): the family stays registered (its slack
  // column is always there) but adds nothing to the QP.
  int rowCount(const NmpcLayout& L) const override { return L.landing_rows; }

  void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> g,
                JacobianRows* jacobian) const override {
    const NmpcLayout& L = model.layout();
    const WalkingParameters& w = model.parameters();
    g.setConstant(-1.0);
    if (!problem.landing_bounded || L.steps == 0 || problem.phase.step_fixed(0)) return;
    const double rates[3] = {w.max_landing_speed, w.max_landing_speed, w.max_landing_yaw_rate};
    const int columns[3] = {L.stepX(), L.stepY(), L.stepYaw()};
    for (int axis = 0; axis < 3; ++axis) {
      if (rates[axis] <= 0.0) continue;  // this axis is switched off
      const double bound = rates[axis] * problem.landing_time_left;
      const double change = U(columns[axis]) - problem.previous_landing(axis);
      const int upper = 2 * axis, lower = 2 * axis + 1;
      g(upper) = change - bound;
      g(lower) = -change - bound;
      if (!jacobian) continue;
      (*jacobian)(upper, columns[axis]) = 1.0;
      (*jacobian)(lower, columns[axis]) = -1.0;
    }
  }

  // The rows keep their meaning during a swing; a completed step changes the swing foot.
  int shiftedRow(const NmpcLayout&, int row, bool step_completed) const override {
    return step_completed ? -1 : row;
  }
};

}  // namespace

std::unique_ptr<ConstraintFamily> makeLandingBoundConstraint() {
  return std::make_unique<LandingBoundConstraint>();
}

}  // namespace wpg
