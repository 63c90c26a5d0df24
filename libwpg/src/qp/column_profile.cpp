// Products C x that skip the zero blocks of C (wpg/qp/column_profile.hpp).
#include "wpg/qp/column_profile.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "qp_internal.hpp"

namespace wpg::qp {
namespace {

Eigen::VectorXi toVector(const std::vector<int>& values) {
  return Eigen::Map<const Eigen::VectorXi>(values.data(), static_cast<Eigen::Index>(values.size()));
}

// out = C x - d on the Rows rows from `top`, over the given spans of columns: the sums stay in
// registers while the columns go by, as in Eigen's kernel. Each row's sum is its products added
// in column order from zero, whatever the vector width of the clone (WPG_QP_KERNEL_CLONES).
template <int Rows>
inline void blockProduct(const double* c, Eigen::Index ld, const double* x, const double* d,
                         double* out, Eigen::Index top, const int* spans, int span_count) {
  static_assert(Rows % kLaneCount == 0, "whole lanes");
  constexpr int kLanes = Rows / kLaneCount;
  Lanes sum[kLanes] = {};
  for (int s = 0; s < span_count; ++s) {
    const int end = spans[2 * s + 1];
    const double* column = c + spans[2 * s] * ld + top;
    for (int k = spans[2 * s]; k < end; ++k, column += ld) {
      const double xk = x[k];
      for (int l = 0; l < kLanes; ++l) {
        Lanes entries;
        loadLanes(entries, column + l * kLaneCount);
        sum[l] += entries * xk;
      }
    }
  }
  for (int l = 0; l < kLanes; ++l) {
    Lanes bound;
    loadLanes(bound, d + top + l * kLaneCount);
    const Lanes difference = sum[l] - bound;
    storeLanes(out + top + l * kLaneCount, difference);
  }
}

// The same for one row (the rows left after the blocks).
void rowProduct(const double* c, Eigen::Index ld, const double* x, const double* d, double* out,
                Eigen::Index top, const int* spans, int span_count) {
  double sum = 0.0;
  for (int s = 0; s < span_count; ++s) {
    const int end = spans[2 * s + 1];
    const double* entry = c + spans[2 * s] * ld + top;
    for (int k = spans[2 * s]; k < end; ++k, entry += ld) sum += *entry * x[k];
  }
  out[top] = sum - d[top];
}

WPG_QP_KERNEL_CLONES
void blockProduct16(const double* c, Eigen::Index ld, const double* x, const double* d,
                    double* out, Eigen::Index top, const int* spans, int span_count) {
  blockProduct<16>(c, ld, x, d, out, top, spans, span_count);
}

WPG_QP_KERNEL_CLONES
void blockProduct8(const double* c, Eigen::Index ld, const double* x, const double* d,
                   double* out, Eigen::Index top, const int* spans, int span_count) {
  blockProduct<8>(c, ld, x, d, out, top, spans, span_count);
}

}  // namespace

ColumnProfile::ColumnProfile(int rows, const Eigen::Ref<const Eigen::VectorXi>& first_row,
                             const Eigen::Ref<const Eigen::VectorXi>& end_row)
    : rows_(rows), cols_(static_cast<int>(first_row.size())), first_row_(first_row),
      end_row_(end_row) {
  if (rows < 0 || end_row.size() != first_row.size()) {
    throw std::invalid_argument("ColumnProfile: expected rows >= 0 and as many end rows (" +
                                std::to_string(end_row.size()) + ") as first rows (" +
                                std::to_string(first_row.size()) + ")");
  }
  for (int k = 0; k < cols_; ++k) {
    if (first_row(k) < 0 || end_row(k) > rows) {
      throw std::invalid_argument("ColumnProfile: column " + std::to_string(k) + ": rows [" +
                                  std::to_string(first_row(k)) + ", " +
                                  std::to_string(end_row(k)) + ") leave [0, " +
                                  std::to_string(rows) + ")");
    }
  }
  std::vector<int> tops, block_spans, spans;
  for (int top = 0; top < rows;) {
    const int remaining = rows - top;
    const int size = remaining >= kBlockRows ? kBlockRows : remaining >= 8 ? 8 : 1;
    tops.push_back(top);
    block_spans.push_back(static_cast<int>(spans.size() / 2));
    // The columns nonzero somewhere in rows [top, top + size), as spans of neighbours.
    for (int k = 0; k < cols_; ++k) {
      if (!(first_row(k) < top + size && end_row(k) > top && first_row(k) < end_row(k))) continue;
      if (spans.size() / 2 > static_cast<std::size_t>(block_spans.back()) && spans.back() == k) {
        spans.back() = k + 1;
      } else {
        spans.push_back(k);
        spans.push_back(k + 1);
      }
    }
    top += size;
  }
  tops.push_back(rows);
  block_spans.push_back(static_cast<int>(spans.size() / 2));
  block_top_ = toVector(tops);
  block_span_ = toVector(block_spans);
  spans_ = toVector(spans);
}

void ColumnProfile::multiplySubtract(const Eigen::Ref<const Eigen::MatrixXd>& C,
                                     const Eigen::Ref<const Eigen::VectorXd>& x,
                                     const Eigen::Ref<const Eigen::VectorXd>& d,
                                     Eigen::Ref<Eigen::VectorXd> out) const {
  eigen_assert(fits(C) && x.size() == cols_ && d.size() == rows_ && out.size() == rows_);
  const double* c = C.data();
  const Eigen::Index ld = C.outerStride();
  const int blocks = static_cast<int>(block_top_.size()) - 1;
  for (int b = 0; b < blocks; ++b) {
    const int top = block_top_(b), size = block_top_(b + 1) - top;
    const int* spans = spans_.data() + 2 * block_span_(b);
    const int span_count = block_span_(b + 1) - block_span_(b);
    if (size == kBlockRows) {
      static_assert(kBlockRows == 16, "blockProduct16 is the kernel of a full block");
      blockProduct16(c, ld, x.data(), d.data(), out.data(), top, spans, span_count);
    } else if (size == 8) {
      blockProduct8(c, ld, x.data(), d.data(), out.data(), top, spans, span_count);
    } else {
      rowProduct(c, ld, x.data(), d.data(), out.data(), top, spans, span_count);
    }
  }
}

bool ColumnProfile::covers(const Eigen::Ref<const Eigen::MatrixXd>& C) const {
  if (!fits(C)) return false;
  for (int k = 0; k < cols_; ++k)
    for (int r = 0; r < rows_; ++r)
      if ((r < first_row_(k) || r >= end_row_(k)) && C(r, k) != 0.0) return false;
  return true;
}

}  // namespace wpg::qp
