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
// Two families, so that each relaxes with a slack in one unit: landing_bound (x, y: 4 rows,
// metres) and landing_yaw_bound (yaw: 2 rows, radians); upper then lower row per axis, linear
// in U. A family whose rate is 0 (off) has no rows; the rows are inactive (g = -1) when no
// foot swings and when step 0 is fixed (landed, final step).
#include "nmpc_internal.hpp"
#include "wpg/nmpc/builtin_families.hpp"
#include "wpg/nmpc/model.hpp"

namespace wpg {
namespace {

class LandingBoundConstraint final : public NamedConstraintFamily {
 public:
  // Axes [first_axis, last_axis) of (x, y, yaw).
  LandingBoundConstraint(const char* name, const char* unit, int first_axis, int last_axis)
      : NamedConstraintFamily(name, unit, RelaxationGroup::kKinematics),
        first_axis_(first_axis),
        last_axis_(last_axis) {}
  int rowCount(const NmpcModel& model) const override {
    return yaw() ? LandingYawBoundRows::count(model) : LandingBoundRows::count(model);
  }

  void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> g,
                JacobianRows* jacobian) const override {
    const NmpcLayout& L = model.layout();
    const WalkingParameters& w = model.parameters();
    g.setConstant(-1.0);
    if (jacobian) nmpc_internal::clearStepColumns(*jacobian, L);  // rewritesJacobianRows
    if (rowCount(model) == 0 || !problem.landing_bounded || L.steps == 0 ||
        problem.phase.step_fixed(0))
      return;
    const double rates[3] = {w.max_landing_speed, w.max_landing_speed, w.max_landing_yaw_rate};
    const int columns[3] = {L.stepX(), L.stepY(), L.stepYaw()};
    for (int axis = first_axis_; axis < last_axis_; ++axis) {
      const double bound = rates[axis] * problem.landing_time_left;
      const double change = U(columns[axis]) - problem.previous_landing(axis);
      const int upper = row(axis, true), lower = row(axis, false);
      g(upper) = change - bound;
      g(lower) = -change - bound;
      if (!jacobian) continue;
      (*jacobian)(upper, columns[axis]) = 1.0;
      (*jacobian)(lower, columns[axis]) = -1.0;
    }
  }

  bool rewritesJacobianRows() const override { return true; }

  // The rows keep their meaning during a swing; a completed step changes the swing foot.
  int jerkSamplesOfRow(const NmpcModel&, int) const override { return 0; }  // steps only

  int shiftedRow(const NmpcModel&, int row, bool step_completed) const override {
    return step_completed ? -1 : row;
  }

 private:
  bool yaw() const { return first_axis_ == 2; }
  int row(int axis, bool upper) const {
    return yaw() ? LandingYawBoundRows::row(upper) : LandingBoundRows::row(axis, upper);
  }

  int first_axis_, last_axis_;
};

}  // namespace

std::unique_ptr<ConstraintFamily> makeLandingBoundConstraint() {
  return std::make_unique<LandingBoundConstraint>("landing_bound", "m", 0, 2);
}

std::unique_ptr<ConstraintFamily> makeLandingYawBoundConstraint() {
  return std::make_unique<LandingBoundConstraint>("landing_yaw_bound", "rad", 2, 3);
}

}  // namespace wpg
