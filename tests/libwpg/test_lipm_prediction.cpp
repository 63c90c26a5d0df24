// Tests of the LIPM prediction matrices (paper eq. 1-3) against step-by-step integration of
// the piecewise-constant jerk model with integrateJerk.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>

#include "wpg/lipm_prediction.hpp"

namespace {

using Eigen::Vector3d;
using Eigen::VectorXd;
using wpg::integrateJerk;
using wpg::LipmPrediction;

constexpr double kHeight = 0.814;
constexpr double kGravity = 9.81;

// |a - b| <= tol * max(1, |b|)
::testing::AssertionResult closeRelative(double a, double b, double tol) {
  const double scale = std::max(1.0, std::abs(b));
  if (std::abs(a - b) <= tol * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b << " (difference " << a - b
                                       << ", allowed " << tol * scale << ")";
}

struct Rng {
  explicit Rng(unsigned seed) : engine(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(engine);
  }
  std::mt19937 engine;
};

// Checks every row of the prediction against integrateJerk applied sample by sample, with
// `substeps` sub-steps of T/substeps per sample (the jerk is constant over a sample, so the
// sub-stepped integration is exact too).
void checkAgainstIntegration(int N, double T, int substeps, unsigned seed, double tol) {
  const LipmPrediction P(N, T, kHeight, kGravity);
  Rng rng(seed);
  for (int trial = 0; trial < 20; ++trial) {
    const Vector3d c_hat(rng.uniform(-2, 2), rng.uniform(-1, 1), rng.uniform(-3, 3));
    VectorXd jerks(N);
    for (int i = 0; i < N; ++i) jerks(i) = rng.uniform(-5, 5);

    const VectorXd position = P.position_state * c_hat + P.position_jerk * jerks;
    const VectorXd velocity = P.velocity_state * c_hat + P.velocity_jerk * jerks;
    const VectorXd acceleration = P.acceleration_state * c_hat + P.acceleration_jerk * jerks;
    const VectorXd cop = P.cop_state * c_hat + P.cop_jerk * jerks;

    Vector3d state = c_hat;
    for (int j = 0; j < N; ++j) {
      for (int s = 0; s < substeps; ++s) integrateJerk(state, jerks(j), T / substeps);
      SCOPED_TRACE(::testing::Message() << "N=" << N << " T=" << T << " trial " << trial
                                        << " row " << j);
      EXPECT_TRUE(closeRelative(position(j), state(0), tol));
      EXPECT_TRUE(closeRelative(velocity(j), state(1), tol));
      EXPECT_TRUE(closeRelative(acceleration(j), state(2), tol));
      // eq. (3): z = c - h/g c''
      EXPECT_TRUE(closeRelative(cop(j), state(0) - kHeight / kGravity * state(2), tol));
    }
  }
}

TEST(LipmPrediction, SizesAndConstants) {
  const LipmPrediction P(16, 0.1, kHeight, kGravity);
  EXPECT_EQ(P.horizon_length, 16);
  EXPECT_DOUBLE_EQ(P.sampling_period, 0.1);
  EXPECT_NEAR(P.height_over_gravity, kHeight / kGravity, 1e-15);
  for (const auto* m : {&P.position_state, &P.velocity_state, &P.acceleration_state, &P.cop_state}) {
    EXPECT_EQ(m->rows(), 16);
    EXPECT_EQ(m->cols(), 3);
  }
  for (const auto* m : {&P.position_jerk, &P.velocity_jerk, &P.acceleration_jerk, &P.cop_jerk}) {
    EXPECT_EQ(m->rows(), 16);
    EXPECT_EQ(m->cols(), 16);
  }
}

TEST(LipmPrediction, MatchesStepByStepIntegration) {
  checkAgainstIntegration(16, 0.1, 1, 1u, 1e-12);
}

TEST(LipmPrediction, MatchesIntegrationAtControlPeriod) {
  // 20 sub-steps of 5 ms per 0.1 s sample, as the walk generator integrates the CoM.
  checkAgainstIntegration(16, 0.1, 20, 2u, 1e-12);
}

TEST(LipmPrediction, OtherHorizonsAndPeriods) {
  checkAgainstIntegration(8, 0.05, 1, 3u, 1e-12);
  checkAgainstIntegration(30, 0.2, 1, 4u, 1e-12);
  checkAgainstIntegration(1, 0.1, 1, 5u, 1e-12);
}

TEST(LipmPrediction, JerkMatricesAreCausal) {
  // Row j (sample k+j+1) depends on the jerks of samples k..k+j only: strictly upper part zero,
  // and the diagonal is the one-sample response B = (T^3/6, T^2/2, T).
  const double T = 0.1;
  const LipmPrediction P(16, T, kHeight, kGravity);
  for (int j = 0; j < 16; ++j) {
    for (int i = j + 1; i < 16; ++i) {
      EXPECT_EQ(P.position_jerk(j, i), 0.0);
      EXPECT_EQ(P.velocity_jerk(j, i), 0.0);
      EXPECT_EQ(P.acceleration_jerk(j, i), 0.0);
      EXPECT_EQ(P.cop_jerk(j, i), 0.0);
    }
    EXPECT_NEAR(P.position_jerk(j, j), T * T * T / 6.0, 1e-15);
    EXPECT_NEAR(P.velocity_jerk(j, j), T * T / 2.0, 1e-15);
    EXPECT_NEAR(P.acceleration_jerk(j, j), T, 1e-15);
    EXPECT_NEAR(P.cop_jerk(j, j), T * T * T / 6.0 - kHeight / kGravity * T, 1e-15);
    // Time invariance: the response to a jerk depends only on j - i (Toeplitz).
    for (int i = 1; i <= j; ++i) {
      EXPECT_NEAR(P.position_jerk(j, i), P.position_jerk(j - 1, i - 1), 1e-15);
      EXPECT_NEAR(P.cop_jerk(j, i), P.cop_jerk(j - 1, i - 1), 1e-15);
    }
  }
}

TEST(LipmPrediction, CopRowsAreOutputOfStateRows) {
  const LipmPrediction P(16, 0.1, kHeight, kGravity);
  const double hg = kHeight / kGravity;
  const auto cop_state = P.position_state - hg * P.acceleration_state;
  const auto cop_jerk = P.position_jerk - hg * P.acceleration_jerk;
  EXPECT_LE((P.cop_state - cop_state).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LE((P.cop_jerk - cop_jerk).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(LipmPrediction, RestStateStaysAtRestAndConstantVelocityIsExact) {
  const double T = 0.1;
  const LipmPrediction P(16, T, kHeight, kGravity);
  const VectorXd zero = VectorXd::Zero(16);
  // At rest at x = 0.3: CoM and CoP stay there.
  const Vector3d rest(0.3, 0.0, 0.0);
  const VectorXd p = P.position_state * rest + P.position_jerk * zero;
  const VectorXd z = P.cop_state * rest + P.cop_jerk * zero;
  for (int j = 0; j < 16; ++j) {
    EXPECT_NEAR(p(j), 0.3, 1e-15);
    EXPECT_NEAR(z(j), 0.3, 1e-15);
  }
  // Constant velocity 0.2: c(j) = 0.2 * (j+1) T.
  const Vector3d moving(0.0, 0.2, 0.0);
  const VectorXd pm = P.position_state * moving;
  const VectorXd vm = P.velocity_state * moving;
  for (int j = 0; j < 16; ++j) {
    EXPECT_NEAR(pm(j), 0.2 * (j + 1) * T, 1e-14);
    EXPECT_NEAR(vm(j), 0.2, 1e-15);
  }
}

TEST(IntegrateJerk, ExternalAccelerationMovesPositionAndVelocityOnly) {
  // A push acceleration a_ext over dt: position += a_ext dt^2 / 2, velocity += a_ext dt, the
  // controlled acceleration (the one the CoP balances) is unchanged.
  const Vector3d start(0.1, 0.2, 0.3);
  const double dt = 0.005, jerk = 1.5, push = 4.0;
  Vector3d free = start, pushed = start;
  integrateJerk(free, jerk, dt);
  integrateJerk(pushed, jerk, dt, push);
  EXPECT_NEAR(pushed(0) - free(0), push * dt * dt / 2.0, 1e-16);
  EXPECT_NEAR(pushed(1) - free(1), push * dt, 1e-16);
  EXPECT_EQ(pushed(2), free(2));
  // Exact polynomial values of the free motion.
  EXPECT_NEAR(free(0), 0.1 + 0.2 * dt + 0.3 * dt * dt / 2 + jerk * dt * dt * dt / 6, 1e-16);
  EXPECT_NEAR(free(1), 0.2 + 0.3 * dt + jerk * dt * dt / 2, 1e-16);
  EXPECT_NEAR(free(2), 0.3 + jerk * dt, 1e-16);
}

}  // namespace
