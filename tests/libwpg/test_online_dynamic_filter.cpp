// The online side of the dynamic filter (paper Fig. 3): the preview controller one control
// period at a time equals the offline pass when it knows the same future; the WPG's
// re-initialisation puts the generator exactly in the state it is given and the walk keeps its
// CoP constraints; the plan's preview (previewReference) is what step() then gives, and reading
// it changes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

#include "wpg/dynamic_filter.hpp"
#include "wpg/online_walking_generator.hpp"
#include "wpg/walk_checks.hpp"
#include "wpg/walk_generator.hpp"

namespace {

using Eigen::Vector3d;

constexpr double kDt = 0.005, kHeight = 0.814, kGravity = 9.81;

Eigen::MatrixXd errorSignal(int n) {
  Eigen::MatrixXd error(n, 2);
  for (int k = 0; k < n; ++k) {
    const double t = k * kDt;
    error(k, 0) = 0.01 * std::sin(2.0 * M_PI * t / 0.8) * (t > 1.0 && t < 6.0);
    error(k, 1) = 0.005 * std::cos(2.0 * M_PI * t / 1.6) * (t > 0.5);
  }
  return error;
}

// Given the true future of the error as its window, the online filter is the offline pass.
TEST(OnlineDynamicFilter, EqualsTheOfflinePassWhenItKnowsTheSameFuture) {
  wpg::PreviewControlSettings settings;
  settings.preview_time = 0.8;
  const wpg::PreviewController controller(kDt, kHeight, kGravity, settings);
  const int n = 1600;
  const Eigen::MatrixXd error = errorSignal(n);
  Eigen::MatrixXd offline(n, 2);
  wpg::dynamicFilterCorrection(controller, error, offline);
  wpg::OnlineDynamicFilter filter(controller);
  const int length = controller.previewLength();
  double worst = 0.0;
  for (int k = 0; k < n; ++k) {
    worst = std::max(worst, std::abs(filter.correctionX()(0) - offline(k, 0)));
    worst = std::max(worst, std::abs(filter.correctionY()(0) - offline(k, 1)));
    // rows k .. k + NL (fewer at the end: the last row is held, as track() holds it)
    const int rows = std::min(length + 1, n - k);
    filter.step(error.middleRows(k, rows));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(offline.cwiseAbs().maxCoeff(), 1e-3);  // a real correction was compared
}

TEST(OnlineDynamicFilter, AbsorptionHandsTheStateOverAndRestarts) {
  const wpg::PreviewController controller(kDt, kHeight, kGravity);
  wpg::OnlineDynamicFilter filter(controller);
  const Eigen::MatrixXd error = errorSignal(400);
  for (int k = 0; k + 10 < 400; ++k) filter.step(error.middleRows(k, 10));
  const Vector3d x = filter.correctionX(), y = filter.correctionY();
  ASSERT_GT(x.norm(), 1e-5);
  Vector3d absorbed_x, absorbed_y;
  filter.absorbCorrection(absorbed_x, absorbed_y);
  EXPECT_EQ(absorbed_x, x);
  EXPECT_EQ(absorbed_y, y);
  EXPECT_EQ(filter.correctionX(), Vector3d::Zero());
  EXPECT_EQ(filter.correctionY(), Vector3d::Zero());
  // Restarted at rest: a zero error keeps it there (no integral left).
  filter.step(Eigen::MatrixXd::Zero(5, 2));
  EXPECT_EQ(filter.correctionX(), Vector3d::Zero());
}

// The closed loop's absorption (mode closed_loop): the WPG takes the position of the correction
// it has not taken yet; the filter runs on exactly as if nothing had been absorbed, and the
// correction sent keeps its velocity and acceleration (the CoM sent has no kink).
TEST(OnlineDynamicFilter, IncrementAbsorptionKeepsTheFilterRunningAndTheCoMSmooth) {
  const wpg::PreviewController controller(kDt, kHeight, kGravity);
  wpg::OnlineDynamicFilter absorbing(controller), plain(controller);
  const Eigen::MatrixXd error = errorSignal(1200);
  Vector3d wpg_x = Vector3d::Zero(), wpg_y = Vector3d::Zero();  // what the WPG absorbed
  int absorptions = 0;
  for (int k = 0; k + 40 < 1200; ++k) {
    if (k > 0 && k % 20 == 0) {  // every NMPC iteration (0.1 s)
      const Vector3d sent_x = absorbing.sentCorrectionX(), sent_y = absorbing.sentCorrectionY();
      Vector3d increment_x, increment_y;
      absorbing.absorbIncrement(increment_x, increment_y);
      ++absorptions;
      EXPECT_EQ(increment_x, Vector3d(sent_x(0), 0.0, 0.0));
      EXPECT_EQ(increment_y, Vector3d(sent_y(0), 0.0, 0.0));
      wpg_x += increment_x;
      wpg_y += increment_y;
      // WPG + correction sent: the same position, velocity and acceleration as before.
      EXPECT_NEAR((wpg_x + absorbing.sentCorrectionX() - plain.correctionX()).norm(), 0.0, 1e-15);
      EXPECT_NEAR((wpg_y + absorbing.sentCorrectionY() - plain.correctionY()).norm(), 0.0, 1e-15);
      EXPECT_EQ(absorbing.sentCorrectionX()(0), 0.0);
      EXPECT_EQ(absorbing.sentCorrectionX().tail<2>(), plain.correctionX().tail<2>());
    }
    // Not reset: the same correction as a filter that never absorbed.
    EXPECT_EQ(absorbing.correctionX(), plain.correctionX());
    EXPECT_EQ(absorbing.correctionY(), plain.correctionY());
    absorbing.step(error.middleRows(k, 40));
    plain.step(error.middleRows(k, 40));
  }
  EXPECT_GT(absorptions, 50);
  EXPECT_GT(wpg_x.cwiseAbs().maxCoeff() + wpg_y.cwiseAbs().maxCoeff(), 1e-4);  // real ones
}

TEST(OnlineDynamicFilter, RejectsABadWindow) {
  const wpg::PreviewController controller(kDt, kHeight, kGravity);
  wpg::OnlineDynamicFilter filter(controller);
  EXPECT_THROW(filter.step(Eigen::MatrixXd::Zero(0, 2)), std::invalid_argument);
  EXPECT_THROW(filter.step(Eigen::MatrixXd::Zero(4, 3)), std::invalid_argument);
  Eigen::MatrixXd nan = Eigen::MatrixXd::Zero(4, 2);
  nan(2, 1) = std::nan("");
  EXPECT_THROW(filter.step(nan), std::invalid_argument);
}

TEST(FilterMode, NamesRoundTrip) {
  for (wpg::DynamicFilterMode mode : {wpg::DynamicFilterMode::kOnline,
                                      wpg::DynamicFilterMode::kOffline,
                                      wpg::DynamicFilterMode::kBoth,
                                      wpg::DynamicFilterMode::kClosedLoop}) {
    wpg::DynamicFilterMode parsed = wpg::DynamicFilterMode::kOnline;
    ASSERT_TRUE(wpg::parseDynamicFilterMode(wpg::dynamicFilterModeName(mode), &parsed));
    EXPECT_EQ(parsed, mode);
  }
  wpg::DynamicFilterMode parsed;
  EXPECT_FALSE(wpg::parseDynamicFilterMode("closed", &parsed));
}

// A controller that re-initialises the WPG at every NMPC iteration with a corrected state
// (its own plus a small, changing offset, as the dynamic filter's correction would be), and
// checks the generator then holds exactly that state.
class Reinitializer : public wpg::ControlLoopObserver {
 public:
  void beforeStep(wpg::OnlineWalkingGenerator& generator) override {
    if (!generator.atSamplingInstant() || generator.time() < 1.0) return;
    ++count_;
    const double s = std::sin(0.7 * count_);
    target_x_ = generator.comStateX() + Vector3d(0.002 * s, 0.004 * s, 0.03 * s);
    target_y_ = generator.comStateY() + Vector3d(-0.002 * s, 0.003 * s, -0.02 * s);
    generator.reinitializeCom(target_x_, target_y_);
    worst_ = std::max(worst_, (generator.comStateX() - target_x_).norm());
    worst_ = std::max(worst_, (generator.comStateY() - target_y_).norm());
    worst_ = std::max(worst_, (generator.patternGenerator().comX() - target_x_).norm());
    worst_ = std::max(worst_, (generator.patternGenerator().comY() - target_y_).norm());
    check_sample_ = true;
  }
  void afterStep(wpg::OnlineWalkingGenerator&, const wpg::ControlSample& sample) override {
    if (!check_sample_) return;
    check_sample_ = false;
    // The sample of the re-initialised instant is the given state.
    worst_ = std::max(worst_, std::abs(sample.com_position.x() - target_x_(0)));
    worst_ = std::max(worst_, std::abs(sample.com_velocity.x() - target_x_(1)));
    worst_ = std::max(worst_, std::abs(sample.com_acceleration.x() - target_x_(2)));
    worst_ = std::max(worst_, std::abs(sample.com_position.y() - target_y_(0)));
    worst_ = std::max(worst_, std::abs(sample.com_velocity.y() - target_y_(1)));
    worst_ = std::max(worst_, std::abs(sample.com_acceleration.y() - target_y_(2)));
  }
  int count_ = 0;
  double worst_ = 0.0;

 private:
  Vector3d target_x_, target_y_;
  bool check_sample_ = false;
};

TEST(Reinitialization, TheGeneratorTakesTheCorrectedStateAndKeepsItsCopConstraints) {
  for (const Vector3d command : {Vector3d(0.2, 0.0, 0.0), Vector3d(0.2, 0.0, 0.2)}) {
    wpg::WalkingParameters parameters;
    parameters.max_step_yaw_change = 0.17;
    wpg::WalkRequest request;
    request.duration = 8.0;
    request.reference = {{0.0, Vector3d::Zero()}, {1.0, command}};
    Reinitializer reinitializer;
    const wpg::WalkResult walk = wpg::generateWalk(parameters, request, {}, &reinitializer);
    ASSERT_TRUE(walk.success) << walk.message;
    EXPECT_GE(reinitializer.count_, 60);
    EXPECT_LT(reinitializer.worst_, 1e-12);
    for (const wpg::MpcIterationLog& log : walk.trajectory.mpc)
      EXPECT_EQ(log.status, wpg::IterationStatus::kSolved) << "t = " << log.time;
    // The CoP at every NMPC sample within the margin-reduced support the NMPC constrains.
    const wpg::WalkCheckReport report = wpg::checkWalk(parameters, walk.trajectory);
    EXPECT_LE(report.cop_sample_violation, 1e-6) << "at t = " << report.cop_sample_violation_time;
    // ... and the walk did move: the re-initialisations were not no-ops.
    EXPECT_GT(walk.trajectory.com.back().head<2>().norm(), 0.8);
  }
}

TEST(Reinitialization, OnlyAtASamplingInstant) {
  wpg::OnlineWalkingGenerator generator{wpg::WalkingParameters(), wpg::GeneratorSettings()};
  generator.step();
  EXPECT_THROW(generator.reinitializeCom(Vector3d::Zero(), Vector3d::Zero()), std::logic_error);
  for (int i = 1; i < 20; ++i) generator.step();
  EXPECT_NO_THROW(generator.reinitializeCom(Vector3d(0.01, 0, 0), Vector3d::Zero()));
  EXPECT_THROW(generator.reinitializeCom(Vector3d(std::nan(""), 0, 0), Vector3d::Zero()),
               std::invalid_argument);
  EXPECT_THROW(generator.reinitializeCom(Eigen::Vector2d::Zero(), Vector3d::Zero()),
               std::invalid_argument);
}

// The preview of the plan in force is what step() gives until the next NMPC iteration (the
// plan is the same), and reading it does not change the generator.
TEST(PreviewReference, IsWhatStepGivesUntilTheNextNmpcIteration) {
  wpg::OnlineWalkingGenerator previewed{wpg::WalkingParameters(), wpg::GeneratorSettings()};
  wpg::OnlineWalkingGenerator plain{wpg::WalkingParameters(), wpg::GeneratorSettings()};
  for (wpg::OnlineWalkingGenerator* g : {&previewed, &plain}) g->setCommand(Vector3d(0.2, 0, 0));
  wpg::WalkTrajectory preview;
  int compared = 0;
  for (int tick = 0; tick < 800; ++tick) {
    ASSERT_EQ(previewed.atSamplingInstant(), plain.atSamplingInstant());
    ASSERT_NEAR(previewed.time(), plain.time(), 1e-12);
    if (tick % 20 == 7) {  // mid-period: 13 control periods left before the next NMPC
      previewed.previewReference(180, preview);
      ASSERT_EQ(preview.size(), 180u);
      for (int j = 0; j < 13; ++j) {
        const wpg::ControlSample& s = previewed.step();
        plain.step();
        ++tick;
        EXPECT_LT((s.com_position - preview.com[j]).norm(), 1e-12);
        EXPECT_LT((s.cop - preview.cop[j]).norm(), 1e-12);
        EXPECT_LT((s.left_foot - preview.left_foot[j]).norm(), 1e-12);
        EXPECT_LT((s.right_foot - preview.right_foot[j]).norm(), 1e-12);
        EXPECT_NEAR(s.time, preview.time[j], 1e-12);
        ++compared;
      }
      --tick;
      continue;
    }
    const wpg::ControlSample& a = previewed.step();
    const wpg::ControlSample& b = plain.step();
    EXPECT_EQ(a.com_position, b.com_position);
    EXPECT_EQ(a.left_foot, b.left_foot);
  }
  EXPECT_GT(compared, 300);
  // Feet in the preview stay where the plan puts them: no jump between control instants.
  for (std::size_t j = 1; j < preview.size(); ++j) {
    EXPECT_LT((preview.left_foot[j] - preview.left_foot[j - 1]).head<3>().norm(), 0.02);
    EXPECT_LT((preview.right_foot[j] - preview.right_foot[j - 1]).head<3>().norm(), 0.02);
  }
  wpg::OnlineWalkingGenerator at_instant{wpg::WalkingParameters(), wpg::GeneratorSettings()};
  EXPECT_THROW(at_instant.previewReference(10, preview), std::logic_error);
}

}  // namespace
