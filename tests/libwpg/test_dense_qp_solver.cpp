// Tests of the Goldfarb-Idnani dense QP solver: KKT conditions on random (also degenerate)
// problems, infeasibility detection, brute force on tiny problems, warm start, allocation.
//
// Why ~750 lines: one file per solver; random feasible, degenerate and infeasible families,
// brute-force comparisons and warm-start cases share the generators and KKT checks above.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

#include "wpg/qp/dense_qp_solver.hpp"

// ---- heap allocation counter (glibc: every malloc of the process, whatever the TU) ----------
// Eigen allocates with std::malloc (operator new does too), so replacing malloc sees every
// heap allocation, also in the library's translation units and in Release builds, where
// Eigen's own EIGEN_RUNTIME_NO_MALLOC check (an eigen_assert) is compiled out. Sanitizers
// replace malloc themselves: there (scripts/test-sanitizers.sh) the count comes from their
// allocation hook, which their allocator calls for every allocation.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define WPG_TEST_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define WPG_TEST_SANITIZED 1
#endif
#if defined(__GLIBC__) && !defined(WPG_TEST_SANITIZED)
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
#elif defined(WPG_TEST_SANITIZED)
#define WPG_TEST_COUNT_MALLOC 1
// Declared in <sanitizer/allocator_interface.h> (compiler-rt and GCC's libsanitizer alike).
extern "C" int __sanitizer_install_malloc_and_free_hooks(
    void (*malloc_hook)(const volatile void*, std::size_t),
    void (*free_hook)(const volatile void*));
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

using Eigen::MatrixXd;
using Eigen::VectorXd;
using wpg::qp::DenseQpSolver;
using wpg::qp::HessianFactor;
using wpg::qp::QpSettings;
using wpg::qp::QpStatus;

struct Qp {
  MatrixXd H;
  VectorXd g;
  MatrixXd E;
  VectorXd e;
  MatrixXd C;
  VectorXd d;
};

struct Rng {
  explicit Rng(unsigned seed) : engine(seed) {}
  double normal() { return normal_dist(engine); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  VectorXd normalVector(int n) {
    VectorXd v(n);
    for (int i = 0; i < n; ++i) v(i) = normal();
    return v;
  }
  MatrixXd normalMatrix(int rows, int cols) {
    MatrixXd m(rows, cols);
    for (int j = 0; j < cols; ++j)
      for (int i = 0; i < rows; ++i) m(i, j) = normal();
    return m;
  }
  std::mt19937 engine;
  std::normal_distribution<double> normal_dist{0.0, 1.0};
};

MatrixXd randomSpd(Rng& rng, int n) {
  const MatrixXd a = rng.normalMatrix(n, n);
  MatrixXd h = a * a.transpose() / std::max(1, n) + rng.uniform(0.01, 1.0) * MatrixXd::Identity(n, n);
  return 0.5 * (h + h.transpose());
}

void appendRow(MatrixXd& m, VectorXd& rhs, const VectorXd& row, double value) {
  const Eigen::Index k = m.rows();
  m.conservativeResize(k + 1, row.size());
  rhs.conservativeResize(k + 1);
  m.row(k) = row.transpose();
  rhs(k) = value;
}

// Degenerate test problems have many rows tight at a known point x0 (d = C x0). Data on a
// dyadic grid (x0 in multiples of 1/16, rows in multiples of 1/64, scale factors powers of
// two) make C x0 exact in floating point, so that the problems are exactly feasible even when
// more than n rows are tight at x0 (otherwise the rounding of d alone can make such a vertex
// infeasible by ~1e-9 when the tight rows are ill-conditioned).
VectorXd onGrid(const VectorXd& v, double step) { return (v / step).array().round().matrix() * step; }
constexpr double kPointStep = 1.0 / 16.0;
constexpr double kRowStep = 1.0 / 64.0;

double powerOfTwo(Rng& rng, int lo, int hi) { return std::ldexp(1.0, rng.integer(lo, hi)); }

// Random feasible QP built around a feasible point x0, with optional degeneracies.
Qp randomFeasibleQp(Rng& rng, int n, int me, int mi, bool degenerate) {
  Qp qp;
  qp.H = randomSpd(rng, n);
  const VectorXd x0 = onGrid(rng.normalVector(n), kPointStep);
  qp.E.resize(0, n);
  qp.e.resize(0);
  for (int i = 0; i < me; ++i) {
    VectorXd row = onGrid(rng.normalVector(n), kRowStep);
    if (degenerate && i >= 2 && rng.chance(0.3)) {
      // duplicated or linearly dependent (but consistent) equality
      row = qp.E.row(rng.integer(0, i - 1)).transpose() * powerOfTwo(rng, -1, 1);
      if (rng.chance(0.5)) row += qp.E.row(rng.integer(0, i - 1)).transpose();
    }
    appendRow(qp.E, qp.e, row, row.dot(x0));
  }
  qp.C.resize(0, n);
  qp.d.resize(0);
  for (int i = 0; i < mi; ++i) {
    const double kind = rng.uniform(0.0, 1.0);
    if (degenerate && i > 0 && kind < 0.10) {  // duplicated row
      const int j = rng.integer(0, i - 1);
      appendRow(qp.C, qp.d, qp.C.row(j).transpose(), qp.d(j));
    } else if (degenerate && i > 0 && kind < 0.20) {  // parallel row, same or weaker bound
      const int j = rng.integer(0, i - 1);
      const double beta = powerOfTwo(rng, -3, 3);
      const double extra = rng.chance(0.5) ? 0.0 : rng.uniform(0.0, 1.0);
      appendRow(qp.C, qp.d, beta * qp.C.row(j).transpose(), beta * qp.d(j) + extra);
    } else if (degenerate && kind < 0.24) {  // zero row, d >= 0
      appendRow(qp.C, qp.d, VectorXd::Zero(n), rng.chance(0.5) ? 0.0 : rng.uniform(0.0, 1.0));
    } else {
      // rows of different scales; many rows tight at x0 in degenerate problems (more than n:
      // a degenerate vertex)
      const VectorXd row = onGrid(rng.normalVector(n) * powerOfTwo(rng, -3, 3), kRowStep);
      const double slack = (degenerate && rng.chance(0.5)) ? 0.0 : rng.uniform(0.0, 2.0);
      appendRow(qp.C, qp.d, row, row.dot(x0) + slack);
    }
  }
  qp.g = rng.normalVector(n) * rng.uniform(1.0, 30.0);
  return qp;
}

// QP whose solution is x0 with many tight constraints, a random subset with positive
// multipliers (degenerate vertex: tight constraints with zero multipliers).
Qp vertexQp(Rng& rng, int n, int mi) {
  Qp qp;
  qp.H = randomSpd(rng, n);
  const VectorXd x0 = onGrid(rng.normalVector(n), kPointStep);
  qp.E.resize(0, n);
  qp.e.resize(0);
  qp.C = rng.normalMatrix(mi, n);
  for (int i = 0; i < mi; ++i) qp.C.row(i) = onGrid(qp.C.row(i).transpose(), kRowStep).transpose();
  qp.d = qp.C * x0;
  VectorXd lambda = VectorXd::Zero(mi);
  for (int i = 0; i < mi; ++i) {
    if (rng.chance(0.4)) qp.d(i) += rng.uniform(0.0, 1.0);        // not tight
    else if (rng.chance(0.3) && i < n) lambda(i) = rng.uniform(0.1, 2.0);  // tight, active
  }
  qp.g = -qp.H * x0 - qp.C.transpose() * lambda;
  return qp;
}

// A random QP made infeasible by construction (several kinds).
Qp randomInfeasibleQp(Rng& rng, int n, int me, int mi, int kind) {
  Qp qp = randomFeasibleQp(rng, n, me, mi, rng.chance(0.5));
  const VectorXd a = rng.normalVector(n);
  const double b = rng.normal();
  switch (kind % 5) {
    case 0:  // a x <= b and -a x <= -b - 1
      appendRow(qp.C, qp.d, a, b);
      appendRow(qp.C, qp.d, -a, -b - rng.uniform(0.01, 1.0));
      break;
    case 1: {  // Farkas combination of three rows with a deficit
      const VectorXd a2 = rng.normalVector(n), a3 = rng.normalVector(n);
      const double b2 = rng.normal(), b3 = rng.normal();
      appendRow(qp.C, qp.d, a, b);
      appendRow(qp.C, qp.d, a2, b2);
      appendRow(qp.C, qp.d, a3, b3);
      appendRow(qp.C, qp.d, -(a + a2 + a3), -(b + b2 + b3) - rng.uniform(0.01, 1.0));
      break;
    }
    case 2:  // zero row with d < 0
      appendRow(qp.C, qp.d, VectorXd::Zero(n), -rng.uniform(0.01, 1.0));
      break;
    case 3:  // equality against inequality
      appendRow(qp.E, qp.e, a, b);
      appendRow(qp.C, qp.d, a * 2.0, 2.0 * b - rng.uniform(0.01, 1.0));
      break;
    default:  // inconsistent duplicated equality
      appendRow(qp.E, qp.e, a, b);
      appendRow(qp.E, qp.e, -3.0 * a, -3.0 * b + rng.uniform(0.01, 1.0));
      break;
  }
  // Shuffle inequality rows so that the conflicting ones are not always last.
  std::vector<int> perm(qp.C.rows());
  for (size_t i = 0; i < perm.size(); ++i) perm[i] = static_cast<int>(i);
  std::shuffle(perm.begin(), perm.end(), rng.engine);
  MatrixXd c = qp.C;
  VectorXd dd = qp.d;
  for (size_t i = 0; i < perm.size(); ++i) {
    qp.C.row(i) = c.row(perm[i]);
    qp.d(i) = dd(perm[i]);
  }
  return qp;
}

struct KktError {
  double stationarity = 0.0;     // relative to the size of the terms
  double primal = 0.0;           // relative to the rounding scale 1 + |A_i| |x| of each row
  double primal_absolute = 0.0;  // largest violation |E x - e|, (C x - d)_+
  double dual = 0.0;             // most negative lambda (as a positive number)
  double complementarity = 0.0;
  double worst() const { return std::max({stationarity, primal, complementarity}); }
};

// Violation of rows A x = b (equality) or A x <= b, each relative to 1 + |A_i| |x|: the size
// of the rounding error made when evaluating A_i x (degenerate, ill-conditioned vertices put
// errors of 1e-11 of that size on x, which absolute checks on rows of norm 50 would count).
void rowViolation(const MatrixXd& A, const VectorXd& b, const VectorXd& x, bool equality,
                  double& relative, double& absolute) {
  if (A.rows() == 0) return;
  const VectorXd residual = A * x - b;
  const VectorXd scale = VectorXd::Ones(A.rows()) + A.cwiseAbs() * x.cwiseAbs();
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    const double violation = equality ? std::abs(residual(i)) : std::max(0.0, residual(i));
    absolute = std::max(absolute, violation);
    relative = std::max(relative, violation / scale(i));
  }
}

KktError kktError(const Qp& qp, const VectorXd& x, const VectorXd& mu, const VectorXd& lambda) {
  KktError err;
  const VectorXd hx = qp.H * x;
  const VectorXd emu = qp.E.transpose() * mu;
  const VectorXd clambda = qp.C.transpose() * lambda;
  const VectorXd residual = hx + qp.g + emu + clambda;
  double scale = 1.0;
  if (x.size() > 0) {
    scale = std::max({1.0, hx.cwiseAbs().maxCoeff(), qp.g.cwiseAbs().maxCoeff(),
                      emu.cwiseAbs().maxCoeff(), clambda.cwiseAbs().maxCoeff()});
    err.stationarity = residual.cwiseAbs().maxCoeff() / scale;
  }
  rowViolation(qp.E, qp.e, x, true, err.primal, err.primal_absolute);
  rowViolation(qp.C, qp.d, x, false, err.primal, err.primal_absolute);
  if (qp.C.rows() > 0) {
    const VectorXd slack = qp.C * x - qp.d;
    err.dual = std::max(0.0, -lambda.minCoeff());
    const double lambda_scale = std::max(1.0, lambda.cwiseAbs().maxCoeff());
    err.complementarity = lambda.cwiseProduct(slack).cwiseAbs().maxCoeff() / lambda_scale;
  }
  return err;
}

QpStatus solveQp(DenseQpSolver& solver, const Qp& qp, VectorXd& x) {
  HessianFactor factor;
  EXPECT_TRUE(factor.compute(qp.H));
  x.setZero(qp.g.size());
  return solver.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x);
}

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
  EXPECT_NEAR(solver.objective(), 0.5 * 0.5 - 1.0, 1e-14);
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
    const QpStatus status = solveQp(solver, qp, x);
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
    EXPECT_NEAR(solver.objective(), f, 1e-9 * (1.0 + std::abs(f)));
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
    const QpStatus status = solveQp(solver, qp, x);
    if (!reference.feasible) {
      ++infeasible;
      EXPECT_EQ(status, QpStatus::kInfeasible) << "trial " << trial;
      continue;
    }
    ++feasible;
    ASSERT_EQ(status, QpStatus::kOptimal) << "trial " << trial;
    EXPECT_NEAR(solver.objective(), reference.value, 1e-9 * (1.0 + std::abs(reference.value)))
        << "trial " << trial;
    EXPECT_LE((x - reference.x).cwiseAbs().maxCoeff(), 1e-7 * (1.0 + reference.x.cwiseAbs().maxCoeff()))
        << "trial " << trial;
  }
  std::printf("[ brute    ] %d feasible, %d infeasible tiny problems\n", feasible, infeasible);
  EXPECT_GT(feasible, 1000);
  EXPECT_GT(infeasible, 100);
}

// MPC-like sequence: g drifts slowly; warm start with the previous active set.
TEST(DenseQpSolver, WarmStartSavesIterationsAndGivesSameSolution) {
  Rng rng(4242);
  const int n = 38, me = 4, mi = 80;
  Qp qp = randomFeasibleQp(rng, n, me, mi, false);
  const VectorXd drift = rng.normalVector(n);
  HessianFactor factor;
  ASSERT_TRUE(factor.compute(qp.H));
  DenseQpSolver cold(n, me, mi), warm(n, me, mi);
  VectorXd x_cold(n), x_warm(n);
  int cold_iterations = 0, warm_iterations = 0, warm_dual_iterations = 0, kept = 0;
  std::vector<int> previous;
  for (int step = 0; step < 200; ++step) {
    qp.g += 0.02 * drift;
    ASSERT_EQ(cold.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x_cold), QpStatus::kOptimal);
    if (!previous.empty()) warm.setActiveSetGuess(previous.data(), static_cast<int>(previous.size()));
    ASSERT_EQ(warm.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x_warm), QpStatus::kOptimal);
    EXPECT_LE((x_cold - x_warm).cwiseAbs().maxCoeff(), 1e-9) << "step " << step;
    EXPECT_LE((cold.inequalityMultipliers() - warm.inequalityMultipliers()).cwiseAbs().maxCoeff(), 1e-8);
    cold_iterations += cold.iterations();
    warm_iterations += warm.iterations();
    warm_dual_iterations += warm.iterations() - warm.warmStartUpdates();
    EXPECT_GE(warm.warmStartUpdates(), warm.warmStartKept());
    kept += warm.warmStartKept();
    previous.assign(warm.activeInequalities(), warm.activeInequalities() + warm.activeInequalityCount());
  }
  std::printf("[ warm     ] 200 solves: %d cold iterations, %d warm (%d of them dual "
              "iterations, the rest loading the guess), %d guesses kept\n",
              cold_iterations, warm_iterations, warm_dual_iterations, kept);
  // The guess saves dual iterations (each a scan of C x); loading it is counted as work too.
  EXPECT_LT(warm_dual_iterations * 3, cold_iterations);
  EXPECT_GE(warm_iterations - warm_dual_iterations, kept);
}

TEST(DenseQpSolver, PerfectGuessNeedsNoIteration) {
  Rng rng(77);
  const int n = 38, mi = 80;
  const Qp qp = vertexQp(rng, n, mi);
  HessianFactor factor;
  ASSERT_TRUE(factor.compute(qp.H));
  DenseQpSolver solver(n, 2, mi);
  VectorXd x(n), x_again(n);
  ASSERT_EQ(solver.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x), QpStatus::kOptimal);
  EXPECT_GT(solver.iterations(), 0);
  std::vector<int> active(solver.activeInequalities(),
                          solver.activeInequalities() + solver.activeInequalityCount());
  ASSERT_FALSE(active.empty());
  // Add junk: duplicates and out-of-range indices are ignored.
  std::vector<int> guess = active;
  guess.push_back(active[0]);
  guess.push_back(-3);
  guess.push_back(mi + 5);
  solver.setActiveSetGuess(guess.data(), static_cast<int>(guess.size()));
  ASSERT_EQ(solver.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x_again), QpStatus::kOptimal);
  // no dual iteration: the only work is loading the guessed rows
  EXPECT_EQ(solver.iterations(), static_cast<int>(active.size()));
  EXPECT_EQ(solver.warmStartUpdates(), static_cast<int>(active.size()));
  EXPECT_EQ(solver.warmStartKept(), static_cast<int>(active.size()));
  EXPECT_LE((x - x_again).cwiseAbs().maxCoeff(), 1e-10);
  // The guess is consumed by one solve.
  ASSERT_EQ(solver.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x_again), QpStatus::kOptimal);
  EXPECT_EQ(solver.warmStartKept(), 0);
  EXPECT_GT(solver.iterations(), 0);
}

TEST(DenseQpSolver, DependentRowsInGuessAndEqualities) {
  // min 1/2|x|^2 - 4 x0 - x1 - x2 s.t. x0 <= 1 (rows 0, 1 duplicated, row 2 = 2 * row 0),
  // x1 + x2 = 1 twice (dependent but consistent), 0'x <= 0.
  HessianFactor f;
  ASSERT_TRUE(f.compute(MatrixXd::Identity(3, 3)));
  VectorXd g(3);
  g << -4, -1, -1;
  MatrixXd E(2, 3);
  E << 0, 1, 1, 0, 2, 2;
  VectorXd e(2);
  e << 1, 2;
  MatrixXd C(4, 3);
  C << 1, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 0;
  VectorXd d(4);
  d << 1, 1, 2, 0;
  DenseQpSolver solver(3, 2, 4);
  const int guess[] = {0, 1, 2, 3};
  solver.setActiveSetGuess(guess, 4);
  VectorXd x(3);
  ASSERT_EQ(solver.solve(f, g, E, e, C, d, x), QpStatus::kOptimal);
  EXPECT_EQ(solver.warmStartKept(), 1);  // rows 1, 2, 3 depend on row 0
  EXPECT_EQ(solver.iterations(), 1);     // loading row 0, no dual iteration
  EXPECT_EQ(solver.warmStartUpdates(), 1);
  EXPECT_NEAR(x(0), 1.0, 1e-14);
  EXPECT_NEAR(x(1), 0.5, 1e-14);
  EXPECT_NEAR(x(2), 0.5, 1e-14);
  const VectorXd& lambda = solver.inequalityMultipliers();
  EXPECT_NEAR(lambda(0) + lambda(1) + 2.0 * lambda(2), 3.0, 1e-14);
  const VectorXd& mu = solver.equalityMultipliers();
  EXPECT_NEAR(mu(0) + 2.0 * mu(1), 0.5, 1e-14);
  // Cold: same solution.
  VectorXd x_cold(3);
  ASSERT_EQ(solver.solve(f, g, E, e, C, d, x_cold), QpStatus::kOptimal);
  EXPECT_LE((x - x_cold).cwiseAbs().maxCoeff(), 1e-14);
  // Inconsistent dependent equalities: infeasible.
  e << 1, 2.5;
  EXPECT_EQ(solver.solve(f, g, E, e, C, d, x), QpStatus::kInfeasible);
  EXPECT_TRUE(x.allFinite());
}

TEST(DenseQpSolver, BadGuessesStillGiveTheOptimum) {
  DenseQpSolver solver(60, 10, 160);
  DenseQpSolver reference(60, 10, 160);
  solver.settings().max_iterations = 1000;
  reference.settings().max_iterations = 1000;
  for (int trial = 0; trial < 300; ++trial) {
    Rng rng(7000 + trial);
    const int n = rng.integer(1, 60);
    const int me = rng.integer(0, std::min(10, n - 1));
    const int mi = rng.integer(1, 150);
    const Qp qp = trial % 3 == 2 ? vertexQp(rng, n, mi) : randomFeasibleQp(rng, n, me, mi, trial % 2 == 1);
    std::vector<int> guess;
    const int count = rng.integer(0, std::min(mi, n + 10));
    for (int k = 0; k < count; ++k) guess.push_back(rng.integer(0, static_cast<int>(qp.C.rows()) - 1));
    HessianFactor factor;
    ASSERT_TRUE(factor.compute(qp.H));
    VectorXd x(n), x_ref(n);
    ASSERT_EQ(reference.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x_ref), QpStatus::kOptimal);
    solver.setActiveSetGuess(guess.data(), count);
    ASSERT_EQ(solver.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x), QpStatus::kOptimal) << trial;
    const KktError err = kktError(qp, x, solver.equalityMultipliers(), solver.inequalityMultipliers());
    EXPECT_LE(err.worst(), 1e-9) << "trial " << trial;
    EXPECT_LE(err.dual, 1e-12) << "trial " << trial;
    EXPECT_LE((x - x_ref).cwiseAbs().maxCoeff(), 1e-7 * (1.0 + x_ref.cwiseAbs().maxCoeff()))
        << "trial " << trial;
    EXPECT_LE(solver.warmStartKept(), count);
  }
}

TEST(DenseQpSolver, InfeasibleWithWarmStart) {
  for (int trial = 0; trial < 100; ++trial) {
    Rng rng(31000 + trial);
    const int n = rng.integer(2, 40);
    const Qp qp = randomInfeasibleQp(rng, n, rng.integer(0, std::min(6, n - 1)), rng.integer(0, 80), trial);
    std::vector<int> guess;
    for (int k = 0; k < 10 && qp.C.rows() > 0; ++k) guess.push_back(rng.integer(0, static_cast<int>(qp.C.rows()) - 1));
    DenseQpSolver solver(40, 8, 90);
    solver.setActiveSetGuess(guess.data(), static_cast<int>(guess.size()));
    VectorXd x;
    EXPECT_EQ(solveQp(solver, qp, x), QpStatus::kInfeasible) << "trial " << trial;
    EXPECT_TRUE(x.allFinite());
  }
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
