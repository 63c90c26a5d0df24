// J' v over the nonzero pairs of v (wpg/qp/sparse_vector_product.hpp).
#include "wpg/qp/sparse_vector_product.hpp"

namespace wpg::qp {

void transposedTimesSparse(const Eigen::Ref<const Eigen::MatrixXd>& J,
                           const Eigen::Ref<const Eigen::VectorXd>& v,
                           Eigen::Ref<Eigen::VectorXi> pairs, Eigen::Ref<Eigen::VectorXd> out) {
  const int n = static_cast<int>(v.size());
  eigen_assert(J.rows() == n && J.cols() >= out.size() && pairs.size() >= n / 2);
  const double* entries = v.data();
  int count = 0;
  for (int j = 0; j + 1 < n; j += 2)
    if (entries[j] != 0.0 || entries[j + 1] != 0.0) pairs(count++) = j;
  const int* pair = pairs.data();
  using Lanes = Eigen::Array2d;  // Eigen's SSE packet: entry 2i in lane 0, 2i + 1 in lane 1
  for (Eigen::Index k = 0; k < out.size(); ++k) {
    const double* column = J.col(k).data();
    Lanes lanes = Lanes::Zero();
    for (int p = 0; p < count; ++p)
      lanes += Eigen::Map<const Lanes>(column + pair[p]) * Eigen::Map<const Lanes>(entries + pair[p]);
    double sum = lanes(0) + lanes(1);
    if (n % 2 != 0) sum += column[n - 1] * entries[n - 1];
    out(k) = 0.0 + sum;  // Eigen adds the sum to the zeroed result: -0 becomes +0
  }
}

}  // namespace wpg::qp
