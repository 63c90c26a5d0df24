#pragma once
// Finite-difference twin of the constraint Jacobians (each family's is tested with it): central
// differences of a family's rows (or of every family's) compared with its exact Jacobian. For
// tests of every family, the built-in ones and any new one.
#include <Eigen/Core>

#include "wpg/nmpc/model.hpp"
#include "wpg/nmpc/problem.hpp"

namespace wpg {

struct JacobianCheck {
  double worst = 0.0;  // max |J - J_fd| / max(1, |J|) over the checked entries
  int worst_row = -1;  // row (of the family, or of the stacked g when family < 0)
  int worst_column = -1;
};

// Compares family `family`'s Jacobian at U (family < 0: every family, stacked) with central
// differences of step h. Allocates (not for the hot loop).
JacobianCheck checkConstraintJacobian(const NmpcModel& model, const NmpcProblem& problem,
                                      const Eigen::Ref<const Eigen::VectorXd>& U, int family = -1,
                                      double h = 1e-6);

// The same for cost term `term`'s residuals (term < 0: every term's, stacked).
JacobianCheck checkCostJacobian(const NmpcModel& model, const NmpcProblem& problem,
                                const Eigen::Ref<const Eigen::VectorXd>& U, int term = -1,
                                double h = 1e-6);

}  // namespace wpg
