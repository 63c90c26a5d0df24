#pragma once
// Dense strictly convex QP solver: the dual active-set method of Goldfarb & Idnani (1983),
//   minimize 1/2 x'Hx + g'x   subject to   E x = e,   C x <= d,
// with H symmetric positive definite. Sized once at construction (capacities); solve() does
// not allocate. The Cholesky factor of H is computed separately (HessianFactor) so callers
// whose Hessian does not change between solves (the NMPC's Gauss-Newton Hessian is constant
// for a given walking phase) pay for it once.
//
// Warm start: an active-set guess (e.g. the previous solution's active set, shifted in time)
// is loaded into the factorization before the dual iterations start; guessed constraints that
// are linearly dependent or get negative multipliers are dropped, then the ordinary dual
// method continues. A good guess leaves zero or few iterations.
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "wpg/qp/column_profile.hpp"

namespace wpg::qp {

enum class QpStatus {
  kOptimal = 0,
  kInfeasible = 1,      // no x satisfies the constraints (detected by the dual method)
  kIterationLimit = 2,  // iteration limit hit; x holds the last (dual-feasible) iterate
  kInvalidInput = 3,    // sizes out of capacity, non-finite data
};
const char* qpStatusName(QpStatus status);

// J = L^{-T} where H = L L^T. Computed once per Hessian.
struct HessianFactor {
  Eigen::MatrixXd inverse_factor_transposed;  // n x n upper triangular, L^{-T}
  int size = 0;
  // Returns false (and leaves size = 0) when H is not symmetric positive definite (numerically:
  // a Cholesky pivot below the rounding level). Reads the lower triangle of H only.
  bool compute(const Eigen::Ref<const Eigen::MatrixXd>& hessian);
  // The same with the caller's Cholesky storage: no allocation once `llt` and this factor
  // have held a Hessian of this size (a Hessian that changes every solve: NMPC cost terms).
  bool compute(const Eigen::Ref<const Eigen::MatrixXd>& hessian, Eigen::LLT<Eigen::MatrixXd>& llt);
  // Solves H x = b in place using the factor (x := H^{-1} b).
  void solveInPlace(Eigen::Ref<Eigen::VectorXd> b) const;
};

struct QpSettings {
  int max_iterations = 200;
  double feasibility_tolerance = 1e-10;  // a constraint counts as violated above this [units of C x - d]
  double dependence_tolerance = 1e-12;   // linear dependence test on new active constraints:
                                         // dependent when |z|_H^2 <= tol |n|_{H^-1}^2, i.e.
                                         // sin^2 of its angle to the working set <= tol
};

class DenseQpSolver {
 public:
  DenseQpSolver(int max_variables, int max_equalities, int max_inequalities);

  // Solves the QP. E (me x n), e (me), C (mi x n), d (mi) may have zero rows. On kOptimal
  // x is the minimizer; otherwise x holds the last iterate (never NaN). Does not allocate
  // (except that the multiplier vectors are resized when mi or me differ from the last solve).
  QpStatus solve(const HessianFactor& factor, const Eigen::Ref<const Eigen::VectorXd>& g,
                 const Eigen::Ref<const Eigen::MatrixXd>& E,
                 const Eigen::Ref<const Eigen::VectorXd>& e,
                 const Eigen::Ref<const Eigen::MatrixXd>& C,
                 const Eigen::Ref<const Eigen::VectorXd>& d, Eigen::Ref<Eigen::VectorXd> x);

  // Indices (into C's rows) to load as the initial active set of the next solve() only.
  // Indices out of range are ignored. Copies into preallocated storage (no allocation).
  void setActiveSetGuess(const int* inequality_indices, int count);
  void clearActiveSetGuess();

  // The structure of the C of the next solves (wpg/qp/column_profile.hpp): their products C x
  // read only the entries it says may be nonzero (the others must be zeros). Used for a C of
  // the profile's size, ignored for others. Copies it (allocates: once, not per solve).
  void setInequalityProfile(const ColumnProfile& profile) { inequality_profile_ = profile; }

  QpSettings& settings() { return settings_; }
  const QpSettings& settings() const { return settings_; }

  // --- results of the last solve ---
  // Working-set updates of the last solve: the warm start's (each guessed row loaded, each
  // dropped for a negative multiplier) plus the dual method's adds and drops. The iteration
  // limit (settings().max_iterations) bounds this total.
  int iterations() const { return iterations_; }
  // The part of iterations() spent loading the guess (rows loaded, rows dropped for a negative
  // multiplier). Loading a row skips the scan for the most violated constraint (C x), so it
  // costs less time than a dual iteration, but it is work: a warm start can take more updates
  // than a cold solve and still be faster.
  int warmStartUpdates() const { return warm_start_updates_; }
  // Active inequality rows at the solution (indices into C), count = activeInequalityCount().
  const int* activeInequalities() const { return active_inequalities_.data(); }
  int activeInequalityCount() const { return active_inequality_count_; }
  // Lagrange multipliers: H x + g + E'mu + C'lambda = 0, lambda >= 0, lambda_i (C x - d)_i = 0.
  // Views of size mi / me of the last solve (storage sized by the capacities: no allocation).
  Eigen::VectorBlock<const Eigen::VectorXd> inequalityMultipliers() const {
    return lambda_.head(last_mi_);
  }
  Eigen::VectorBlock<const Eigen::VectorXd> equalityMultipliers() const {
    return mu_.head(last_me_);
  }
  // f(x) = 1/2 x'Hx + g'x at the returned iterate (0 after invalid input), given the factor of
  // H passed to the last solve (std::invalid_argument if its size differs). Evaluated when
  // asked: the NMPC never asks, and the triangular solve it takes was ~4 % of an iteration.
  double objective(const HessianFactor& factor) const;
  // How many of the guessed inequality rows (setActiveSetGuess) were still in the working set
  // when the dual iterations started (linearly dependent ones and ones with negative
  // multipliers are dropped). 0 when no guess was given.
  int warmStartKept() const { return warm_start_kept_; }

 private:
  // --- the steps of solve() (dense_qp_solver.cpp), in the order it takes them ---
  // Whether the data fit the capacities and each other (sizes only).
  bool sizesFit(const HessianFactor& factor, const Eigen::Ref<const Eigen::VectorXd>& g,
                const Eigen::Ref<const Eigen::MatrixXd>& E,
                const Eigen::Ref<const Eigen::VectorXd>& e,
                const Eigen::Ref<const Eigen::MatrixXd>& C,
                const Eigen::Ref<const Eigen::VectorXd>& d,
                const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // Marks every row scale 1 / ||C_i|| not computed yet (rowScale computes them on demand);
  // false when some entry of g, E, e or d is not finite (C's are checked by mostViolatedRow).
  bool scaleInequalityRows(const Eigen::Ref<const Eigen::VectorXd>& g,
                           const Eigen::Ref<const Eigen::MatrixXd>& E,
                           const Eigen::Ref<const Eigen::VectorXd>& e,
                           const Eigen::Ref<const Eigen::MatrixXd>& C,
                           const Eigen::Ref<const Eigen::VectorXd>& d);
  // Step 0: J = J0, empty working set; x = -H^{-1} g left to updateIterate.
  void startFromUnconstrainedMinimum(const HessianFactor& factor,
                                     const Eigen::Ref<const Eigen::VectorXd>& g);
  // Adds every equality to the working set (their full steps left to updateIterate); false
  // when they are inconsistent.
  bool addEqualities(const HessianFactor& factor, const Eigen::Ref<const Eigen::VectorXd>& g,
                     const Eigen::Ref<const Eigen::MatrixXd>& E,
                     const Eigen::Ref<const Eigen::VectorXd>& e, Eigen::Ref<Eigen::VectorXd> x);
  // Brings x (and the equalities' multipliers) up to the working set's equalities: x = -H^{-1}
  // g, then the full step of each equality added since, in order, with the same operations as
  // if each had been taken when it was added. Nothing when the iterate was computed afresh.
  void updateIterate(const HessianFactor& factor, const Eigen::Ref<const Eigen::VectorXd>& g,
                     const Eigen::Ref<const Eigen::MatrixXd>& E,
                     const Eigen::Ref<const Eigen::VectorXd>& e, Eigen::Ref<Eigen::VectorXd> x);
  // Loads the guessed inequality rows that are independent of the working set.
  void loadGuessedRows(int guess_count, const Eigen::Ref<const Eigen::MatrixXd>& C, int n);
  // The minimum on the working set, dropping the most negative inequality multiplier until
  // all are >= 0 (the warm start's primal point).
  void solveOnWorkingSet(const Eigen::Ref<const Eigen::VectorXd>& g,
                         const Eigen::Ref<const Eigen::VectorXd>& e,
                         const Eigen::Ref<const Eigen::VectorXd>& d,
                         Eigen::Ref<Eigen::VectorXd> x);
  // 1 / ||C_i|| (1 for a zero row), computed at the first call of the solve; -1 when the
  // squared norm is not finite.
  double rowScale(const Eigen::Ref<const Eigen::MatrixXd>& C, int i);
  // Step 1: the most violated row not in the working set (violation scaled by the row norm),
  // -1 when x is feasible, kInvalidRow when C x - d is not finite (a non-finite entry of C,
  // x being finite) or a violated row's norm overflows. slack_ = C x - d afterwards.
  static constexpr int kInvalidRow = -2;
  int mostViolatedRow(const Eigen::Ref<const Eigen::MatrixXd>& C,
                      const Eigen::Ref<const Eigen::VectorXd>& d,
                      const Eigen::Ref<const Eigen::VectorXd>& x);
  // Step 2: partial steps, each dropping a constraint, until the full step adds row p (or p
  // is set aside as implied by the working set). kOptimal then, else kInfeasible or
  // kIterationLimit with the results stored.
  QpStatus addViolatedRow(int p, const Eigen::Ref<const Eigen::VectorXd>& g,
                          const Eigen::Ref<const Eigen::MatrixXd>& C,
                          Eigen::Ref<Eigen::VectorXd> x, int me);
  // Linear dependence of the constraint just reduced (reduceNormal() returned h) on the
  // working set: |z|_H^2 = h^2 negligible against |n+|_{H^-1}^2 = |d|^2.
  bool isDependent(double h, int n) const;
  // r = R^{-1} d1: the dual step direction (minus the change of the working-set multipliers).
  void computeDualDirection();
  // The longest dual step t1 that keeps the inequality multipliers >= 0, and the working-set
  // position `blocking` of the one it zeroes (-1 and infinity when none limits it).
  double dualStepLength(int* blocking) const;
  // u <- u - t r on the working set, inequality multipliers clamped at 0 (rounding).
  void stepMultipliers(double t);
  // Removes working-set position `position` (an inequality) and lets the rows set aside
  // compete again: the working set has lost a constraint.
  void dropInequality(int n, int mi, int position);
  void releaseSetAside(int mi);
  // Copies multipliers and active set of the current iterate into the results, and what
  // objective() needs.
  void storeResults(const Eigen::Ref<const Eigen::VectorXd>& g,
                    const Eigen::Ref<const Eigen::VectorXd>& x, int me, int mi, int pending,
                    double pending_multiplier);

  // --- updates of the factorization J, R when the working set changes ---
  // d_ = J' normal_, then Givens rotations of the free columns J2 (any orthonormal basis of the
  // free space will do) bring d2 to (h, 0, ..., 0); returns h = |d2| >= 0. Afterwards the
  // primal direction z = J2 J2' n+ is h times column q of J.
  double reduceNormal(int n);
  // Appends the constraint reduced by the last reduceNormal() to the working set.
  void appendToWorkingSet(int code, double multiplier);
  // Removes working-set entry `position` (Givens rotations restore R, applied to J too).
  void dropFromWorkingSet(int n, int position);

  int max_n_, max_me_, max_mi_;
  QpSettings settings_;
  ColumnProfile inequality_profile_;  // default: C dense
  int iterations_ = 0;
  int warm_start_updates_ = 0;
  // What objective() needs: whether the last solve returned an iterate, g and x.
  bool has_objective_ = false;
  Eigen::VectorXd objective_gradient_;  // max_n
  Eigen::VectorXd objective_iterate_;   // max_n
  mutable Eigen::VectorXd objective_work_;  // max_n
  int objective_size_ = 0;
  int warm_start_kept_ = 0;
  Eigen::VectorXi active_inequalities_;  // max_mi
  int active_inequality_count_ = 0;
  Eigen::VectorXi guess_;                // max_mi
  int guess_count_ = 0;
  Eigen::VectorXd lambda_, mu_;          // capacity-sized; the last solve used the heads
  int last_mi_ = 0, last_me_ = 0;
  // Workspace (all sized in the constructor from the capacities; see dense_qp_solver.cpp).
  // The working set is stored in Goldfarb-Idnani form n_j'x >= b_j (n_j = -row, b_j = -rhs).
  Eigen::MatrixXd J_;             // max_n x max_n: J = L^{-T} Q, [J1 | J2], J2 spans the free space
  Eigen::MatrixXd R_;             // max_n x max_n: upper triangular R of L^{-1} N = Q [R; 0]
  Eigen::VectorXd d_;             // max_n: J' n+ of the constraint being added
  Eigen::VectorXd r_;             // max_n: dual step direction R^{-1} J1' n+
  Eigen::VectorXd u_;             // max_n: multipliers of the working set
  Eigen::VectorXd normal_;        // max_n: n+ = -(row of C or E)
  Eigen::VectorXd work_;          // max_n: temporaries
  Eigen::VectorXd gradient_;      // max_n: J'g (warm start)
  Eigen::VectorXd cosines_, sines_;  // max_n: Givens rotations of one update, applied to J at once
  Eigen::VectorXi normal_pairs_;  // max_n / 2: the pairs (2i, 2i + 1) of normal_ not both zero
  Eigen::VectorXd slack_;         // max_mi: C x - d (positive = violated)
  Eigen::VectorXd row_scale_;     // max_mi: 1 / ||C_i|| (1 for zero rows), 0 = not computed yet
  Eigen::VectorXi active_;        // max_n: working set, equality i -> -1-i, inequality i -> i
  Eigen::Matrix<unsigned char, Eigen::Dynamic, 1> in_working_set_;  // max_mi
  int active_count_ = 0;          // q
  int active_equality_count_ = 0; // equalities in the working set (always the first ones)
  bool any_set_aside_ = false;    // some in_working_set_ entry is kSetAside
  // updateIterate: 0 = x not computed yet; k > 0 = x holds -H^{-1} g and the full steps of the
  // working set's first k - 1 equalities; -1 = x is current (computed afresh)
  int iterate_steps_ = 0;
};

}  // namespace wpg::qp
