#pragma once
// Random QPs for the tests of the dense QP solver (feasible, degenerate, infeasible, vertex
// problems) and their KKT residuals.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "wpg/qp/dense_qp_solver.hpp"

namespace qp_test {

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

inline MatrixXd randomSpd(Rng& rng, int n) {
  const MatrixXd a = rng.normalMatrix(n, n);
  MatrixXd h = a * a.transpose() / std::max(1, n) + rng.uniform(0.01, 1.0) * MatrixXd::Identity(n, n);
  return 0.5 * (h + h.transpose());
}

inline void appendRow(MatrixXd& m, VectorXd& rhs, const VectorXd& row, double value) {
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
inline VectorXd onGrid(const VectorXd& v, double step) { return (v / step).array().round().matrix() * step; }
constexpr double kPointStep = 1.0 / 16.0;
constexpr double kRowStep = 1.0 / 64.0;

inline double powerOfTwo(Rng& rng, int lo, int hi) { return std::ldexp(1.0, rng.integer(lo, hi)); }

// Random feasible QP built around a feasible point x0, with optional degeneracies.
inline Qp randomFeasibleQp(Rng& rng, int n, int me, int mi, bool degenerate) {
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
inline Qp vertexQp(Rng& rng, int n, int mi) {
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
inline Qp randomInfeasibleQp(Rng& rng, int n, int me, int mi, int kind) {
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
inline void rowViolation(const MatrixXd& A, const VectorXd& b, const VectorXd& x, bool equality,
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

inline KktError kktError(const Qp& qp, const VectorXd& x, const VectorXd& mu, const VectorXd& lambda) {
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

// Factors qp.H into `factor` (the caller keeps it for the solver's objective()) and solves.
inline QpStatus solveQp(DenseQpSolver& solver, const Qp& qp, VectorXd& x, HessianFactor& factor) {
  EXPECT_TRUE(factor.compute(qp.H));
  x.setZero(qp.g.size());
  return solver.solve(factor, qp.g, qp.E, qp.e, qp.C, qp.d, x);
}

inline QpStatus solveQp(DenseQpSolver& solver, const Qp& qp, VectorXd& x) {
  HessianFactor factor;
  return solveQp(solver, qp, x, factor);
}

}  // namespace qp_test
