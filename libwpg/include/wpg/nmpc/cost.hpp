#pragma once
// The NMPC's cost (paper eq. 5-8): alpha/2 J1 (CoM velocity tracking) + alpha/2 J2 (step yaw
// tracking, weight_yaw) + beta/2 J3 (CoP centred on the support) + gamma/2 J4 (jerk). It is
// quadratic in U, so its Hessian is the model's constant one (NmpcModel::hessian); what
// changes with the sample is the linear term.
#include <Eigen/Core>

#include "wpg/nmpc/model.hpp"
#include "wpg/nmpc/problem.hpp"

namespace wpg {

// Linear term p of the canonical cost (8): cost = 1/2 U'QU + p'U + const (the paper's terms;
// the solver adds those of the cost terms per QP). Does not allocate.
void buildCostGradient(const NmpcModel& model, const NmpcProblem& problem,
                       Eigen::Ref<Eigen::VectorXd> gradient);
// The cost (5) itself (with its constant), alpha/2 J1 + alpha/2 J2 + beta/2 J3 + gamma/2 J4,
// plus 1/2 |r(U)|^2 of the model's cost terms (cost_term.hpp; allocates when it has some).
double evaluateCost(const NmpcModel& model, const NmpcProblem& problem,
                    const Eigen::Ref<const Eigen::VectorXd>& U);

}  // namespace wpg
