// The factorization of the Goldfarb-Idnani method's working set (dense_qp_solver.cpp) and its
// updates when a constraint enters or leaves.
//
// The working-set matrix N (n x q, linearly independent columns) is kept through
//   L^{-1} N = Q [R; 0],   J = L^{-T} Q = [J1 | J2]   (H = L L'),
// so that J' H J = I, J2 spans the null space of N' in the H-metric, and for a constraint n+
// about to be added (d = J' n+ = [d1; d2]) the primal step direction is z = J2 d2.
// Any orthonormal basis of the free space serves as J2, so each candidate n+ is reduced at
// once: Givens rotations of the columns of J2 bring d2 onto its first entry, h = |d2|. Then
// z = h J_q (no product needed), and adding n+ only appends the column [d1; h] to R.
// Dropping column k of R leaves an upper Hessenberg block that Givens rotations on rows k..
// restore; the same rotations act on columns k.. of J.
#include <cmath>

#include "qp_internal.hpp"
#include "wpg/qp/dense_qp_solver.hpp"
#include "wpg/qp/sparse_vector_product.hpp"

namespace wpg::qp {
namespace {

// The Givens rotations of one update form a chain over neighbouring column pairs; applying
// them row block by row block keeps the running column in registers, so each entry of J is
// loaded and stored once per update instead of twice (the update is the cost that dominates
// the method). Rotation G = (c, s) maps columns (a, b) to (c a + s b, -s a + c b). Per row,
// c * carry - s * a is a product, a product and a difference, as Eigen's array expression
// evaluated it; the lanes only change how many rows go at once (WPG_QP_KERNEL_CLONES).

constexpr int kLanesPerBlock = kRowBlock / kLaneCount;
static_assert(kRowBlock % kLaneCount == 0, "a row block is a whole number of lanes");

// Rotations i = last, last-1, ..., first+1 on the column pairs (i-1, i), in that order, on
// `rows` rows: a whole number of row blocks (J's padded rows).
WPG_QP_KERNEL_CLONES
void applyRotationChainDescending(double* matrix, Eigen::Index ld, int rows, int first, int last,
                                  const double* c, const double* s) {
  eigen_assert(rows % kRowBlock == 0);
  for (int r0 = 0; r0 < rows; r0 += kRowBlock) {
    Lanes carry[kLanesPerBlock];
    for (int l = 0; l < kLanesPerBlock; ++l)
      loadLanes(carry[l], matrix + last * ld + r0 + l * kLaneCount);
    for (int i = last; i > first; --i) {
      const double* a = matrix + (i - 1) * ld + r0;
      double* out = matrix + i * ld + r0;
      const double ci = c[i], si = s[i];
      for (int l = 0; l < kLanesPerBlock; ++l) {
        Lanes al;
        loadLanes(al, a + l * kLaneCount);
        const Lanes rotated = ci * carry[l] - si * al;
        storeLanes(out + l * kLaneCount, rotated);
        carry[l] = ci * al + si * carry[l];
      }
    }
    for (int l = 0; l < kLanesPerBlock; ++l)
      storeLanes(matrix + first * ld + r0 + l * kLaneCount, carry[l]);
  }
}

// Rotations j = first, first+1, ..., last-1 on the column pairs (j, j+1), in that order, on
// `rows` rows: a whole number of row blocks.
WPG_QP_KERNEL_CLONES
void applyRotationChainAscending(double* matrix, Eigen::Index ld, int rows, int first, int last,
                                 const double* c, const double* s) {
  eigen_assert(rows % kRowBlock == 0);
  for (int r0 = 0; r0 < rows; r0 += kRowBlock) {
    Lanes carry[kLanesPerBlock];
    for (int l = 0; l < kLanesPerBlock; ++l)
      loadLanes(carry[l], matrix + first * ld + r0 + l * kLaneCount);
    for (int j = first; j < last; ++j) {
      const double* b = matrix + (j + 1) * ld + r0;
      double* out = matrix + j * ld + r0;
      const double cj = c[j], sj = s[j];
      for (int l = 0; l < kLanesPerBlock; ++l) {
        Lanes bl;
        loadLanes(bl, b + l * kLaneCount);
        const Lanes rotated = cj * carry[l] + sj * bl;
        storeLanes(out + l * kLaneCount, rotated);
        carry[l] = cj * bl - sj * carry[l];
      }
    }
    for (int l = 0; l < kLanesPerBlock; ++l)
      storeLanes(matrix + last * ld + r0 + l * kLaneCount, carry[l]);
  }
}

}  // namespace

double DenseQpSolver::reduceNormal(int n) {
  const int q = active_count_;
  // d = J' n+ over the nonzero entries of the normal (a row of C or E, mostly zeros)
  transposedTimesSparse(J_.topLeftCorner(n, n), normal_.head(n), normal_pairs_, d_.head(n));
  if (q >= n) return 0.0;
  // Zero d(q+1..n-1) from the bottom up with rotations G_i of the pairs (i-1, i), i = n-1..q+1;
  // J2 <- J2 G' keeps J'n+ = d. Rotation i meets a = d(i-1) and b = what rotation i+1 left in
  // slot i, i.e. the norm of the tail d(i..n-1) (d(n-1) itself for the first one), and leaves
  // h = |d(i-1..n-1)|. With the tail norms computed up front the rotations do not depend on
  // each other (no chain of square roots and divisions).
  if (n - 1 > q) {
    double tail2 = d_(n - 1) * d_(n - 1);
    double b = d_(n - 1);
    for (int i = n - 1; i > q; --i) {
      const double a = d_(i - 1);
      tail2 += a * a;
      const double h = std::sqrt(tail2);
      if (h > 0.0) {
        const double inverse = 1.0 / h;
        cosines_(i) = a * inverse;
        sines_(i) = b * inverse;
      } else {
        cosines_(i) = 1.0;
        sines_(i) = 0.0;
      }
      d_(i) = 0.0;
      d_(i - 1) = h;
      b = h;
    }
    applyRotationChainDescending(J_.data(), J_.outerStride(), paddedRows(n), q, n - 1,
                                 cosines_.data(), sines_.data());
  } else if (d_(q) < 0.0) {  // q = n-1: one free column, flip it so that h >= 0
    d_(q) = -d_(q);
    J_.col(q).head(n) = -J_.col(q).head(n);
  }
  return d_(q);
}

void DenseQpSolver::appendToWorkingSet(int code, double multiplier) {
  const int q = active_count_;
  R_.col(q).head(q + 1) = d_.head(q + 1);
  active_(q) = code;
  u_(q) = multiplier;
  ++active_count_;
}

void DenseQpSolver::dropFromWorkingSet(int n, int position) {
  const int q = active_count_;
  for (int j = position; j + 1 < q; ++j) {
    R_.col(j).head(j + 2) = R_.col(j + 1).head(j + 2);
    active_(j) = active_(j + 1);
    u_(j) = u_(j + 1);
  }
  // Columns position..q-2 now have one subdiagonal entry each; rotate rows (j, j+1) to remove
  // it. R <- G R needs Q <- Q G', i.e. the same rotation of columns (j, j+1) of J.
  for (int j = position; j + 1 < q; ++j) {
    const double a = R_(j, j);
    const double b = R_(j + 1, j);
    if (b == 0.0) {
      cosines_(j) = 1.0;
      sines_(j) = 0.0;
      continue;
    }
    const double h = std::sqrt(a * a + b * b);
    const double c = a / h;
    const double s = b / h;
    cosines_(j) = c;
    sines_(j) = s;
    R_(j, j) = h;
    R_(j + 1, j) = 0.0;
    for (int l = j + 1; l + 1 < q; ++l) {
      const double top = R_(j, l);
      const double bottom = R_(j + 1, l);
      R_(j, l) = c * top + s * bottom;
      R_(j + 1, l) = -s * top + c * bottom;
    }
  }
  if (q - 1 > position) {
    applyRotationChainAscending(J_.data(), J_.outerStride(), paddedRows(n), position, q - 1,
                                cosines_.data(), sines_.data());
  }
  --active_count_;
}

}  // namespace wpg::qp
