// The memo of Hessian factors (wpg/qp/shared_hessian_factor.hpp): the factor it gives is the
// one HessianFactor::compute gives, to the last bit, whoever asked first and from whichever
// thread; it refuses what compute() refuses; NMPC models with the same Hessians share them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <thread>
#include <vector>

#include <Eigen/Core>

#include "wpg/nmpc/model.hpp"
#include "wpg/qp/shared_hessian_factor.hpp"

namespace {

using wpg::qp::HessianFactor;
using wpg::qp::sharedHessianFactor;

// A symmetric positive definite n x n matrix from the seed.
Eigen::MatrixXd randomHessian(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd a(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) a(i, j) = u(rng);
  return a * a.transpose() + n * Eigen::MatrixXd::Identity(n, n);
}

bool sameBits(const HessianFactor& a, const HessianFactor& b) {
  const Eigen::MatrixXd& x = a.inverse_factor_transposed;
  const Eigen::MatrixXd& y = b.inverse_factor_transposed;
  return a.size == b.size && x.rows() == y.rows() && x.cols() == y.cols() &&
         std::memcmp(x.data(), y.data(), sizeof(double) * static_cast<std::size_t>(x.size())) == 0;
}

TEST(SharedHessianFactor, IsTheComputedFactorBitForBit) {
  for (unsigned seed = 0; seed < 20; ++seed) {
    const Eigen::MatrixXd H = randomHessian(seed, 5 + static_cast<int>(seed) % 34);
    HessianFactor fresh;
    ASSERT_TRUE(fresh.compute(H));
    const auto first = sharedHessianFactor(H);
    ASSERT_TRUE(first);
    EXPECT_TRUE(sameBits(*first, fresh)) << "seed " << seed;
    const Eigen::MatrixXd copy = H;  // another matrix with the same bits: the same factor
    EXPECT_EQ(sharedHessianFactor(copy), first);
    Eigen::MatrixXd nudged = H;  // one bit more in one entry: another factor
    nudged(2, 1) = std::nextafter(nudged(2, 1), 1e9);
    nudged(1, 2) = nudged(2, 1);
    const auto other = sharedHessianFactor(nudged);
    ASSERT_TRUE(other);
    EXPECT_NE(other, first);
    HessianFactor nudged_fresh;
    ASSERT_TRUE(nudged_fresh.compute(nudged));
    EXPECT_TRUE(sameBits(*other, nudged_fresh));
  }
}

TEST(SharedHessianFactor, RefusesWhatComputeRefuses) {
  Eigen::MatrixXd H = randomHessian(3, 6);
  H(4, 4) = -1.0;  // not positive definite
  EXPECT_FALSE(HessianFactor().compute(H));
  EXPECT_FALSE(sharedHessianFactor(H));
  H = randomHessian(3, 6);
  H(0, 5) = std::numeric_limits<double>::quiet_NaN();  // upper triangle: compute() checks all
  EXPECT_FALSE(HessianFactor().compute(H));
  EXPECT_FALSE(sharedHessianFactor(H));
  EXPECT_FALSE(sharedHessianFactor(Eigen::MatrixXd::Identity(3, 4)));
}

// Threads asking for the same new Hessians at once all get the factor compute() gives.
TEST(SharedHessianFactor, ThreadsGetTheSameBits) {
  std::vector<Eigen::MatrixXd> hessians;
  std::vector<HessianFactor> expected(16);
  for (unsigned k = 0; k < 16; ++k) {
    hessians.push_back(randomHessian(1000 + k, 38));
    ASSERT_TRUE(expected[k].compute(hessians.back()));
  }
  std::vector<std::vector<std::shared_ptr<const HessianFactor>>> got(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (const Eigen::MatrixXd& H : hessians) got[t].push_back(sharedHessianFactor(H));
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < 4; ++t) {
    for (std::size_t k = 0; k < hessians.size(); ++k) {
      ASSERT_TRUE(got[t][k]);
      EXPECT_TRUE(sameBits(*got[t][k], expected[k])) << "thread " << t << " Hessian " << k;
    }
  }
}

// Two generators with the same walking parameters (two runs of a study) share each pattern's
// factor, which is the one the model's Hessian gives.
TEST(SharedHessianFactor, ModelsWithTheSameHessiansShareTheirFactors) {
  wpg::WalkingParameters parameters;
  const wpg::NmpcModel a(parameters), b(parameters);
  parameters.weight_cop *= 3.0;
  const wpg::NmpcModel c(parameters);
  ASSERT_EQ(a.patternCount(), b.patternCount());
  for (int pattern = 0; pattern < a.patternCount(); ++pattern) {
    EXPECT_EQ(&a.hessianFactor(pattern), &b.hessianFactor(pattern));
    EXPECT_NE(&a.hessianFactor(pattern), &c.hessianFactor(pattern));
    HessianFactor fresh;
    ASSERT_TRUE(fresh.compute(a.hessian(pattern)));
    EXPECT_TRUE(sameBits(a.hessianFactor(pattern), fresh)) << "pattern " << pattern;
  }
}

}  // namespace
