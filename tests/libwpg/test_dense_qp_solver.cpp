// Tests of the Goldfarb-Idnani dense QP solver: KKT conditions on random (also degenerate)
// problems, infeasibility detection, brute force on tiny problems, the iteration limit, bad
// input, allocation (its warm start: test_dense_qp_warm_start.cpp; the problems:
// qp_test_problems.hpp).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "../common/sanitizer_malloc.hpp"
#include "qp_test_problems.hpp"
#include "wpg/qp/dense_qp_solver.hpp"

// ---- heap allocation counter (glibc: every malloc of the process, whatever the TU) ----------
// Eigen allocates with std::malloc (operator new does too), so replacing malloc sees every
// heap allocation, also in the library's translation units and in Release builds, where
// Eigen's own EIGEN_RUNTIME_NO_MALLOC check (an eigen_assert) is compiled out. Sanitizers
// replace malloc themselves: there the count comes from their allocation hook
// (sanitizer_malloc.hpp).
#if defined(__GLIBC__) && !defined(WPG_TEST_SANITIZER_OWNS_MALLOC)
#define WPG_TEST_COUNT_MALLOC 1
extern "C" void* __libc_malloc(std::size_t size);
namespace {
bool g_count_mallocs = false;
long g_malloc_count = 0;
}  // namespace
extern "C" void* malloc(std::size_t size) {
  if (g_count_mallocs) ++g_malloc_count;
  return __libc_malloc(size);
}
#elif defined(WPG_TEST_SANITIZER_OWNS_MALLOC)
#define WPG_TEST_COUNT_MALLOC 1
namespace {
bool g_count_mallocs = false;
long g_malloc_count = 0;
void countMalloc(const volatile void*, std::size_t) {
  if (g_count_mallocs) ++g_malloc_count;
}
void ignoreFree(const volatile void*) {}
[[maybe_unused]] const int g_hook_installed =
    __sanitizer_install_malloc_and_free_hooks(countMalloc, ignoreFree);
}  // namespace
#endif

namespace {

using namespace qp_test;

// ---------------------------------------------------------------------------------------------

TEST(HessianFactor, RejectsNonSpdAndSolves) {
  HessianFactor f;
  MatrixXd indefinite(2, 2);
  indefinite << 1, 2, 2, 1;
  EXPECT_FALSE(f.compute(indefinite));
  EXPECT_EQ(f.size, 0);
  EXPECT_FALSE(f.compute(MatrixXd::Zero(3, 3)));
  EXPECT_FALSE(f.compute(MatrixXd::Identity(2, 3)));
  MatrixXd nan_h = MatrixXd::Identity(2, 2);
  nan_h(1, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(f.compute(nan_h));

  Rng rng(7);
  const MatrixXd h = randomSpd(rng, 12);
  ASSERT_TRUE(f.compute(h));
  EXPECT_EQ(f.size, 12);
  const MatrixXd& j0 = f.inverse_factor_transposed;
  EXPECT_TRUE((j0.transpose() * h * j0).isApprox(MatrixXd::Identity(12, 12), 1e-10));
  EXPECT_EQ(j0.triangularView<Eigen::StrictlyLower>().toDenseMatrix().cwiseAbs().maxCoeff(), 0.0);
  const VectorXd b = rng.normalVector(12);
  VectorXd x = b;
  f.solveInPlace(x);
  EXPECT_LE((h * x - b).cwiseAbs().maxCoeff(), 1e-10 * (1.0 + b.cwiseAbs().maxCoeff()));
}

TEST(DenseQpSolver, UnconstrainedAndSimple) {
  // min 1/2|x|^2 - [1 1]'x s.t. x0 + x1 <= 1  ->  x = (0.5, 0.5), lambda = 0.5
  MatrixXd h = MatrixXd::Identity(2, 2);
  VectorXd g(2);
  g << -1, -1;
  MatrixXd c(1, 2);
  c << 1, 1;
  VectorXd d(1);
  d << 1;
  HessianFactor f;
  ASSERT_TRUE(f.compute(h));
  DenseQpSolver solver(4, 2, 4);
  VectorXd x(2);
  ASSERT_EQ(solver.solve(f, g, MatrixXd(0, 2), VectorXd(0), c, d, x), QpStatus::kOptimal);
  EXPECT_NEAR(x(0), 0.5, 1e-14);
  EXPECT_NEAR(x(1), 0.5, 1e-14);
  EXPECT_NEAR(solver.inequalityMultipliers()(0), 0.5, 1e-14);
  EXPECT_NEAR(solver.objective(f), 0.5 * 0.5 - 1.0, 1e-14);
  HessianFactor other;  // the objective is evaluated with the last solve's factor only
  ASSERT_TRUE(other.compute(Eigen::Matrix3d::Identity()));
  EXPECT_THROW(solver.objective(other), std::invalid_argument);
  ASSERT_EQ(solver.activeInequalityCount(), 1);
  EXPECT_EQ(solver.activeInequalities()[0], 0);
  // No constraints at all.
  ASSERT_EQ(solver.solve(f, g, MatrixXd(0, 2), VectorXd(0), MatrixXd(0, 2), VectorXd(0), x),
            QpStatus::kOptimal);
  EXPECT_NEAR(x(0), 1.0, 1e-14);
  EXPECT_EQ(solver.iterations(), 0);
  EXPECT_STREQ(wpg::qp::qpStatusName(QpStatus::kInfeasible), "infeasible");
}

double g_worst_kkt = 0.0;

TEST(DenseQpSolver, RandomFeasibleProblemsSatisfyKkt) {
  DenseQpSolver solver(60, 10, 160);
  solver.settings().max_iterations = 1000;
  int solved = 0, degenerate_count = 0;
  KktError worst;
  for (int trial = 0; trial < 1200; ++trial) {
    Rng rng(1000 + trial);
    const int n = rng.integer(1, 60);
    const int me = rng.integer(0, std::min(10, n - 1));
    const int mi = rng.integer(0, 150);
    const bool degenerate = trial % 2 == 1;
    degenerate_count += degenerate;
    const Qp qp = trial % 5 == 4 ? vertexQp(rng, n, mi) : randomFeasibleQp(rng, n, me, mi, degenerate);
    VectorXd x;
    HessianFactor factor;
    const QpStatus status = solveQp(solver, qp, x, factor);
    ASSERT_EQ(status, QpStatus::kOptimal) << "trial " << trial << " n=" << n << " me=" << qp.E.rows()
                                          << " mi=" << qp.C.rows();
    ASSERT_EQ(solver.inequalityMultipliers().size(), qp.C.rows());
    ASSERT_EQ(solver.equalityMultipliers().size(), qp.E.rows());
    const KktError err = kktError(qp, x, solver.equalityMultipliers(), solver.inequalityMultipliers());
    EXPECT_LE(err.stationarity, 1e-9) << "trial " << trial;
    EXPECT_LE(err.primal, 1e-9) << "trial " << trial;
    EXPECT_LE(err.dual, 1e-12) << "trial " << trial;
    EXPECT_LE(err.complementarity, 1e-9) << "trial " << trial;
    // objective and active set consistent with x and lambda
    const double f = 0.5 * x.dot(qp.H * x) + qp.g.dot(x);
    EXPECT_NEAR(solver.objective(factor), f, 1e-9 * (1.0 + std::abs(f)));
    for (int k = 0; k < solver.activeInequalityCount(); ++k) {
      const int i = solver.activeInequalities()[k];
      EXPECT_LE(std::abs(qp.C.row(i).dot(x) - qp.d(i)), 1e-9);
    }
    for (int i = 0; i < qp.C.rows(); ++i) {
      const bool active = std::find(solver.activeInequalities(),
                                    solver.activeInequalities() + solver.activeInequalityCount(),
                                    i) != solver.activeInequalities() + solver.activeInequalityCount();
      if (!active) {
        EXPECT_EQ(solver.inequalityMultipliers()(i), 0.0);
      }
    }
    worst.stationarity = std::max(worst.stationarity, err.stationarity);
    worst.primal = std::max(worst.primal, err.primal);
    worst.primal_absolute = std::max(worst.primal_absolute, err.primal_absolute);
    worst.dual = std::max(worst.dual, err.dual);
    worst.complementarity = std::max(worst.complementarity, err.complementarity);
    ++solved;
  }
  g_worst_kkt = worst.worst();
  std::printf("[ kkt      ] %d problems (%d degenerate), worst stationarity %.2e, primal %.2e "
              "(absolute %.2e), dual %.2e, complementarity %.2e\n",
              solved, degenerate_count, worst.stationarity, worst.primal, worst.primal_absolute,
              worst.dual, worst.complementarity);
}

TEST(DenseQpSolver, RandomInfeasibleProblemsAreDetected) {
  DenseQpSolver solver(60, 12, 160);
  solver.settings().max_iterations = 1000;
  for (int trial = 0; trial < 500; ++trial) {
    Rng rng(50000 + trial);
    const int n = rng.integer(1, 60);
    const int me = rng.integer(0, std::min(8, n - 1));
    const int mi = rng.integer(0, 150);
    const Qp qp = randomInfeasibleQp(rng, n, me, mi, trial);
    VectorXd x;
    const QpStatus status = solveQp(solver, qp, x);
    EXPECT_EQ(status, QpStatus::kInfeasible) << "trial " << trial << " kind " << trial % 5;
    EXPECT_TRUE(x.allFinite());
  }
}

// Brute force: the optimum is the solution of the equality-constrained QP on some linearly
// independent subset of the constraints (plus the equalities) that is feasible; the smallest
// objective over all feasible subsets is the optimal value.
struct BruteForce {
  bool feasible = false;
  double value = std::numeric_limits<double>::infinity();
  VectorXd x;
};

BruteForce bruteForce(const Qp& qp) {
  BruteForce best;
  const int n = static_cast<int>(qp.g.size());
  const int me = static_cast<int>(qp.E.rows());
  const int mi = static_cast<int>(qp.C.rows());
  for (int mask = 0; mask < (1 << mi); ++mask) {
    std::vector<int> rows;
    for (int i = 0; i < mi; ++i)
      if (mask & (1 << i)) rows.push_back(i);
    const int m = me + static_cast<int>(rows.size());
    if (m > n) continue;
    MatrixXd kkt = MatrixXd::Zero(n + m, n + m);
    VectorXd rhs(n + m);
    kkt.topLeftCorner(n, n) = qp.H;
    rhs.head(n) = -qp.g;
    for (int k = 0; k < m; ++k) {
      const VectorXd a = k < me ? VectorXd(qp.E.row(k).transpose()) : VectorXd(qp.C.row(rows[k - me]).transpose());
      kkt.block(0, n + k, n, 1) = a;
      kkt.block(n + k, 0, 1, n) = a.transpose();
      rhs(n + k) = k < me ? qp.e(k) : qp.d(rows[k - me]);
    }
    const Eigen::FullPivLU<MatrixXd> lu(kkt);
    if (lu.rank() < n + m) continue;
    const VectorXd sol = lu.solve(rhs);
    const VectorXd x = sol.head(n);
    double violation = 0.0, unused = 0.0;
    rowViolation(qp.E, qp.e, x, true, violation, unused);
    rowViolation(qp.C, qp.d, x, false, violation, unused);
    if (violation > 1e-9) continue;
    const double f = 0.5 * x.dot(qp.H * x) + qp.g.dot(x);
    best.feasible = true;
    if (f < best.value) {
      best.value = f;
      best.x = x;
    }
  }
  return best;
}

TEST(DenseQpSolver, MatchesBruteForceOnTinyProblems) {
  DenseQpSolver solver(3, 1, 6);
  int feasible = 0, infeasible = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Rng rng(90000 + trial);
    const int n = rng.integer(1, 3);
    const int me = rng.integer(0, std::min(1, n - 1));
    const int mi = rng.integer(0, 6);
    Qp qp;
    qp.H = randomSpd(rng, n);
    qp.g = rng.normalVector(n) * 3.0;
    qp.E = rng.normalMatrix(me, n);
    qp.e = rng.normalVector(me);
    qp.C = rng.normalMatrix(mi, n);
    qp.d = rng.normalVector(mi);  // not built feasible: some are infeasible
    if (mi >= 2 && rng.chance(0.2)) {  // parallel / duplicated rows
      qp.C.row(1) = qp.C.row(0) * (rng.chance(0.5) ? 1.0 : -2.0);
    }
    const BruteForce reference = bruteForce(qp);
    VectorXd x;
    HessianFactor factor;
    const QpStatus status = solveQp(solver, qp, x, factor);
    if (!reference.feasible) {
      ++infeasible;
      EXPECT_EQ(status, QpStatus::kInfeasible) << "trial " << trial;
      continue;
    }
    ++feasible;
    ASSERT_EQ(status, QpStatus::kOptimal) << "trial " << trial;
    EXPECT_NEAR(solver.objective(factor), reference.value, 1e-9 * (1.0 + std::abs(reference.value)))
        << "trial " << trial;
    EXPECT_LE((x - reference.x).cwiseAbs().maxCoeff(), 1e-7 * (1.0 + reference.x.cwiseAbs().maxCoeff()))
        << "trial " << trial;
  }
  std::printf("[ brute    ] %d feasible, %d infeasible tiny problems\n", feasible, infeasible);
  EXPECT_GT(feasible, 1000);
  EXPECT_GT(infeasible, 100);
}

TEST(DenseQpSolver, IterationLimit) {
  Rng rng(5);
  const Qp qp = vertexQp(rng, 30, 60);
  DenseQpSolver solver(30, 0, 60);
  solver.settings().max_iterations = 2;
  VectorXd x;
  EXPECT_EQ(solveQp(solver, qp, x), QpStatus::kIterationLimit);
  EXPECT_TRUE(x.allFinite());
  EXPECT_EQ(solver.iterations(), 2);
  // The returned iterate is dual feasible: stationarity holds with the reported multipliers.
  const KktError err = kktError(qp, x, solver.equalityMultipliers(), solver.inequalityMultipliers());
  EXPECT_LE(err.stationarity, 1e-9);
}

TEST(DenseQpSolver, InvalidInput) {
  const int n = 4;
  HessianFactor factor;
  ASSERT_TRUE(factor.compute(MatrixXd::Identity(n, n)));
  DenseQpSolver solver(n, 1, 3);
  VectorXd g = VectorXd::Ones(n), x(n);
  const MatrixXd E = MatrixXd::Ones(1, n);
  const VectorXd e = VectorXd::Zero(1);
  const MatrixXd C = MatrixXd::Identity(3, n);
  const VectorXd d = VectorXd::Ones(3);
  ASSERT_EQ(solver.solve(factor, g, E, e, C, d, x), QpStatus::kOptimal);
  // capacities exceeded
  EXPECT_EQ(solver.solve(factor, g, E, e, MatrixXd::Identity(4, n), VectorXd::Ones(4), x),
            QpStatus::kInvalidInput);
  EXPECT_EQ(solver.solve(factor, g, MatrixXd::Ones(2, n), VectorXd::Zero(2), C, d, x),
            QpStatus::kInvalidInput);
  HessianFactor big;
  ASSERT_TRUE(big.compute(MatrixXd::Identity(n + 1, n + 1)));
  VectorXd x_big(n + 1);
  EXPECT_EQ(solver.solve(big, VectorXd::Ones(n + 1), MatrixXd(0, n + 1), VectorXd(0),
                         MatrixXd(0, n + 1), VectorXd(0), x_big),
            QpStatus::kInvalidInput);
  // inconsistent sizes
  EXPECT_EQ(solver.solve(factor, g, E, e, C, VectorXd::Ones(2), x), QpStatus::kInvalidInput);
  HessianFactor small;
  ASSERT_TRUE(small.compute(MatrixXd::Identity(n - 1, n - 1)));
  EXPECT_EQ(solver.solve(small, g, E, e, C, d, x), QpStatus::kInvalidInput);
  // non-finite data
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  VectorXd g_bad = g;
  g_bad(2) = nan;
  EXPECT_EQ(solver.solve(factor, g_bad, E, e, C, d, x), QpStatus::kInvalidInput);
  EXPECT_TRUE(x.allFinite());
  MatrixXd C_bad = C;
  C_bad(1, 3) = inf;
  EXPECT_EQ(solver.solve(factor, g, E, e, C_bad, d, x), QpStatus::kInvalidInput);
  C_bad(1, 3) = nan;
  EXPECT_EQ(solver.solve(factor, g, E, e, C_bad, d, x), QpStatus::kInvalidInput);
  // ... also when the row is loaded from the warm-start guess before any product C x
  const int guess[] = {1};
  solver.setActiveSetGuess(guess, 1);
  EXPECT_EQ(solver.solve(factor, g, E, e, C_bad, d, x), QpStatus::kInvalidInput);
  EXPECT_TRUE(x.allFinite());
  // a violated row whose squared norm overflows (its scale cannot be computed)
  C_bad = C;
  C_bad.row(0) *= 1e200;
  VectorXd d_far = d;
  d_far(0) = -1e200;  // 1e200 x_0 <= -1e200: violated at the unconstrained minimum
  EXPECT_EQ(solver.solve(factor, g, E, e, C_bad, d_far, x), QpStatus::kInvalidInput);
  EXPECT_TRUE(x.allFinite());
  VectorXd d_bad = d;
  d_bad(0) = -inf;
  EXPECT_EQ(solver.solve(factor, g, E, e, C, d_bad, x), QpStatus::kInvalidInput);
  MatrixXd E_bad = E;
  E_bad(0, 0) = nan;
  EXPECT_EQ(solver.solve(factor, g, E_bad, e, C, d, x), QpStatus::kInvalidInput);
  VectorXd e_bad = e;
  e_bad(0) = inf;
  EXPECT_EQ(solver.solve(factor, g, E, e_bad, C, d, x), QpStatus::kInvalidInput);
  EXPECT_TRUE(x.allFinite());
  // still usable afterwards
  EXPECT_EQ(solver.solve(factor, g, E, e, C, d, x), QpStatus::kOptimal);
}

TEST(DenseQpSolver, SolveDoesNotAllocate) {
  // Problem smaller than the capacities, with equalities, warm start and cold start; then an
  // infeasible problem and one stopped by the iteration limit (every way out of solve()).
  Rng rng(99);
  const int n = 38, me = 4, mi = 80;
  const Qp qp = randomFeasibleQp(rng, n, me, mi, true);
  HessianFactor factor;
  ASSERT_TRUE(factor.compute(qp.H));
  DenseQpSolver solver(45, 6, 100);
  VectorXd x(n);
  ASSERT_EQ(solver.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x), QpStatus::kOptimal);  // warm-up
  ASSERT_GT(solver.activeInequalityCount(), 0);
  std::vector<int> guess(solver.activeInequalities(),
                         solver.activeInequalities() + solver.activeInequalityCount());
  guess.push_back(3);
  guess.push_back(11);
  const VectorXd g2 = qp.g + 0.1 * rng.normalVector(n);
  const Qp infeasible = randomInfeasibleQp(rng, 20, 2, 40, 1);
  const Qp vertex = vertexQp(rng, 30, 60);
  HessianFactor infeasible_factor, vertex_factor;
  ASSERT_TRUE(infeasible_factor.compute(infeasible.H));
  ASSERT_TRUE(vertex_factor.compute(vertex.H));
  VectorXd x_infeasible(20), x_vertex(30);
  int iterations_cold = 0, iterations_warm = 0;
#ifdef EIGEN_RUNTIME_NO_MALLOC
  Eigen::internal::set_is_malloc_allowed(false);
#endif
#ifdef WPG_TEST_COUNT_MALLOC
  g_malloc_count = 0;
  g_count_mallocs = true;
#endif
  const QpStatus cold = solver.solve(factor, g2, qp.E, qp.e, qp.C, qp.d, x);
  iterations_cold = solver.iterations();
  solver.setActiveSetGuess(guess.data(), static_cast<int>(guess.size()));
  const QpStatus warm = solver.solve(factor, g2, qp.E, qp.e, qp.C, qp.d, x);
  iterations_warm = solver.iterations();
  const QpStatus no_solution =
      solver.solve(infeasible_factor, infeasible.g, infeasible.E, infeasible.e, infeasible.C,
                   infeasible.d, x_infeasible);
  solver.settings().max_iterations = 2;
  const QpStatus capped = solver.solve(vertex_factor, vertex.g, vertex.E, vertex.e, vertex.C,
                                       vertex.d, x_vertex);
  solver.settings().max_iterations = QpSettings().max_iterations;
#ifdef WPG_TEST_COUNT_MALLOC
  g_count_mallocs = false;
  EXPECT_EQ(g_malloc_count, 0);
#endif
#ifdef EIGEN_RUNTIME_NO_MALLOC
  Eigen::internal::set_is_malloc_allowed(true);
#endif
  EXPECT_EQ(cold, QpStatus::kOptimal);
  EXPECT_EQ(warm, QpStatus::kOptimal);
  EXPECT_EQ(no_solution, QpStatus::kInfeasible);
  EXPECT_EQ(capped, QpStatus::kIterationLimit);
  EXPECT_GT(iterations_cold, 0);
  EXPECT_LE(iterations_warm, iterations_cold);
#ifdef WPG_TEST_COUNT_MALLOC
  // The counter works (so that a zero above means something).
  g_malloc_count = 0;
  g_count_mallocs = true;
  static VectorXd* volatile probe = nullptr;
  probe = new VectorXd(100);
  g_count_mallocs = false;
  EXPECT_GT(g_malloc_count, 0);
  delete probe;
#endif
}

}  // namespace
