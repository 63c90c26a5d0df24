// Tests of the NMPC cost (paper eq. 5-8): the canonical form 1/2 U'QU + p'U + const with the
// constant Gauss-Newton Hessian of each walking phase, and the Hessian factors.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "wpg/nmpc.hpp"
#include "wpg/walking_parameters.hpp"
#include "nmpc_test_problems.hpp"

namespace {

using Eigen::MatrixXd;

using namespace wpg_test;

// A random problem of `pattern`: every step fixed when standing, none while walking.
NmpcProblem randomProblem(const NmpcModel& model, int pattern, Rng& rng) {
  const bool standing = pattern == model.standingPattern();
  return wpg_test::randomProblem(model, pattern,
                                 rng.chance(0.5) ? FootSide::kLeft : FootSide::kRight,
                                 standing ? FixedMode::kAll : FixedMode::kNone, rng);
}

class NmpcCost : public ::testing::TestWithParam<int> {};

TEST(NmpcCostModel, HessiansSymmetricPositiveDefinite) {
  const WalkingParameters w;
  const NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  const int n = L.variableCount();
  ASSERT_EQ(model.patternCount(), w.stepSamples() + 1);
  ASSERT_EQ(model.standingPattern(), w.stepSamples());
  for (int pattern = 0; pattern < model.patternCount(); ++pattern) {
    SCOPED_TRACE(::testing::Message() << "pattern " << pattern);
    const MatrixXd& Q = model.hessian(pattern);
    ASSERT_EQ(Q.rows(), n);
    ASSERT_EQ(Q.cols(), n);
    EXPECT_LE((Q - Q.transpose()).cwiseAbs().maxCoeff(), 1e-12 * Q.cwiseAbs().maxCoeff());
    const Eigen::SelfAdjointEigenSolver<MatrixXd> eig(Q);
    ASSERT_EQ(eig.info(), Eigen::Success);
    EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
    // Not numerically singular either (the QP solver needs a usable Cholesky factor).
    EXPECT_LT(eig.eigenvalues().maxCoeff() / eig.eigenvalues().minCoeff(), 1e12);
    EXPECT_EQ(Q.llt().info(), Eigen::Success);
    // Structure: x and y decoupled and identical, the yaw block alpha_theta I alone.
    const int N = L.horizon, nf = L.steps;
    const int xs = L.jerkX(), ys = L.jerkY(), m = N + nf;
    EXPECT_EQ((Q.block(xs, xs, m, m) - Q.block(ys, ys, m, m)).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(Q.block(xs, ys, m, m).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_LE((Q.block(L.stepYaw(), L.stepYaw(), nf, nf) -
               w.weight_yaw * MatrixXd::Identity(nf, nf)).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(Q.block(L.stepYaw(), 0, nf, L.stepYaw()).cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(NmpcCostModel, PatternsDifferOnlyInTheStepBlocks) {
  const WalkingParameters w;
  const NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  const int N = L.horizon;
  for (int pattern = 1; pattern < model.patternCount(); ++pattern) {
    const MatrixXd& Q0 = model.hessian(0);
    const MatrixXd& Q = model.hessian(pattern);
    EXPECT_LE((Q.block(0, 0, N, N) - Q0.block(0, 0, N, N)).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_GT((Q - Q0).cwiseAbs().maxCoeff(), 0.0) << "pattern " << pattern << " equals pattern 0";
  }
}

TEST_P(NmpcCost, EvaluateCostIsTheCanonicalQuadraticPlusAConstant) {
  const int pattern = GetParam();
  WalkingParameters w;
  w.weight_yaw = 1.7;  // distinct from weight_velocity, to catch a mix-up of the two
  const NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  const int n = L.variableCount();
  Rng rng(100 + pattern);
  for (int instance = 0; instance < 5; ++instance) {
    const NmpcProblem problem = randomProblem(model, pattern, rng);
    const MatrixXd& Q = model.hessian(pattern);
    VectorXd p(n);
    p.setConstant(12345.0);  // buildCostGradient must overwrite every entry
    wpg::buildCostGradient(model, problem, p);
    double constant = 0.0;
    for (int trial = 0; trial < 20; ++trial) {
      const VectorXd U = randomU(model, problem, rng);
      const double cost = wpg::evaluateCost(model, problem, U);
      const double quadratic = 0.5 * U.dot(Q * U) + p.dot(U);
      ASSERT_TRUE(std::isfinite(cost));
      const double c = cost - quadratic;
      if (trial == 0) {
        constant = c;
        continue;
      }
      const double scale = std::max({1.0, std::abs(cost), std::abs(quadratic)});
      EXPECT_NEAR(c, constant, 1e-9 * scale)
          << "pattern " << pattern << " instance " << instance << " trial " << trial;
    }
    // The cost is a sum of squares: non-negative, and 0.5 U'QU + p'U + const equals it at the
    // minimizer U* = -Q^{-1} p, where it is smallest.
    const VectorXd U_star = -Q.llt().solve(p);
    const double at_min = wpg::evaluateCost(model, problem, U_star);
    EXPECT_GE(at_min, -1e-9);
    for (int trial = 0; trial < 5; ++trial) {
      VectorXd U = U_star;
      for (int k = 0; k < n; ++k) U(k) += 1e-2 * rng.normal();
      EXPECT_GE(wpg::evaluateCost(model, problem, U), at_min - 1e-9 * std::max(1.0, at_min));
    }
  }
}

TEST_P(NmpcCost, GradientMatchesFiniteDifferencesOfTheCost) {
  const int pattern = GetParam();
  const WalkingParameters w;
  const NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  const int n = L.variableCount();
  Rng rng(300 + pattern);
  const NmpcProblem problem = randomProblem(model, pattern, rng);
  VectorXd p(n);
  wpg::buildCostGradient(model, problem, p);
  const VectorXd U = randomU(model, problem, rng);
  const VectorXd gradient = model.hessian(pattern) * U + p;
  const double h = 1e-5;
  for (int k = 0; k < n; ++k) {
    VectorXd Up = U, Um = U;
    Up(k) += h;
    Um(k) -= h;
    const double fd = (wpg::evaluateCost(model, problem, Up) - wpg::evaluateCost(model, problem, Um)) / (2 * h);
    EXPECT_NEAR(fd, gradient(k), 1e-5 * std::max(1.0, std::abs(gradient(k)))) << "column " << k;
  }
}

TEST_P(NmpcCost, HessianFactorSolves) {
  const int pattern = GetParam();
  const WalkingParameters w;
  const NmpcModel model(w);
  const int n = model.layout().variableCount();
  const MatrixXd& Q = model.hessian(pattern);
  const wpg::qp::HessianFactor& factor = model.hessianFactor(pattern);
  ASSERT_EQ(factor.size, n);
  // J0 = L^{-T}: upper triangular with J0' Q J0 = I.
  const MatrixXd& J0 = factor.inverse_factor_transposed;
  ASSERT_EQ(J0.rows(), n);
  EXPECT_EQ(J0.triangularView<Eigen::StrictlyLower>().toDenseMatrix().cwiseAbs().maxCoeff(), 0.0);
  EXPECT_LE((J0.transpose() * Q * J0 - MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-8);
  Rng rng(500 + pattern);
  const Eigen::LLT<MatrixXd> llt(Q);
  for (int trial = 0; trial < 10; ++trial) {
    VectorXd b(n);
    for (int k = 0; k < n; ++k) b(k) = rng.normal();
    VectorXd x = b;
    factor.solveInPlace(x);
    ASSERT_TRUE(x.allFinite());
    const double residual = (Q * x - b).norm();
    EXPECT_LE(residual, 1e-10 * (Q.norm() * x.norm() + b.norm())) << "trial " << trial;
    const VectorXd reference = llt.solve(b);
    EXPECT_LE((x - reference).norm(), 1e-6 * reference.norm());
  }
}

INSTANTIATE_TEST_SUITE_P(AllPatterns, NmpcCost, ::testing::Range(0, 9),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return info.param == 8 ? std::string("standing")
                                                  : "r" + std::to_string(info.param);
                         });

TEST(NmpcCostModel, PatternCountMatchesParameterization) {
  // The instantiation above assumes the default S = 8 (patterns 0..7 and standing 8).
  const WalkingParameters w;
  EXPECT_EQ(NmpcModel(w).patternCount(), 9);
}

TEST(NmpcHessianFactor, RejectsIndefiniteAndNonFinite) {
  wpg::qp::HessianFactor factor;
  MatrixXd indefinite(2, 2);
  indefinite << 1, 2, 2, 1;
  EXPECT_FALSE(factor.compute(indefinite));
  EXPECT_EQ(factor.size, 0);
  MatrixXd nan = MatrixXd::Identity(2, 2);
  nan(1, 1) = std::nan("");
  EXPECT_FALSE(factor.compute(nan));
  MatrixXd spd(2, 2);
  spd << 4, 1, 1, 3;
  ASSERT_TRUE(factor.compute(spd));
  VectorXd b(2);
  b << 1, 2;
  factor.solveInPlace(b);
  EXPECT_NEAR((spd * b - Eigen::Vector2d(1, 2)).norm(), 0.0, 1e-14);
}

TEST(NmpcCostModel, CostTermsOnAKnownPlan) {
  // Robot at rest over the support ankle, zero plan, zero references: every term is zero
  // except the CoP term of the samples on the (unmoved) previewed steps.
  const WalkingParameters w;
  const NmpcModel model(w);
  const NmpcLayout& L = model.layout();
  NmpcProblem problem = model.makeProblem();
  problem.phase.pattern = 3;
  model.rowStepsOf(3, problem.phase.row_step);
  problem.phase.support_pose = Vector3d(0.5, 0.1, 0.0);
  problem.com_x = Vector3d(0.5, 0, 0);
  problem.com_y = Vector3d(0.1, 0, 0);
  VectorXd U = VectorXd::Zero(L.variableCount());
  for (int i = 0; i < L.steps; ++i) {
    U(L.stepX() + i) = 0.5;
    U(L.stepY() + i) = 0.1;
  }
  EXPECT_NEAR(wpg::evaluateCost(model, problem, U), 0.0, 1e-12);
  // Move step 1 by 0.1 m: J3 = sum over its samples of 0.1^2 (samples 4..11, 8 of them).
  U(L.stepX() + 0) += 0.1;
  EXPECT_NEAR(wpg::evaluateCost(model, problem, U), 0.5 * w.weight_cop * 8 * 0.01, 1e-9);
  // A reference velocity of 0.2 while the robot stays put: J1 = N * 0.2^2.
  U(L.stepX() + 0) -= 0.1;
  problem.velocity_x.setConstant(0.2);
  EXPECT_NEAR(wpg::evaluateCost(model, problem, U), 0.5 * w.weight_velocity * L.horizon * 0.04, 1e-9);
  // A yaw reference of 0.1 on both steps: J2 = 2 * 0.01.
  problem.velocity_x.setZero();
  problem.yaw_reference.setConstant(0.1);
  EXPECT_NEAR(wpg::evaluateCost(model, problem, U), 0.5 * w.weight_yaw * 2 * 0.01, 1e-12);
}

}  // namespace
