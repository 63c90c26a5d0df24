#pragma once
// The Hessian factors of a process, each computed once per distinct Hessian. A study's runs
// share their walking parameters but for the swept keys (speed, weights, height): every run
// built the same NMPC Hessians again, and their factors (an LLT and a triangular inverse per
// walking pattern and step cadence) were a tenth of a batch.
#include <memory>

#include <Eigen/Core>

#include "wpg/qp/dense_qp_solver.hpp"

namespace wpg::qp {

// The factor HessianFactor::compute(hessian) gives, shared with every earlier call of the
// process for a Hessian of the same size and the same bits; null where compute() fails. The
// factor is a function of those bits alone, so it is the same to the last bit whichever call
// (or thread) computed it: the number of threads, the order of the runs and what the memo
// still holds change no result. Thread safe. The memo holds the most recently used factors up
// to a fixed budget of memory (factors in use stay alive with their users). Allocates.
std::shared_ptr<const HessianFactor> sharedHessianFactor(
    const Eigen::Ref<const Eigen::MatrixXd>& hessian);

}  // namespace wpg::qp
