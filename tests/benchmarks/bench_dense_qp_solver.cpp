// Dense QP solver on a problem of the NMPC's size: n = 38 variables, 80 inequalities of which
// 10 are active at the solution. Cold start, warm start with the exact active set, and an
// MPC-like sequence (gradient drifting between solves, warm start from the previous solve).
// Run with --benchmark_repetitions=N --benchmark_report_aggregates_only=true for medians.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <random>
#include <vector>

#include "wpg/qp/dense_qp_solver.hpp"

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;
using wpg::qp::DenseQpSolver;
using wpg::qp::HessianFactor;
using wpg::qp::QpStatus;

struct QpFixture : benchmark::Fixture {
  static constexpr int kVariables = 38;
  static constexpr int kInequalities = 80;
  static constexpr int kActive = 10;
  static constexpr int kSequence = 64;

  MatrixXd H, E, C;
  VectorXd g, e, d, x;
  std::vector<VectorXd> g_sequence;  // slowly drifting gradients (there and back)
  HessianFactor factor;

  void SetUp(const benchmark::State&) override {
    std::mt19937 engine(2017);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    auto random_matrix = [&](int rows, int cols) {
      MatrixXd m(rows, cols);
      for (int j = 0; j < cols; ++j)
        for (int i = 0; i < rows; ++i) m(i, j) = normal(engine);
      return m;
    };
    const int n = kVariables, mi = kInequalities;
    const MatrixXd a = random_matrix(n, n);
    H = a * a.transpose() / n + MatrixXd::Identity(n, n);
    C = random_matrix(mi, n);
    E.resize(0, n);
    e.resize(0);
    // Solution x_star with rows 0..kActive-1 active (positive multipliers), the rest slack.
    const VectorXd x_star = random_matrix(n, 1);
    d = C * x_star;
    VectorXd lambda = VectorXd::Zero(mi);
    for (int i = 0; i < mi; ++i) {
      if (i < kActive) lambda(i) = 0.5 + uniform(engine);
      else d(i) += 0.1 + uniform(engine);
    }
    g = -H * x_star - C.transpose() * lambda;
    const VectorXd drift = 0.002 * random_matrix(n, 1);
    for (int k = 0; k < kSequence; ++k) {
      const int phase = k < kSequence / 2 ? k : kSequence - k;
      g_sequence.push_back(g + phase * drift);
    }
    x.setZero(n);
    factor.compute(H);
  }
};

BENCHMARK_F(QpFixture, ColdStart)(benchmark::State& state) {
  DenseQpSolver solver(kVariables, 0, kInequalities);
  int iterations = 0;
  for (auto _ : state) {
    const QpStatus status = solver.solve(factor, g, E, e, C, d, x);
    benchmark::DoNotOptimize(status);
    benchmark::DoNotOptimize(x.data());
    iterations = solver.iterations();
  }
  state.counters["iterations"] = iterations;
  state.counters["active"] = solver.activeInequalityCount();
}

BENCHMARK_F(QpFixture, WarmStartExactGuess)(benchmark::State& state) {
  DenseQpSolver solver(kVariables, 0, kInequalities);
  solver.solve(factor, g, E, e, C, d, x);
  const std::vector<int> guess(solver.activeInequalities(),
                               solver.activeInequalities() + solver.activeInequalityCount());
  int iterations = 0;
  for (auto _ : state) {
    solver.setActiveSetGuess(guess.data(), static_cast<int>(guess.size()));
    const QpStatus status = solver.solve(factor, g, E, e, C, d, x);
    benchmark::DoNotOptimize(status);
    benchmark::DoNotOptimize(x.data());
    iterations = solver.iterations();
  }
  state.counters["iterations"] = iterations;
}

// One solve per benchmark iteration, cycling through the drifting sequence.
BENCHMARK_F(QpFixture, ColdStartDriftingSequence)(benchmark::State& state) {
  DenseQpSolver solver(kVariables, 0, kInequalities);
  int k = 0;
  long iterations = 0, solves = 0;
  for (auto _ : state) {
    const QpStatus status = solver.solve(factor, g_sequence[k], E, e, C, d, x);
    benchmark::DoNotOptimize(status);
    k = (k + 1) % kSequence;
    iterations += solver.iterations();
    ++solves;
  }
  state.counters["iterations"] = static_cast<double>(iterations) / static_cast<double>(solves);
}

BENCHMARK_F(QpFixture, WarmStartDriftingSequence)(benchmark::State& state) {
  DenseQpSolver solver(kVariables, 0, kInequalities);
  std::vector<int> guess(kInequalities);
  int guess_count = 0, k = 0;
  long iterations = 0, solves = 0;
  for (auto _ : state) {
    solver.setActiveSetGuess(guess.data(), guess_count);
    const QpStatus status = solver.solve(factor, g_sequence[k], E, e, C, d, x);
    benchmark::DoNotOptimize(status);
    guess_count = solver.activeInequalityCount();
    std::copy(solver.activeInequalities(), solver.activeInequalities() + guess_count, guess.begin());
    k = (k + 1) % kSequence;
    iterations += solver.iterations();
    ++solves;
  }
  state.counters["iterations"] = static_cast<double>(iterations) / static_cast<double>(solves);
}

BENCHMARK_F(QpFixture, HessianFactorCompute)(benchmark::State& state) {
  HessianFactor f;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f.compute(H));
  }
}

}  // namespace

