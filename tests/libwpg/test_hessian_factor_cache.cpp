// The cache of Hessian factors (wpg/qp/hessian_factor_cache.hpp): the factor it gives is the
// one HessianFactor::compute gives, to the last bit, whoever asked first and from whichever
// thread; it refuses what compute() refuses; NMPC models given the same cache share the
// factors of equal Hessians, and models given none or other caches share nothing.
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
#include "wpg/qp/hessian_factor_cache.hpp"
#include "wpg/pattern_generator.hpp"

namespace {

using wpg::qp::HessianFactor;
using wpg::qp::HessianFactorCache;

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

TEST(HessianFactorCache, IsTheComputedFactorBitForBit) {
  HessianFactorCache cache;
  for (unsigned seed = 0; seed < 20; ++seed) {
    const Eigen::MatrixXd H = randomHessian(seed, 5 + static_cast<int>(seed) % 34);
    HessianFactor fresh;
    ASSERT_TRUE(fresh.compute(H));
    const auto first = cache.factor(H);
    ASSERT_TRUE(first);
    EXPECT_TRUE(sameBits(*first, fresh)) << "seed " << seed;
    const Eigen::MatrixXd copy = H;  // another matrix with the same bits: the same factor
    EXPECT_EQ(cache.factor(copy), first);
    Eigen::MatrixXd nudged = H;  // one bit more in one entry: another factor
    nudged(2, 1) = std::nextafter(nudged(2, 1), 1e9);
    nudged(1, 2) = nudged(2, 1);
    const auto other = cache.factor(nudged);
    ASSERT_TRUE(other);
    EXPECT_NE(other, first);
    HessianFactor nudged_fresh;
    ASSERT_TRUE(nudged_fresh.compute(nudged));
    EXPECT_TRUE(sameBits(*other, nudged_fresh));
  }
}

TEST(HessianFactorCache, RefusesWhatComputeRefuses) {
  HessianFactorCache cache;
  Eigen::MatrixXd H = randomHessian(3, 6);
  H(4, 4) = -1.0;  // not positive definite
  EXPECT_FALSE(HessianFactor().compute(H));
  EXPECT_FALSE(cache.factor(H));
  H = randomHessian(3, 6);
  H(0, 5) = std::numeric_limits<double>::quiet_NaN();  // upper triangle: compute() checks all
  EXPECT_FALSE(HessianFactor().compute(H));
  EXPECT_FALSE(cache.factor(H));
  EXPECT_FALSE(cache.factor(Eigen::MatrixXd::Identity(3, 4)));
}

// Threads asking for the same new Hessians at once all get the factor compute() gives.
TEST(HessianFactorCache, ThreadsGetTheSameBits) {
  std::vector<Eigen::MatrixXd> hessians;
  std::vector<HessianFactor> expected(16);
  for (unsigned k = 0; k < 16; ++k) {
    hessians.push_back(randomHessian(1000 + k, 38));
    ASSERT_TRUE(expected[k].compute(hessians.back()));
  }
  HessianFactorCache cache;
  std::vector<std::vector<std::shared_ptr<const HessianFactor>>> got(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (const Eigen::MatrixXd& H : hessians) got[t].push_back(cache.factor(H));
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

// Two models given the same cache (two runs of a study) share each pattern's factor, which is
// the one the model's Hessian gives; models given no cache, or another one, share nothing.
TEST(HessianFactorCache, ModelsWithTheSameCacheShareTheirFactors) {
  HessianFactorCache cache, other_cache;
  wpg::WalkingParameters parameters;
  const wpg::NmpcModel a(parameters, 0, &cache), b(parameters, 0, &cache);
  const wpg::NmpcModel own(parameters), other(parameters, 0, &other_cache);
  parameters.weight_cop *= 3.0;
  const wpg::NmpcModel c(parameters, 0, &cache);
  ASSERT_EQ(a.patternCount(), b.patternCount());
  for (int pattern = 0; pattern < a.patternCount(); ++pattern) {
    EXPECT_EQ(&a.hessianFactor(pattern), &b.hessianFactor(pattern));
    EXPECT_NE(&a.hessianFactor(pattern), &c.hessianFactor(pattern));
    EXPECT_NE(&a.hessianFactor(pattern), &own.hessianFactor(pattern));
    EXPECT_NE(&a.hessianFactor(pattern), &other.hessianFactor(pattern));
    HessianFactor fresh;
    ASSERT_TRUE(fresh.compute(a.hessian(pattern)));
    EXPECT_TRUE(sameBits(a.hessianFactor(pattern), fresh)) << "pattern " << pattern;
    EXPECT_TRUE(sameBits(own.hessianFactor(pattern), fresh)) << "pattern " << pattern;
  }
}

// A generator given no cache keeps its factors to itself: two generators share none, and one
// given a cache fills that cache (and only it).
TEST(HessianFactorCache, AGeneratorWithoutACacheHasItsOwn) {
  const wpg::WalkingParameters parameters;
  wpg::GeneratorSettings settings;
  const wpg::PatternGenerator first(parameters, settings), second(parameters, settings);
  EXPECT_NE(&first.model().hessianFactor(0), &second.model().hessianFactor(0));
  settings.hessian_factors = std::make_shared<HessianFactorCache>();
  const wpg::PatternGenerator third(parameters, settings), fourth(parameters, settings);
  EXPECT_EQ(&third.model().hessianFactor(0), &fourth.model().hessianFactor(0));
  EXPECT_GT(settings.hessian_factors->size(), 0u);
}

}  // namespace
