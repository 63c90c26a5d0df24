// Goldfarb-Idnani dual active-set method (D. Goldfarb, A. Idnani, "A numerically stable dual
// method for solving strictly convex quadratic programs", Math. Programming 27, 1983): solve()
// and its steps. The factorization they update is in working_set_factorization.cpp.
//
// Notation of the paper. Constraints are handled in the form n_j'x >= b_j: an inequality row
// C_i x <= d_i becomes n = -C_i', b = -d_i, and an equality E_i x = e_i likewise (its
// multiplier is free in sign). With these signs the paper's multipliers u satisfy
// H x + g = N u, i.e. H x + g + E'mu + C'lambda = 0 with mu, lambda read off u directly.
// For a constraint n+ about to be added (d = J' n+ = [d1; d2], working_set_factorization.cpp):
//   z = J2 d2 = h J_q   primal step direction (change of x per unit of the new multiplier),
//   r = R^{-1} d1       dual step direction (minus the change of the working-set multipliers).
// The steps of solve(): the unconstrained minimum (step 0), the equalities (full steps), the
// warm start (the guessed rows, then the minimum on that working set), then the dual
// iterations: the most violated row (step 1), added by partial steps that each drop the
// constraint whose multiplier reaches zero first, then a full step (step 2).
//
// Beyond the paper: the most violated row is chosen after scaling by the row norm, dependent
// rows use a relative test (see QpSettings::dependence_tolerance), and a dependent row whose
// violation is within rounding of the working set is set aside instead of reported as proof of
// infeasibility (degenerate vertices).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "qp_internal.hpp"
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
  objective_gradient_.setZero(max_n_);
  objective_iterate_.setZero(max_n_);
  objective_work_.setZero(max_n_);
  slack_.setZero(max_mi_);
  row_scale_.setZero(max_mi_);
  cosines_.setZero(max_n_);
  sines_.setZero(max_n_);
  normal_pairs_.setZero(max_n_ / 2 + 1);
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

void DenseQpSolver::storeResults(const Eigen::Ref<const Eigen::VectorXd>& g,
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
  const int n = static_cast<int>(x.size());
  has_objective_ = true;
  objective_gradient_.head(n) = g;
  objective_iterate_.head(n) = x;
  objective_size_ = n;
}

double DenseQpSolver::objective(const HessianFactor& factor) const {
  if (!has_objective_) return 0.0;
  const int n = objective_size_;
  if (factor.size != n) {
    throw std::invalid_argument("DenseQpSolver::objective: expected the factor of the last solve (" +
                                std::to_string(n) + " variables), got one of " +
                                std::to_string(factor.size));
  }
  // f = 1/2 |L'x|^2 + g'x with L' = J0^{-1}.
  const auto x = objective_iterate_.head(n);
  objective_work_.head(n) = x;
  factor.inverse_factor_transposed.topLeftCorner(n, n)
      .triangularView<Eigen::Upper>()
      .solveInPlace(objective_work_.head(n));
  return 0.5 * objective_work_.head(n).squaredNorm() + objective_gradient_.head(n).dot(x);
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
  has_objective_ = false;
  warm_start_kept_ = 0;
  active_inequality_count_ = 0;
  active_count_ = 0;
  active_equality_count_ = 0;
  const int guess_count = guess_count_;
  guess_count_ = 0;  // the guess is for this solve only

  const int n = static_cast<int>(g.size());
  const int me = static_cast<int>(E.rows());
  const int mi = static_cast<int>(C.rows());
  if (!sizesFit(factor, g, E, e, C, d, x)) {
    if (x.size() == n && n <= max_n_) x.setZero();
    return QpStatus::kInvalidInput;
  }
  // lambda_/mu_ keep their capacity; the accessors return the first mi / me entries, so
  // changing problem sizes never allocate.
  last_mi_ = mi;
  last_me_ = me;
  lambda_.setZero();
  mu_.setZero();
  if (!scaleInequalityRows(g, E, e, C, d)) {
    x.setZero();
    return QpStatus::kInvalidInput;
  }
  in_working_set_.head(mi).setZero();

  startFromUnconstrainedMinimum(factor, g);
  if (!addEqualities(factor, g, E, e, x)) {
    storeResults(g, x, me, mi, -1, 0.0);
    return QpStatus::kInfeasible;  // inconsistent equalities
  }
  active_equality_count_ = active_count_;
  if (guess_count > 0 && mi > 0) {
    loadGuessedRows(guess_count, C, n);
    if (warm_start_kept_ > 0) {
      solveOnWorkingSet(g, e, d, x);  // the iterate afresh: the one of the equalities is not needed
      iterate_steps_ = -1;
    }
  }
  updateIterate(factor, g, E, e, x);

  // Dual iterations (the iteration limit bounds them with the warm start's updates).
  iterations_ = warm_start_updates_;
  any_set_aside_ = false;
  for (;;) {
    const int p = mostViolatedRow(C, d, x);
    if (p == kInvalidRow) {
      // A non-finite entry of C (or an overflowing row): nothing of this solve is kept.
      x.setZero();
      iterations_ = warm_start_updates_ = warm_start_kept_ = 0;
      active_count_ = active_equality_count_ = 0;
      return QpStatus::kInvalidInput;
    }
    if (p < 0) break;
    const QpStatus status = addViolatedRow(p, g, C, x, me);
    if (status != QpStatus::kOptimal) return status;
  }
  storeResults(g, x, me, mi, -1, 0.0);
  return QpStatus::kOptimal;
}

bool DenseQpSolver::sizesFit(const HessianFactor& factor, const Eigen::Ref<const Eigen::VectorXd>& g,
                             const Eigen::Ref<const Eigen::MatrixXd>& E,
                             const Eigen::Ref<const Eigen::VectorXd>& e,
                             const Eigen::Ref<const Eigen::MatrixXd>& C,
                             const Eigen::Ref<const Eigen::VectorXd>& d,
                             const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const Eigen::Index n = g.size(), me = E.rows(), mi = C.rows();
  return n <= max_n_ && me <= max_me_ && mi <= max_mi_ && x.size() == n && factor.size == n &&
         factor.inverse_factor_transposed.rows() >= n &&
         factor.inverse_factor_transposed.cols() >= n && (me == 0 || E.cols() == n) &&
         e.size() == me && (mi == 0 || C.cols() == n) && d.size() == mi;
}

bool DenseQpSolver::scaleInequalityRows(const Eigen::Ref<const Eigen::VectorXd>& g,
                                        const Eigen::Ref<const Eigen::MatrixXd>& E,
                                        const Eigen::Ref<const Eigen::VectorXd>& e,
                                        const Eigen::Ref<const Eigen::MatrixXd>& C,
                                        const Eigen::Ref<const Eigen::VectorXd>& d) {
  // The row norms of C (for the scale-invariant choice of the most violated row) are computed
  // when a row is first found violated (rowScale): most rows never are, and C is the largest
  // input. C's entries are checked for finiteness by the first product C x (mostViolatedRow):
  // with x finite, a non-finite entry makes its row's C x non-finite (the entries a profile
  // says are zeros are not read: setInequalityProfile).
  const int me = static_cast<int>(E.rows()), mi = static_cast<int>(C.rows());
  row_scale_.head(mi).setZero();  // 0 = not computed yet (a computed scale is > 0)
  return g.allFinite() && e.allFinite() && d.allFinite() && (me == 0 || E.allFinite());
}

double DenseQpSolver::rowScale(const Eigen::Ref<const Eigen::MatrixXd>& C, int i) {
  if (row_scale_(i) > 0.0) return row_scale_(i);
  // The squares summed in column order, as a column-by-column accumulation over all rows would.
  double norm2 = 0.0;
  for (Eigen::Index col = 0; col < C.cols(); ++col) norm2 += C(i, col) * C(i, col);
  if (!std::isfinite(norm2)) return -1.0;  // overflows (> ~1e154): invalid input
  const double norm = std::sqrt(norm2);
  row_scale_(i) = norm > 0.0 ? 1.0 / norm : 1.0;
  return row_scale_(i);
}

void DenseQpSolver::startFromUnconstrainedMinimum(const HessianFactor& factor,
                                                  const Eigen::Ref<const Eigen::VectorXd>& g) {
  // J = J0: J' H J = I, and every column of J is free. Copied column by column, the upper
  // triangle and then zeros (with the padding rows), as a triangular view would assign it.
  const int n = static_cast<int>(g.size());
  const int rows = paddedRows(n);
  const Eigen::MatrixXd& J0 = factor.inverse_factor_transposed;
  for (int k = 0; k < n; ++k) {  // plain copies: Eigen's short dynamic segments cost more
    double* column = J_.col(k).data();
    std::memcpy(column, J0.col(k).data(), static_cast<std::size_t>(k + 1) * sizeof(double));
    std::fill(column + k + 1, column + rows, 0.0);
  }
  iterate_steps_ = 0;  // x = -H^{-1} g is computed when needed (updateIterate)
}

void DenseQpSolver::updateIterate(const HessianFactor& factor,
                                  const Eigen::Ref<const Eigen::VectorXd>& g,
                                  const Eigen::Ref<const Eigen::MatrixXd>& E,
                                  const Eigen::Ref<const Eigen::VectorXd>& e,
                                  Eigen::Ref<Eigen::VectorXd> x) {
  if (iterate_steps_ < 0) return;
  const int n = static_cast<int>(x.size());
  if (iterate_steps_ == 0) {
    x = -g;  // x = -H^{-1} g = -J0 J0' g
    factor.solveInPlace(x);
    iterate_steps_ = 1;
  }
  // The full step of each equality added since, as it would have been taken when the equality
  // was added: column q of J, column q of R and the dual direction from R's first q columns
  // have not changed since (later updates touch only the columns after the equalities').
  for (int q = iterate_steps_ - 1; q < active_count_ && active_(q) < 0; ++q) {
    const int i = -1 - active_(q);
    normal_.head(n) = -E.row(i).transpose();
    const double violation = normal_.head(n).dot(x) + e(i);  // s = n'x - b with b = -e_i
    const double h = R_(q, q);
    r_.head(q) = R_.col(q).head(q);
    R_.topLeftCorner(q, q).triangularView<Eigen::Upper>().solveInPlace(r_.head(q));
    const double t = -violation / (h * h);
    x += (t * h) * J_.col(q).head(n);  // z = h J_q
    u_.head(q) -= t * r_.head(q);
    u_(q) = t;
    iterate_steps_ = q + 2;
  }
}

bool DenseQpSolver::isDependent(double h, int n) const {
  const int q = active_count_;
  return h * h <= settings_.dependence_tolerance * d_.head(std::min(q + 1, n)).squaredNorm();
}

void DenseQpSolver::computeDualDirection() {
  const int q = active_count_;
  r_.head(q) = d_.head(q);
  R_.topLeftCorner(q, q).triangularView<Eigen::Upper>().solveInPlace(r_.head(q));
}

bool DenseQpSolver::addEqualities(const HessianFactor& factor,
                                  const Eigen::Ref<const Eigen::VectorXd>& g,
                                  const Eigen::Ref<const Eigen::MatrixXd>& E,
                                  const Eigen::Ref<const Eigen::VectorXd>& e,
                                  Eigen::Ref<Eigen::VectorXd> x) {
  // Each is a full step of the paper with an unrestricted multiplier (no inequality is in the
  // working set yet, so no partial step can occur). The steps themselves wait for updateIterate:
  // a warm start that keeps a guessed row computes its iterate afresh and needs none of them.
  const int n = static_cast<int>(x.size());
  for (int i = 0; i < E.rows(); ++i) {
    normal_.head(n) = -E.row(i).transpose();
    const double h = reduceNormal(n);
    const int q = active_count_;
    if (isDependent(h, n)) {
      // n+ = N r: consistent (hence redundant) when the violation is within what the
      // residuals of the equalities already in the working set can explain.
      updateIterate(factor, g, E, e, x);
      normal_.head(n) = -E.row(i).transpose();
      const double violation = normal_.head(n).dot(x) + e(i);  // s = n'x - b with b = -e_i
      computeDualDirection();
      const double explainable =
          settings_.feasibility_tolerance * (1.0 + r_.head(q).cwiseAbs().sum());
      if (std::abs(violation) <= explainable) continue;
      return false;
    }
    appendToWorkingSet(-1 - i, 0.0);  // its multiplier: updateIterate
  }
  return true;
}

void DenseQpSolver::loadGuessedRows(int guess_count, const Eigen::Ref<const Eigen::MatrixXd>& C,
                                    int n) {
  const int mi = static_cast<int>(C.rows());
  for (int k = 0; k < guess_count; ++k) {
    const int i = guess_(k);
    if (i < 0 || i >= mi || in_working_set_(i)) continue;
    if (active_count_ >= n) break;  // every further row is dependent
    normal_.head(n) = -C.row(i).transpose();
    if (isDependent(reduceNormal(n), n)) continue;
    appendToWorkingSet(i, 0.0);
    in_working_set_(i) = 1;
    ++warm_start_kept_;
    ++warm_start_updates_;  // a working-set update like any other: the warm start's work counts
  }
}

void DenseQpSolver::solveOnWorkingSet(const Eigen::Ref<const Eigen::VectorXd>& g,
                                      const Eigen::Ref<const Eigen::VectorXd>& e,
                                      const Eigen::Ref<const Eigen::VectorXd>& d,
                                      Eigen::Ref<Eigen::VectorXd> x) {
  const int n = static_cast<int>(g.size());
  const auto J = J_.topLeftCorner(n, n);
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
      return;
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

int DenseQpSolver::mostViolatedRow(const Eigen::Ref<const Eigen::MatrixXd>& C,
                                   const Eigen::Ref<const Eigen::VectorXd>& d,
                                   const Eigen::Ref<const Eigen::VectorXd>& x) {
  // One product C x per added constraint; choosing the most violated row keeps the iteration
  // count low (checking only the rows violated at an earlier scan was tried: more iterations,
  // slower).
  const int mi = static_cast<int>(C.rows());
  if (mi == 0) return -1;
  if (inequality_profile_.fits(C)) {
    eigen_assert(inequality_profile_.covers(C) && "C is nonzero outside its profile");
    inequality_profile_.multiplySubtract(C, x, d, slack_.head(mi));  // the same bits
  } else {
    slack_.head(mi).noalias() = C * x;
    slack_.head(mi) -= d;
  }
  int p = -1;
  double worst = 0.0;
  bool finite = true;
  for (int i = 0; i < mi; ++i) {
    const double s = slack_(i);
    finite = finite && std::isfinite(s);
    if (s > settings_.feasibility_tolerance && !in_working_set_(i)) {
      const double scale = rowScale(C, i);
      if (scale < 0.0) return kInvalidRow;
      const double scaled = s * scale;
      if (scaled > worst) {
        worst = scaled;
        p = i;
      }
    }
  }
  return finite ? p : kInvalidRow;
}

double DenseQpSolver::dualStepLength(int* blocking) const {
  const int q = active_count_, qe = active_equality_count_;
  double r_max = 0.0;
  for (int j = qe; j < q; ++j) r_max = std::max(r_max, std::abs(r_(j)));
  const double r_positive = kDualDirectionRelativeZero * r_max;
  double t1 = kInfinity;
  *blocking = -1;
  for (int j = qe; j < q; ++j) {
    if (r_(j) > r_positive) {
      const double ratio = u_(j) / r_(j);
      if (ratio < t1) {
        t1 = ratio;
        *blocking = j;
      }
    }
  }
  return std::max(t1, 0.0);
}

void DenseQpSolver::stepMultipliers(double t) {
  const int q = active_count_;
  u_.head(q) -= t * r_.head(q);
  for (int j = active_equality_count_; j < q; ++j) u_(j) = std::max(u_(j), 0.0);
}

void DenseQpSolver::dropInequality(int n, int mi, int position) {
  in_working_set_(active_(position)) = 0;
  dropFromWorkingSet(n, position);
  releaseSetAside(mi);
}

void DenseQpSolver::releaseSetAside(int mi) {
  if (!any_set_aside_) return;
  for (int i = 0; i < mi; ++i) {
    if (in_working_set_(i) == kSetAside) in_working_set_(i) = 0;
  }
  any_set_aside_ = false;
}

QpStatus DenseQpSolver::addViolatedRow(int p, const Eigen::Ref<const Eigen::VectorXd>& g,
                                       const Eigen::Ref<const Eigen::MatrixXd>& C,
                                       Eigen::Ref<Eigen::VectorXd> x, int me) {
  const int n = static_cast<int>(x.size()), mi = static_cast<int>(C.rows());
  normal_.head(n) = -C.row(p).transpose();
  double violation = -slack_(p);  // s_p = n'x - b < 0
  double u_plus = 0.0;            // multiplier of the constraint being added
  for (;;) {
    if (iterations_ >= settings_.max_iterations) {
      storeResults(g, x, me, mi, p, u_plus);
      return QpStatus::kIterationLimit;
    }
    // (a) directions: z = h J_q (after reduceNormal), r = R^{-1} d1
    const double h = reduceNormal(n);
    const bool dependent = isDependent(h, n);
    const int q = active_count_;
    computeDualDirection();
    // (b) step lengths: t1 keeps the inequality multipliers >= 0, t2 satisfies p.
    int k = -1;
    const double t1 = dualStepLength(&k);
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
        const double explainable =
            settings_.feasibility_tolerance * (1.0 + r_.head(q).cwiseAbs().sum());
        if (-violation > explainable) {
          storeResults(g, x, me, mi, p, u_plus);
          return QpStatus::kInfeasible;
        }
        // H x + g = N u + u+ n+ = N (u + u+ r): fold the multiplier of p into the working set
        // (u+ is 0 unless pure dual steps were taken for p, which rounding alone can cause).
        stepMultipliers(-u_plus);
        in_working_set_(p) = kSetAside;
        any_set_aside_ = true;
        return QpStatus::kOptimal;
      }
      // Pure dual step, then drop k; n+ can then enter the space freed by k.
      stepMultipliers(t1);
      u_plus += t1;
      dropInequality(n, mi, k);
      ++iterations_;
      continue;
    }
    const double free_norm2 = h * h;  // z'n+
    const double t2 = -violation / free_norm2;
    const bool full_step = t2 <= t1;
    const double t = full_step ? t2 : t1;
    x += (t * h) * J_.col(q).head(n);
    stepMultipliers(t);
    u_plus += t;
    violation += t * free_norm2;
    ++iterations_;
    if (full_step) {
      appendToWorkingSet(p, u_plus);
      in_working_set_(p) = 1;
      return QpStatus::kOptimal;
    }
    dropInequality(n, mi, k);
  }
}

}  // namespace wpg::qp
