// Tests of the dense QP solver's warm start (DenseQpSolver::setActiveSetGuess): fewer
// iterations and the same solution on a drifting sequence, no iteration for a perfect guess,
// dependent and bad guesses, infeasible problems with a guess.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "qp_test_problems.hpp"
#include "wpg/qp/dense_qp_solver.hpp"

namespace {

using namespace qp_test;

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

}  // namespace
