// Goldfarb-Idnani dual active-set method (D. Goldfarb, A. Idnani, "A numerically stable dual
// method for solving strictly convex quadratic programs", Math. Programming 27, 1983).
//
// Notation of the paper. Constraints are handled in the form n_j'x >= b_j: an inequality row
// C_i x <= d_i becomes n = -C_i', b = -d_i, and an equality E_i x = e_i likewise (its
// multiplier is free in sign). With these signs the paper's multipliers u satisfy
// H x + g = N u, i.e. H x + g + E'mu + C'lambda = 0 with mu, lambda read off u directly.
//
// The working-set matrix N (n x q, linearly independent columns) is kept through
//   L^{-1} N = Q [R; 0],   J = L^{-T} Q = [J1 | J2]   (H = L L'),
// so that J' H J = I, J2 spans the null space of N' in the H-metric, and for a constraint n+
// about to be added (d = J' n+ = [d1; d2]):
//   z = J2 d2           primal step direction (change of x per unit of the new multiplier),
//   r = R^{-1} d1       dual step direction (minus the change of the working-set multipliers).
// Any orthonormal basis of the free space serves as J2, so each candidate n+ is reduced at
// once: Givens rotations of the columns of J2 bring d2 onto its first entry, h = |d2|. Then
// z = h J_q (no product needed), and adding n+ only appends the column [d1; h] to R.
// Dropping column k of R leaves an upper Hessenberg block that Givens rotations on rows k..
// restore; the same rotations act on columns k.. of J.
//
// Beyond the paper: the most violated row is chosen after scaling by the row norm, dependent
// rows use a relative test (see QpSettings::dependence_tolerance), and a dependent row whose
// violation is within rounding of the working set is set aside instead of reported as proof of
// infeasibility (degenerate vertices).
//
// Why one file of ~550 lines: solve() is one algorithm whose steps (equalities, warm start, dual
// iterations with partial steps) share the factorization state J, R and the working set;
// splitting it would scatter one proof-carrying loop across files.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "wpg/qp/dense_qp_solver.hpp"

namespace wpg::qp {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A dual-direction entry r_j counts as positive above this fraction of max |r| (rounding
// noise on an entry that is zero in exact arithmetic would otherwise trigger spurious
// zero-length steps that drop degenerate constraints and add them back).
constexpr double kDualDirectionRelativeZero = 1e-14;
// in_working_set_ values: 0 free, 1 in the working set, kSetAside skipped by the scans (a row
// implied by the working set and violated only by rounding; see the dual iterations).
constexpr unsigned char kSetAside = 2;

// The Givens rotations of one update form a chain over neighbouring column pairs; applying
// them row block by row block keeps the running column in registers, so each entry of J is
// loaded and stored once per update instead of twice (the update is the cost that dominates
// the method). Rotation G = (c, s) maps columns (a, b) to (c a + s b, -s a + c b).
constexpr int kRowBlock = 8;

// J is stored with its row count rounded up to a whole number of row blocks (the extra rows
// are zero and stay zero under rotations), so that no scalar remainder loop is needed.
int paddedRows(int rows) { return (rows + kRowBlock - 1) / kRowBlock * kRowBlock; }

using RowBlock = Eigen::Array<double, kRowBlock, 1>;
using RowBlockMap = Eigen::Map<RowBlock>;
using ConstRowBlockMap = Eigen::Map<const RowBlock>;

// Rotations i = last, last-1, ..., first+1 on the column pairs (i-1, i), in that order.
void applyRotationChainDescending(double* matrix, Eigen::Index ld, int rows, int first, int last,
                                  const double* c, const double* s) {
  int r0 = 0;
  for (; r0 + kRowBlock <= rows; r0 += kRowBlock) {
    RowBlock carry = ConstRowBlockMap(matrix + last * ld + r0);
    for (int i = last; i > first; --i) {
      const RowBlock a = ConstRowBlockMap(matrix + (i - 1) * ld + r0);
      RowBlockMap(matrix + i * ld + r0) = c[i] * carry - s[i] * a;
      carry = c[i] * a + s[i] * carry;
    }
    RowBlockMap(matrix + first * ld + r0) = carry;
  }
  for (int r = r0; r < rows; ++r) {
    double carry = matrix[last * ld + r];
    for (int i = last; i > first; --i) {
      const double a = matrix[(i - 1) * ld + r];
      matrix[i * ld + r] = c[i] * carry - s[i] * a;
      carry = c[i] * a + s[i] * carry;
    }
    matrix[first * ld + r] = carry;
  }
}

// Rotations j = first, first+1, ..., last-1 on the column pairs (j, j+1), in that order.
void applyRotationChainAscending(double* matrix, Eigen::Index ld, int rows, int first, int last,
                                 const double* c, const double* s) {
  int r0 = 0;
  for (; r0 + kRowBlock <= rows; r0 += kRowBlock) {
    RowBlock carry = ConstRowBlockMap(matrix + first * ld + r0);
    for (int j = first; j < last; ++j) {
      const RowBlock b = ConstRowBlockMap(matrix + (j + 1) * ld + r0);
      RowBlockMap(matrix + j * ld + r0) = c[j] * carry + s[j] * b;
      carry = c[j] * b - s[j] * carry;
    }
    RowBlockMap(matrix + last * ld + r0) = carry;
  }
  for (int r = r0; r < rows; ++r) {
    double carry = matrix[first * ld + r];
    for (int j = first; j < last; ++j) {
      const double b = matrix[(j + 1) * ld + r];
      matrix[j * ld + r] = c[j] * carry + s[j] * b;
      carry = c[j] * b - s[j] * carry;
    }
    matrix[last * ld + r] = carry;
  }
}

}  // namespace

const char* qpStatusName(QpStatus status) {
  switch (status) {
    case QpStatus::kOptimal:
      return "optimal";
    case QpStatus::kInfeasible:
      return "infeasible";
    case QpStatus::kIterationLimit:
      return "iteration_limit";
    case QpStatus::kInvalidInput:
      return "invalid_input";
  }
  return "unknown";
}

DenseQpSolver::DenseQpSolver(int max_variables, int max_equalities, int max_inequalities)
    : max_n_(max_variables), max_me_(max_equalities), max_mi_(max_inequalities) {
  if (max_variables < 0 || max_equalities < 0 || max_inequalities < 0) {
    throw std::invalid_argument(
        "DenseQpSolver: capacities must be >= 0, got variables=" + std::to_string(max_variables) +
        " equalities=" + std::to_string(max_equalities) +
        " inequalities=" + std::to_string(max_inequalities));
  }
  active_inequalities_.setZero(max_mi_);
  guess_.setZero(max_mi_);
  lambda_.setZero(max_mi_);
  mu_.setZero(max_me_);
  J_.setZero(paddedRows(max_n_), max_n_);
  R_.setZero(max_n_, max_n_);
  d_.setZero(max_n_);
  gradient_.setZero(max_n_);
  r_.setZero(max_n_);
  u_.setZero(max_n_);
  normal_.setZero(max_n_);
  work_.setZero(max_n_);
  slack_.setZero(max_mi_);
  row_scale_.setZero(max_mi_);
  cosines_.setZero(max_n_);
  sines_.setZero(max_n_);
  active_.setZero(max_n_);
  in_working_set_.setZero(max_mi_);
}

void DenseQpSolver::setActiveSetGuess(const int* inequality_indices, int count) {
  guess_count_ = 0;
  if (inequality_indices == nullptr) return;
  count = std::min(count, max_mi_);
  for (int k = 0; k < count; ++k) guess_(guess_count_++) = inequality_indices[k];
}

void DenseQpSolver::clearActiveSetGuess() { guess_count_ = 0; }

double DenseQpSolver::reduceNormal(int n) {
  const int q = active_count_;
  d_.head(n).noalias() = J_.topLeftCorner(n, n).transpose() * normal_.head(n);
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

void DenseQpSolver::storeResults(const HessianFactor& factor,
                                 const Eigen::Ref<const Eigen::VectorXd>& g,
                                 const Eigen::Ref<const Eigen::VectorXd>& x, int me, int mi,
                                 int pending, double pending_multiplier) {
  lambda_.head(mi).setZero();
  mu_.head(me).setZero();
  active_inequality_count_ = 0;
  for (int j = 0; j < active_count_; ++j) {
    const int code = active_(j);
    if (code < 0) {
      mu_(-1 - code) = u_(j);
    } else {
      lambda_(code) = std::max(u_(j), 0.0);
      active_inequalities_(active_inequality_count_++) = code;
    }
  }
  // A constraint in the middle of being added (partial steps taken) carries a multiplier too;
  // reporting it keeps H x + g + E'mu + C'lambda = 0 true for the returned iterate.
  if (pending >= 0) lambda_(pending) = std::max(pending_multiplier, 0.0);
  std::sort(active_inequalities_.data(), active_inequalities_.data() + active_inequality_count_);
  // f = 1/2 |L'x|^2 + g'x with L' = J0^{-1}.
  const int n = static_cast<int>(x.size());
  work_.head(n) = x;
  factor.inverse_factor_transposed.topLeftCorner(n, n).triangularView<Eigen::Upper>().solveInPlace(
      work_.head(n));
  objective_ = 0.5 * work_.head(n).squaredNorm() + g.dot(x);
}

QpStatus DenseQpSolver::solve(const HessianFactor& factor,
                              const Eigen::Ref<const Eigen::VectorXd>& g,
                              const Eigen::Ref<const Eigen::MatrixXd>& E,
                              const Eigen::Ref<const Eigen::VectorXd>& e,
                              const Eigen::Ref<const Eigen::MatrixXd>& C,
                              const Eigen::Ref<const Eigen::VectorXd>& d,
                              Eigen::Ref<Eigen::VectorXd> x) {
  iterations_ = 0;
  warm_start_updates_ = 0;
  objective_ = 0.0;
  warm_start_kept_ = 0;
  active_inequality_count_ = 0;
  active_count_ = 0;
  active_equality_count_ = 0;
  const int guess_count = guess_count_;
  guess_count_ = 0;  // the guess is for this solve only

  const int n = static_cast<int>(g.size());
  const int me = static_cast<int>(E.rows());
  const int mi = static_cast<int>(C.rows());

  // ---- input checks ----
  const bool sizes_ok = n <= max_n_ && me <= max_me_ && mi <= max_mi_ && x.size() == n &&
                        factor.size == n && factor.inverse_factor_transposed.rows() >= n &&
                        factor.inverse_factor_transposed.cols() >= n &&
                        (me == 0 || E.cols() == n) && e.size() == me &&
                        (mi == 0 || C.cols() == n) && d.size() == mi;
  if (!sizes_ok) {
    if (x.size() == n && n <= max_n_) x.setZero();
    return QpStatus::kInvalidInput;
  }
  // lambda_/mu_ keep their capacity; the accessors return the first mi / me entries, so
  // changing problem sizes never allocate.
  last_mi_ = mi;
  last_me_ = me;
  lambda_.setZero();
  mu_.setZero();

  // Row norms of C (for scale-invariant selection of the most violated constraint); the same
  // pass catches non-finite entries of C (and rows whose squared norm overflows, > ~1e154).
  row_scale_.head(mi).setZero();
  for (int col = 0; col < n; ++col) row_scale_.head(mi) += C.col(col).cwiseAbs2();
  if (!g.allFinite() || !e.allFinite() || !d.allFinite() || !row_scale_.head(mi).allFinite() ||
      (me > 0 && !E.allFinite())) {
    x.setZero();
    return QpStatus::kInvalidInput;
  }
  for (int i = 0; i < mi; ++i) {
    const double norm = std::sqrt(row_scale_(i));
    row_scale_(i) = norm > 0.0 ? 1.0 / norm : 1.0;
  }
  in_working_set_.head(mi).setZero();

  const double feasibility_tol = settings_.feasibility_tolerance;
  const double dependence_tol = settings_.dependence_tolerance;
  const int max_iterations = settings_.max_iterations;
  const auto j0 = factor.inverse_factor_transposed.topLeftCorner(n, n);
  auto J = J_.topLeftCorner(n, n);

  // ---- step 0: unconstrained minimum x = -H^{-1} g = -J0 J0' g, empty working set ----
  J = j0.triangularView<Eigen::Upper>();
  J_.block(n, 0, paddedRows(n) - n, n).setZero();
  x = -g;
  factor.solveInPlace(x);

  // Linear dependence test after reduceNormal(): n+ lies in the span of the working set when
  // its free-space component |z|_H^2 = h^2 = z'n+ is negligible against |d|^2 = |n+|_{H^-1}^2.
  auto is_dependent = [&](double h) {
    const int q = active_count_;
    return h * h <= dependence_tol * d_.head(std::min(q + 1, n)).squaredNorm();
  };
  // r = R^{-1} d1: dual step direction (minus the change of the working-set multipliers).
  auto compute_dual_direction = [&]() {
    const int q = active_count_;
    r_.head(q) = d_.head(q);
    R_.topLeftCorner(q, q).triangularView<Eigen::Upper>().solveInPlace(r_.head(q));
  };

  // ---- equalities first: each is a full step of the paper with an unrestricted multiplier
  // (no inequality is in the working set yet, so no partial step can occur) ----
  for (int i = 0; i < me; ++i) {
    normal_.head(n) = -E.row(i).transpose();
    const double violation = normal_.head(n).dot(x) + e(i);  // s = n'x - b with b = -e_i
    const double h = reduceNormal(n);
    const int q = active_count_;
    compute_dual_direction();
    if (is_dependent(h)) {
      // n+ = N r: consistent (hence redundant) when the violation is within what the
      // residuals of the equalities already in the working set can explain.
      if (std::abs(violation) <= feasibility_tol * (1.0 + r_.head(q).cwiseAbs().sum())) continue;
      storeResults(factor, g, x, me, mi, -1, 0.0);
      return QpStatus::kInfeasible;  // inconsistent equalities
    }
    const double t = -violation / (h * h);
    x += (t * h) * J.col(q);  // z = h J_q
    u_.head(q) -= t * r_.head(q);
    appendToWorkingSet(-1 - i, t);
  }
  active_equality_count_ = active_count_;

  // ---- warm start: load the guessed rows, then solve the equality-constrained QP on that
  // working set, dropping the most negative multiplier until all are >= 0 ----
  if (guess_count > 0 && mi > 0) {
    for (int k = 0; k < guess_count; ++k) {
      const int i = guess_(k);
      if (i < 0 || i >= mi || in_working_set_(i)) continue;
      if (active_count_ >= n) break;  // every further row is dependent
      normal_.head(n) = -C.row(i).transpose();
      if (is_dependent(reduceNormal(n))) continue;
      appendToWorkingSet(i, 0.0);
      in_working_set_(i) = 1;
      ++warm_start_kept_;
      ++warm_start_updates_;  // a working-set update like any other: the warm start's work counts
    }
    if (warm_start_kept_ > 0) {
      gradient_.head(n).noalias() = J.transpose() * g;
      for (;;) {
        const int q = active_count_;
        // In y = J'x the problem reads min 1/2|y|^2 + (J'g)'y s.t. R'y1 = b, so
        // y1 = R^{-T} b, y2 = -J2'g, and R u = y1 + J1'g gives the multipliers.
        for (int j = 0; j < q; ++j) {
          const int code = active_(j);
          work_(j) = code < 0 ? -e(-1 - code) : -d(code);
        }
        R_.topLeftCorner(q, q).triangularView<Eigen::Upper>().transpose().solveInPlace(
            work_.head(q));
        u_.head(q) = work_.head(q) + gradient_.head(q);
        R_.topLeftCorner(q, q).triangularView<Eigen::Upper>().solveInPlace(u_.head(q));
        int most_negative = -1;
        double most_negative_value = 0.0;
        for (int j = active_equality_count_; j < q; ++j) {
          if (u_(j) < most_negative_value) {
            most_negative_value = u_(j);
            most_negative = j;
          }
        }
        if (most_negative < 0) {
          work_.segment(q, n - q) = -gradient_.segment(q, n - q);
          x.noalias() = J * work_.head(n);
          break;
        }
        in_working_set_(active_(most_negative)) = 0;
        dropFromWorkingSet(n, most_negative);
        --warm_start_kept_;
        ++warm_start_updates_;
        // The drop rotated columns most_negative..q-1 of J: refresh J'g there.
        gradient_.segment(most_negative, q - most_negative).noalias() =
            J.middleCols(most_negative, q - most_negative).transpose() * g;
      }
    }
  }

  // ---- dual iterations (the limit bounds them with the warm start's updates) ----
  iterations_ = warm_start_updates_;
  bool any_set_aside = false;
  auto release_set_aside = [&]() {
    if (!any_set_aside) return;
    for (int i = 0; i < mi; ++i) {
      if (in_working_set_(i) == kSetAside) in_working_set_(i) = 0;
    }
    any_set_aside = false;
  };
  for (;;) {
    // Step 1: pick the most violated constraint (violation scaled by the row norm). One product
    // C x per added constraint; choosing the most violated row keeps the iteration count low
    // (checking only the rows violated at an earlier scan was tried: more iterations, slower).
    if (mi == 0) break;
    slack_.head(mi).noalias() = C * x;
    slack_.head(mi) -= d;
    int p = -1;
    double worst = 0.0;
    for (int i = 0; i < mi; ++i) {
      const double s = slack_(i);
      if (s > feasibility_tol && !in_working_set_(i)) {
        const double scaled = s * row_scale_(i);
        if (scaled > worst) {
          worst = scaled;
          p = i;
        }
      }
    }
    if (p < 0) break;  // x is feasible: optimal

    normal_.head(n) = -C.row(p).transpose();
    double violation = -slack_(p);  // s_p = n'x - b < 0
    double u_plus = 0.0;            // multiplier of the constraint being added
    // Step 2: partial steps (each drops a constraint) until the full step adds p.
    for (;;) {
      if (iterations_ >= max_iterations) {
        storeResults(factor, g, x, me, mi, p, u_plus);
        return QpStatus::kIterationLimit;
      }
      // (a) directions: z = h J_q (after reduceNormal), r = R^{-1} d1
      const double h = reduceNormal(n);
      const bool dependent = is_dependent(h);
      const int q = active_count_;
      compute_dual_direction();
      // (b) step lengths: t1 keeps the inequality multipliers >= 0, t2 satisfies p.
      const int qe = active_equality_count_;
      double r_max = 0.0;
      for (int j = qe; j < q; ++j) r_max = std::max(r_max, std::abs(r_(j)));
      const double r_positive = kDualDirectionRelativeZero * r_max;
      double t1 = kInfinity;
      int k = -1;
      for (int j = qe; j < q; ++j) {
        if (r_(j) > r_positive) {
          const double ratio = u_(j) / r_(j);
          if (ratio < t1) {
            t1 = ratio;
            k = j;
          }
        }
      }
      t1 = std::max(t1, 0.0);
      // (c)
      if (dependent) {
        // n+ = N r: no primal direction. If no multiplier limits the dual ray, the dual is
        // unbounded: the constraints are inconsistent, b+ > sum_j r_j b_j (Farkas) ...
        if (k < 0) {
          // ... unless the violation is within what the working-set residuals (each counted
          // up to the feasibility tolerance) can explain: n+'x - b+ = sum_j r_j (n_j'x - b_j)
          // + (sum_j r_j b_j - b+). That happens at degenerate vertices, where more than n
          // constraints are tight and rounding makes one of them look violated. Such a row is
          // implied by the working set (n+'x <= sum_j r_j b_j ~ b+ on it), so it is set aside
          // until the working set loses a constraint.
          const double explainable = feasibility_tol * (1.0 + r_.head(q).cwiseAbs().sum());
          if (-violation > explainable) {
            storeResults(factor, g, x, me, mi, p, u_plus);
            return QpStatus::kInfeasible;
          }
          // H x + g = N u + u+ n+ = N (u + u+ r): fold the multiplier of p into the working set
          // (u+ is 0 unless pure dual steps were taken for p, which rounding alone can cause).
          u_.head(q) += u_plus * r_.head(q);
          for (int j = qe; j < q; ++j) u_(j) = std::max(u_(j), 0.0);
          in_working_set_(p) = kSetAside;
          any_set_aside = true;
          break;
        }
        // Pure dual step, then drop k; n+ can then enter the space freed by k.
        u_.head(q) -= t1 * r_.head(q);
        for (int j = qe; j < q; ++j) u_(j) = std::max(u_(j), 0.0);
        u_plus += t1;
        in_working_set_(active_(k)) = 0;
        dropFromWorkingSet(n, k);
        release_set_aside();
        ++iterations_;
        continue;
      }
      const double free_norm2 = h * h;  // z'n+
      const double t2 = -violation / free_norm2;
      const bool full_step = t2 <= t1;
      const double t = full_step ? t2 : t1;
      x += (t * h) * J.col(q);
      u_.head(q) -= t * r_.head(q);
      for (int j = qe; j < q; ++j) u_(j) = std::max(u_(j), 0.0);
      u_plus += t;
      violation += t * free_norm2;
      ++iterations_;
      if (full_step) {
        appendToWorkingSet(p, u_plus);
        in_working_set_(p) = 1;
        break;
      }
      in_working_set_(active_(k)) = 0;
      dropFromWorkingSet(n, k);
      release_set_aside();
    }
  }

  storeResults(factor, g, x, me, mi, -1, 0.0);
  return QpStatus::kOptimal;
}

}  // namespace wpg::qp
