// Central finite differences of the constraint families (wpg/nmpc/numdiff.hpp).
#include "wpg/nmpc/numdiff.hpp"

#include <algorithm>
#include <cmath>

namespace wpg {
namespace {

// Rows of `family` (all families when < 0) at U, with the Jacobian when J is not null.
void evaluateRows(const NmpcModel& model, const NmpcProblem& problem,
                  const Eigen::Ref<const Eigen::VectorXd>& U, int family, Eigen::VectorXd& g,
                  Eigen::MatrixXd* J) {
  if (family < 0) {
    evaluateConstraints(model, problem, U, g, J);
    return;
  }
  if (J) {
    JacobianRows rows(*J);
    model.family(family).evaluate(model, problem, U, g, &rows);
  } else {
    model.family(family).evaluate(model, problem, U, g, nullptr);
  }
}

}  // namespace

JacobianCheck checkConstraintJacobian(const NmpcModel& model, const NmpcProblem& problem,
                                      const Eigen::Ref<const Eigen::VectorXd>& U, int family,
                                      double h) {
  const int n = model.layout().variableCount();
  const int m = family < 0 ? model.inequalityCount() : model.familyRowCount(family);
  Eigen::VectorXd g(m), gp(m), gm(m);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, n);  // families write into zeroed rows
  evaluateRows(model, problem, U, family, g, &J);
  JacobianCheck check;
  Eigen::VectorXd Up = U, Um = U;
  for (int k = 0; k < n; ++k) {
    Up(k) = U(k) + h;
    Um(k) = U(k) - h;
    evaluateRows(model, problem, Up, family, gp, nullptr);
    evaluateRows(model, problem, Um, family, gm, nullptr);
    Up(k) = U(k);
    Um(k) = U(k);
    for (int r = 0; r < m; ++r) {
      const double fd = (gp(r) - gm(r)) / (2.0 * h);
      const double err = std::abs(J(r, k) - fd) / std::max(1.0, std::abs(J(r, k)));
      if (!(err <= check.worst)) {  // also catches NaN
        check.worst = std::isfinite(err) ? err : INFINITY;
        check.worst_row = r;
        check.worst_column = k;
      }
    }
  }
  return check;
}

}  // namespace wpg
