#pragma once
// A term added to the NMPC's cost (5) as a weighted least-squares residual, as residual models
// are in crocoddyl: cost_term = 1/2 |r(U)|^2 (the weight folded into r). The solver keeps its
// Gauss-Newton scheme (Sec. III-E): at the linearization point U0 it adds R'R to the model's
// constant Hessian and R'(r(U0) - R U0) to the linear term, R = dr/dU exact. A model without
// terms (NmpcModel::costTermCount() == 0) solves with the constant Hessians' precomputed
// factors as before; a model with terms factors Q + R'R once per QP (workspace storage, no
// allocation). A new term is one class implementing this interface, registered by name
// (wpg/nmpc/extension_registry.hpp) or added to a model (NmpcModel::addCostTerm), and one
// finite-difference test (checkCostJacobian, wpg/nmpc/numdiff.hpp).
#include <Eigen/Core>

#include "wpg/nmpc/problem.hpp"

namespace wpg {

class NmpcModel;

class CostTerm {
 public:
  virtual ~CostTerm() = default;
  // snake_case name, used in messages and by the registry
  virtual const char* name() const = 0;
  // Number of residuals in `model` (fixed for the model's lifetime; its layout is set).
  virtual int residualCount(const NmpcModel& model) const = 0;
  // r(U) into `r` (residualCount entries) and, when `jacobian` is not null, dr/dU into its
  // rows (residualCount x variables), which the caller has zeroed. U's layout:
  // wpg/nmpc/layout.hpp. Must not allocate.
  virtual void evaluate(const NmpcModel& model, const NmpcProblem& problem,
                        const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> r,
                        Eigen::Ref<Eigen::MatrixXd>* jacobian) const = 0;
};

// The residuals of every cost term of the model, stacked in registration order, and when
// jacobian != nullptr their Jacobian (NmpcModel::residualCount() x variables). Throws
// std::invalid_argument on sizes that do not match the model. Does not allocate.
void evaluateCostTerms(const NmpcModel& model, const NmpcProblem& problem,
                       const Eigen::Ref<const Eigen::VectorXd>& U, Eigen::Ref<Eigen::VectorXd> r,
                       Eigen::MatrixXd* jacobian);

}  // namespace wpg
