// Kajita et al. 2003 preview control and the dynamic filter built on it (paper Sec. IV).
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "wpg/dynamic_filter.hpp"
#include "wpg/preview_control.hpp"

namespace {

constexpr double kDt = 0.005, kHeight = 0.814, kGravity = 9.81;

TEST(PreviewControl, RiccatiSolutionAndStableClosedLoop) {
  const wpg::PreviewController controller(kDt, kHeight, kGravity);
  const Eigen::Matrix4d& P = controller.riccati();
  EXPECT_LT(controller.riccatiResidual(), 1e-9 * P.cwiseAbs().maxCoeff());
  EXPECT_LT((P - P.transpose()).cwiseAbs().maxCoeff(), 1e-9 * P.cwiseAbs().maxCoeff());
  EXPECT_GT(P.selfadjointView<Eigen::Lower>().eigenvalues().minCoeff(), -1e-9);
  EXPECT_LT(controller.closedLoopSpectralRadius(), 1.0);
  EXPECT_EQ(controller.previewLength(), 320);  // 1.6 s at 5 ms
  // Gd_1 = -Gi, the preview gains decay, and their infinite sum equals -Gx(c): what is left
  // beyond 1.6 s is below 1 % (the truncation the classic 1.6 s preview accepts).
  const Eigen::VectorXd& Gd = controller.previewGains();
  EXPECT_DOUBLE_EQ(Gd(0), -controller.integralGain());
  EXPECT_LT(std::abs(Gd(Gd.size() - 1)), 0.02 * std::abs(Gd(0)));
  EXPECT_NEAR(Gd.sum(), -controller.stateGain()(0), 0.01 * controller.stateGain()(0));
}

TEST(PreviewControl, TracksAZmpStaircaseWithPreview) {
  const wpg::PreviewController controller(kDt, kHeight, kGravity);
  const int n = 2400, step = 160;  // 0.8 s per support
  Eigen::VectorXd reference(n);
  for (int k = 0; k < n; ++k) reference(k) = (k / step) % 2 ? 0.1 : -0.1;
  Eigen::MatrixXd states(n, 3);
  Eigen::VectorXd zmp(n);
  controller.track(reference, Eigen::Vector3d(-0.1, 0.0, 0.0), states, zmp);
  double worst = 0.0;
  for (int k = 2 * step; k < n - 2 * step; ++k)
    if (k % step >= 20 && k % step < step - 20)
      worst = std::max(worst, std::abs(zmp(k) - reference(k)));
  // A ZMP step cannot be followed exactly by the cart-table: preview control smooths it over
  // both sides of the switch (it anticipates); 0.1 s away the error is below 2 mm.
  EXPECT_LT(worst, 2e-3) << "ZMP error more than 0.1 s away from a switch";
  // The CoM stays between the supports and moves before the ZMP switches (preview).
  EXPECT_LE(states.col(0).cwiseAbs().maxCoeff(), 0.1 + 1e-12);
  EXPECT_GT(states(5 * step - 1, 0), states(5 * step - 40, 0));
}

TEST(PreviewControl, ConstantReferenceIsReachedExactly) {
  const wpg::PreviewController controller(kDt, kHeight, kGravity);
  const int n = 3000;
  Eigen::MatrixXd states(n, 3);
  Eigen::VectorXd zmp(n);
  controller.track(Eigen::VectorXd::Constant(n, 0.05), Eigen::Vector3d::Zero(), states, zmp);
  EXPECT_NEAR(zmp(n - 1), 0.05, 1e-6);
  EXPECT_NEAR(states(n - 1, 0), 0.05, 1e-6);
}

TEST(PreviewControl, RejectsBadSettings) {
  wpg::PreviewControlSettings settings;
  settings.input_weight = 0.0;
  EXPECT_THROW(wpg::PreviewController(kDt, kHeight, kGravity, settings), std::invalid_argument);
  EXPECT_THROW(wpg::PreviewController(0.0, kHeight, kGravity), std::invalid_argument);
}

// The filter's correction has the ZMP error as its cart-table ZMP: z(dc) = dc - h/g dc''.
TEST(DynamicFilter, CorrectionReproducesTheZmpError) {
  const wpg::PreviewController controller(kDt, kHeight, kGravity);
  const int n = 2000;
  Eigen::MatrixXd error(n, 2);
  for (int k = 0; k < n; ++k) {
    const double t = k * kDt;
    error(k, 0) = 0.01 * std::sin(2.0 * M_PI * t / 0.8) * (t > 1.0 && t < 8.0);
    error(k, 1) = 0.005 * std::cos(2.0 * M_PI * t / 1.6) * (t > 1.0 && t < 8.0);
  }
  Eigen::MatrixXd correction(n, 2);
  wpg::dynamicFilterCorrection(controller, error, correction);
  double worst = 0.0;
  for (int k = 400; k < 1500; ++k) {
    for (int axis = 0; axis < 2; ++axis) {
      const double acceleration =
          (correction(k + 1, axis) - 2 * correction(k, axis) + correction(k - 1, axis)) / (kDt * kDt);
      const double zmp = correction(k, axis) - kHeight / kGravity * acceleration;
      worst = std::max(worst, std::abs(zmp - error(k, axis)));
    }
  }
  EXPECT_LT(worst, 5e-4);
  EXPECT_TRUE(correction.allFinite());
}

}  // namespace
