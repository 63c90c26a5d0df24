#pragma once
// Where the inequality matrix C of a QP may be nonzero, so that the products C x skip its
// blocks of zeros. The NMPC's constraint Jacobian is one: the CoP rows of sample j depend on
// the jerks of samples 0..j only (the prediction of eq. 1-3 is lower triangular) and every
// other row on the steps only, so that more than half of its 92 x 38 entries are zeros that
// never change (NmpcModel::jacobianProfile).
#include <Eigen/Core>

namespace wpg::qp {

class ColumnProfile {
 public:
  // No profile: every product is dense.
  ColumnProfile() = default;
  // Column k of every matrix it describes (`rows` rows, first_row.size() columns) is zero
  // outside rows [first_row(k), end_row(k)) (an empty range: a zero column). Throws
  // std::invalid_argument when the sizes differ or a range leaves [0, rows]. Allocates.
  ColumnProfile(int rows, const Eigen::Ref<const Eigen::VectorXi>& first_row,
                const Eigen::Ref<const Eigen::VectorXi>& end_row);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  // A matrix of the profile's size (a default profile fits none).
  bool fits(const Eigen::Ref<const Eigen::MatrixXd>& C) const {
    return cols_ > 0 && C.rows() == rows_ && C.cols() == cols_;
  }

  // out = C x - d for a C that fits(), reading only the columns each block of rows may be
  // nonzero in. The same bits as Eigen's dense C * x then - d: Eigen sums each row's terms
  // in column order starting from zero (no fused multiply-add in the project's x86-64 build),
  // and so does this; the terms it skips are zeros, which leave such a sum unchanged.
  // Entries outside the profile are not read: they must be zeros (covers()).
  void multiplySubtract(const Eigen::Ref<const Eigen::MatrixXd>& C,
                        const Eigen::Ref<const Eigen::VectorXd>& x,
                        const Eigen::Ref<const Eigen::VectorXd>& d,
                        Eigen::Ref<Eigen::VectorXd> out) const;

  // True when every entry of C outside the profile is zero (tests, debug builds).
  bool covers(const Eigen::Ref<const Eigen::MatrixXd>& C) const;

 private:
  int rows_ = 0, cols_ = 0;
  Eigen::VectorXi first_row_, end_row_;
  // The rows in blocks of kBlockRows (then one of 8 and single rows for the rest), each
  // summed in registers: block b is rows [block_top_(b), block_top_(b + 1)); the columns that
  // may be nonzero in it are the spans [spans_(2 s), spans_(2 s + 1)) for s in
  // [block_span_(b), block_span_(b + 1)), in increasing order.
  static constexpr int kBlockRows = 16;
  Eigen::VectorXi block_top_, block_span_, spans_;
};

}  // namespace wpg::qp
