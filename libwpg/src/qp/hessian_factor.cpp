// Cholesky factor of the QP Hessian in the form the Goldfarb-Idnani method starts from:
// J0 = L^{-T} (H = L L'), so that H^{-1} = J0 J0' and J0' H J0 = I.
#include <Eigen/Cholesky>
#include <cassert>
#include <cmath>
#include <limits>

#include "wpg/qp/dense_qp_solver.hpp"

namespace wpg::qp {

bool HessianFactor::compute(const Eigen::Ref<const Eigen::MatrixXd>& hessian) {
  Eigen::LLT<Eigen::MatrixXd> llt;
  return compute(hessian, llt);
}

bool HessianFactor::compute(const Eigen::Ref<const Eigen::MatrixXd>& hessian,
                            Eigen::LLT<Eigen::MatrixXd>& llt) {
  size = 0;
  if (hessian.rows() != hessian.cols() || !hessian.allFinite()) return false;
  const Eigen::Index n = hessian.rows();
  // Only the lower triangle of H is read (as by Eigen::LLT).
  llt.compute(hessian);
  if (llt.info() != Eigen::Success) return false;
  // Numerically singular H passes LLT with tiny pivots; the dual method would then take
  // huge steps. Reject pivots below the rounding level of the diagonal.
  if (n > 0) {
    const Eigen::MatrixXd& lu = llt.matrixLLT();
    const double min_pivot = lu.diagonal().minCoeff();
    const double max_diag = hessian.diagonal().cwiseAbs().maxCoeff();
    if (!(min_pivot * min_pivot >
          static_cast<double>(n) * std::numeric_limits<double>::epsilon() * max_diag)) {
      return false;
    }
  }
  // J0 = L^{-T} = U^{-1} with U = L' upper triangular: solve U J0 = I.
  inverse_factor_transposed.setIdentity(n, n);
  llt.matrixU().solveInPlace(inverse_factor_transposed);
  if (!inverse_factor_transposed.allFinite()) return false;
  size = static_cast<int>(n);
  return true;
}

void HessianFactor::solveInPlace(Eigen::Ref<Eigen::VectorXd> b) const {
  assert(b.size() == size);
  const Eigen::MatrixXd& j0 = inverse_factor_transposed;
  const Eigen::Index n = size;
  // x = J0 (J0' b). Both triangular products are done in place, without a temporary:
  // (J0' b)_i only reads b_0..b_i, so go from the bottom up.
  for (Eigen::Index i = n - 1; i >= 0; --i) b(i) = j0.col(i).head(i + 1).dot(b.head(i + 1));
  // (J0 w) = sum_k J0(0..k, k) w_k: column k only writes entries 0..k, and w_k is read before
  // any later column touches it, so go from left to right.
  for (Eigen::Index k = 0; k < n; ++k) {
    const double wk = b(k);
    b.head(k) += wk * j0.col(k).head(k);
    b(k) = j0(k, k) * wk;
  }
}

}  // namespace wpg::qp
