#pragma once
// One family of the NMPC's nonlinear inequality rows g(U) <= 0 (CoP, step feasibility, yaw
// bound, obstacles, ...) behind one interface, as residual and constraint models are in
// crocoddyl: each family gives its rows and their exact Jacobian, says how its rows move when
// the plan is shifted (the warm start's active set), and to which relaxation group its rows
// belong (what an infeasible QP may give up, Sec. III-D: the robot may get blocked, never
// unbalanced). A family knows only its own rows, numbered from 0: the model stacks the
// families in registration order and assigns each its first row (NmpcModel::familyFirstRow),
// as crocoddyl's constraint manager assigns offsets. A new family is one new file implementing
// this interface plus its registration (NmpcModel's constructor for the built-in ones,
// builtin_families.hpp; addConstraintFamily for others), one finite-difference test
// (wpg/nmpc/numdiff.hpp) and one test of its shiftedRow.
#include <memory>

#include <Eigen/Core>

#include "wpg/nmpc/problem.hpp"

namespace wpg {

class NmpcModel;

// What an infeasible QP may relax, in this order (NmpcSolver): obstacles first (the robot
// stops in front of the obstacle), then everything else. The group of the rows that had to be
// relaxed is the iteration's status (IterationStatus::kRelaxedObstacle / kRelaxedKinematics /
// kRelaxedBalance).
enum class RelaxationGroup : unsigned char {
  kObstacle = 0,    // steps out of an obstacle's margin (eq. 18-19)
  kKinematics = 1,  // where and how a foot may land (eq. 14-17, landing bounds)
  kBalance = 2,     // the CoP inside the support polygon (eq. 9-13)
};
const char* relaxationGroupName(RelaxationGroup group);

// The rows of one family inside the model's stacked g(U): a view of the Jacobian rows
// [first_row, first_row + rows) (no copy, no allocation).
using JacobianRows = Eigen::Ref<Eigen::MatrixXd>;

class ConstraintFamily {
 public:
  virtual ~ConstraintFamily() = default;

  // snake_case name, used in datasets (mpc/slack columns) and messages
  virtual const char* name() const = 0;
  // unit of g (and so of its relaxation slack): "m" or "rad"
  virtual const char* unit() const = 0;
  virtual RelaxationGroup group() const = 0;
  // Number of rows in `model` (fixed for the model's lifetime). Called while the model
  // registers the family: its parameters, layout, feasibility polygons and obstacle slots are
  // set, its families and rows not yet.
  virtual int rowCount(const NmpcModel& model) const = 0;
  // g(U) of its rows (<= 0 when satisfied) into `g` (rowCount entries, its row 0 first) and,
  // when `jacobian` is not null, dg/dU into its rows; the caller has zeroed them, unless the
  // family rewritesJacobianRows(). Inactive rows (of a fixed step, an empty obstacle slot) are
  // g = -1 with a zero Jacobian row. Must not allocate.
  virtual void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                        const Eigen::Ref<const Eigen::VectorXd>& U,
                        Eigen::Ref<Eigen::VectorXd> g, JacobianRows* jacobian) const = 0;
  // True when evaluate() leaves its Jacobian rows exact whatever they held on entry, provided
  // they held zeros or what an earlier evaluate() of this family on this model wrote: it
  // rewrites (zeros included) every entry it may ever write. The solver then hands it the
  // previous sample's Jacobian instead of zeroing its rows first (the built-in families do;
  // a family that does not is simply zeroed).
  virtual bool rewritesJacobianRows() const { return false; }
  // The jerk columns its row `row` may be nonzero in: those of samples 0 .. k - 1 of both axes
  // for the k returned; the step columns are always taken as possibly nonzero. A row about the
  // CoM or the CoP of sample j depends on the jerks up to sample j only (the prediction of
  // eq. 1-3 is lower triangular): j + 1; a row about the steps alone: 0. The products with the
  // Jacobian skip the other columns (NmpcModel::jacobianProfile), so evaluate() must leave
  // them zero. Default: every sample (the horizon).
  virtual int jerkSamplesOfRow(const NmpcModel& model, int row) const;
  // Warm start: the row that its row `row` (active at the last sample) becomes once the plan
  // is shifted one sample forward (and one step when a step was completed), or -1 when it
  // leaves the horizon or changes meaning. Must not allocate.
  virtual int shiftedRow(const NmpcModel& model, int row, bool step_completed) const = 0;
};

// A family whose name, unit and relaxation group are fixed at construction (the built-in ones
// derive from it; so may new ones).
class NamedConstraintFamily : public ConstraintFamily {
 public:
  NamedConstraintFamily(const char* name, const char* unit, RelaxationGroup group)
      : name_(name), unit_(unit), group_(group) {}
  const char* name() const override { return name_; }
  const char* unit() const override { return unit_; }
  RelaxationGroup group() const override { return group_; }

 private:
  const char* name_;
  const char* unit_;
  RelaxationGroup group_;
};

// g(U) of every family of the model, stacked, and when jacobian != nullptr its exact Jacobian
// dg/dU (every term, including the yaw derivative of the CoP rows through the current CoM
// state). Does not allocate.
void evaluateConstraints(const NmpcModel& model, const NmpcProblem& problem,
                         const Eigen::Ref<const Eigen::VectorXd>& U,
                         Eigen::Ref<Eigen::VectorXd> g, Eigen::MatrixXd* jacobian);

// Equality rows E U = e fixing the fixed steps (landed, final: x, y, yaw); returns their count.
int buildStepEqualities(const NmpcModel& model, const NmpcProblem& problem,
                        Eigen::Ref<Eigen::MatrixXd> E, Eigen::Ref<Eigen::VectorXd> e);

}  // namespace wpg
