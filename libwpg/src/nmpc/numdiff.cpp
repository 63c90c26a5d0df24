// Central finite differences of the constraint families and cost terms (wpg/nmpc/numdiff.hpp).
#include "wpg/nmpc/numdiff.hpp"

#include <algorithm>
#include <cmath>

namespace wpg {
namespace {

// Residuals of cost term `term` (all terms when < 0) at U, with the Jacobian when J is not null.
void evaluateResiduals(const NmpcModel& model, const NmpcProblem& problem,
                       const Eigen::Ref<const Eigen::VectorXd>& U, int term, Eigen::VectorXd& r,
                       Eigen::MatrixXd* J) {
  if (term < 0) {
    evaluateCostTerms(model, problem, U, r, J);
    return;
  }
  if (J) {
    Eigen::Ref<Eigen::MatrixXd> rows(*J);
    model.costTerm(term).evaluate(model, problem, U, r, &rows);
  } else {
    model.costTerm(term).evaluate(model, problem, U, r, nullptr);
  }
}

// Central differences of `evaluate` (rows, Jacobian) against its Jacobian.
template <class Evaluate>
JacobianCheck compareWithDifferences(int m, int n, const Eigen::Ref<const Eigen::VectorXd>& U,
                                     double h, Evaluate evaluate) {
  Eigen::VectorXd g(m), gp(m), gm(m);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, n);  // written into zeroed rows
  evaluate(U, g, &J);
  JacobianCheck check;
  Eigen::VectorXd Up = U, Um = U;
  for (int k = 0; k < n; ++k) {
    Up(k) = U(k) + h;
    Um(k) = U(k) - h;
    evaluate(Up, gp, nullptr);
    evaluate(Um, gm, nullptr);
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
  const int m = family < 0 ? model.inequalityCount() : model.familyRowCount(family);
  return compareWithDifferences(
      m, model.layout().variableCount(), U, h,
      [&](const Eigen::Ref<const Eigen::VectorXd>& at, Eigen::VectorXd& g, Eigen::MatrixXd* J) {
        evaluateRows(model, problem, at, family, g, J);
      });
}

JacobianCheck checkCostJacobian(const NmpcModel& model, const NmpcProblem& problem,
                                const Eigen::Ref<const Eigen::VectorXd>& U, int term, double h) {
  const int m = term < 0 ? model.residualCount() : model.costTermResidualCount(term);
  return compareWithDifferences(
      m, model.layout().variableCount(), U, h,
      [&](const Eigen::Ref<const Eigen::VectorXd>& at, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
        evaluateResiduals(model, problem, at, term, r, J);
      });
}

}  // namespace wpg
