// The progress monitor (wpg/progress_monitor.hpp) on synthetic CoM and command sequences whose
// verdicts follow from its definition by hand: a robot that walks is never blocked, one that
// stops in front of something is blocked from the right window start, one that resumes is
// not, and samples without a linear command judge nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include <Eigen/Core>

#include "wpg/progress_monitor.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walking_parameters.hpp"

namespace {

using wpg::ProgressMonitor;

constexpr double kT = 0.1;      // sampling period [s]
constexpr int kWindow = 48;     // 4.8 s: three gait cycles of 0.8 s steps
constexpr int kSettle = 16;     // one gait cycle of command before a window counts
constexpr double kSway = 0.05;  // lateral sway amplitude [m]
constexpr double kCycle = 1.6;  // gait cycle [s]

// Feeds samples k = 0 .. samples-1 at k T: the CoM x(t) plus a lateral sway of one gait cycle,
// the command v(t) (world), then the closing sample at samples T.
struct Feed {
  std::function<double(double)> x;
  std::function<Eigen::Vector2d(double)> v;
};

Eigen::Vector2d com(const Feed& f, double t) {
  return {f.x(t), kSway * std::sin(2.0 * M_PI * t / kCycle)};
}

ProgressMonitor run(const Feed& f, int samples, double threshold = 0.25) {
  ProgressMonitor monitor(kT, kWindow, kSettle, threshold);
  for (int k = 0; k < samples; ++k) monitor.addSample(k * kT, com(f, k * kT), f.v(k * kT));
  monitor.finish(samples * kT, com(f, samples * kT));
  return monitor;
}

Eigen::Vector2d forward(double) { return {0.2, 0.0}; }

TEST(ProgressMonitor, WindowIsThreeGaitCyclesOfTheNominalSteps) {
  wpg::WalkingParameters w;  // HRP-2's 0.7 + 0.1 s steps, T = 0.1 s
  w.single_support_samples = 7;
  w.double_support_samples = 1;
  w.sampling_period = 0.1;
  const ProgressMonitor monitor(w, wpg::GeneratorSettings());
  EXPECT_EQ(monitor.windowSamples(), 48);  // 6 steps of 0.8 s: 4.8 s
  wpg::GeneratorSettings one;
  one.blocked_window_cycles = 1;
  EXPECT_EQ(ProgressMonitor(w, one).windowSamples(), 16);
}

// Walking at the commanded speed, with its sway: every window walks its whole command.
TEST(ProgressMonitor, WalkingRobotIsNotBlocked) {
  const Feed walking{[](double t) { return 0.2 * t; }, forward};
  const ProgressMonitor monitor = run(walking, 300);
  EXPECT_FALSE(monitor.blocked());
  EXPECT_NEAR(monitor.progressRatio(), 1.0, 1e-12);
  // Slower than commanded but above the threshold: still progress.
  const Feed slow{[](double t) { return 0.06 * t; }, forward};
  EXPECT_FALSE(run(slow, 300).blocked());
  EXPECT_NEAR(run(slow, 300).progressRatio(), 0.3, 1e-12);
}

// Walks to x = 2.03 m, then steps in place (the sway goes on). The window [t - 4.8, t] walks
// 2.03 - 0.2 (t - 4.8) of the 0.96 m commanded; below 0.25 x 0.96 = 0.24 m from t - 4.8 > 8.95:
// the first such window starts at t = 9.0 s, x = 1.8 m.
TEST(ProgressMonitor, StuckRobotIsBlockedSinceTheFirstWindowWithoutProgress) {
  const Feed stuck{[](double t) { return std::min(0.2 * t, 2.03); }, forward};
  ProgressMonitor monitor(kT, kWindow, kSettle, 0.25);
  double found = -1.0;
  for (int k = 0; k < 300; ++k) {
    monitor.addSample(k * kT, com(stuck, k * kT), stuck.v(k * kT));
    if (found < 0.0 && monitor.blocked()) found = k * kT;
  }
  monitor.finish(30.0, com(stuck, 30.0));
  ASSERT_TRUE(monitor.blocked());
  EXPECT_NEAR(found, 13.8, 1e-9);  // the window that ends 4.8 s after its start at 9.0 s
  EXPECT_NEAR(monitor.blockedSince(), 9.0, 1e-9);
  EXPECT_NEAR(monitor.blockedPosition().x(), 1.8, 1e-9);
  EXPECT_NEAR(monitor.blockedPosition().y(), com(stuck, 9.0).y(), 1e-12);
  // The last window (25.1 .. 29.9 s) walked nothing but the sway's change, along x: 0.
  const ProgressMonitor::Window& last = monitor.lastBlockedWindow();
  EXPECT_NEAR(last.end_time, 29.9, 1e-9);
  EXPECT_NEAR(last.duration, 4.8, 1e-9);
  EXPECT_NEAR(last.commanded, 0.96, 1e-12);
  EXPECT_NEAR(last.walked, 0.0, 1e-12);
  // The whole walk: 2.03 m walked of 0.2 x 30 = 6 m commanded.
  EXPECT_NEAR(monitor.progressRatio(), 2.03 / 6.0, 1e-12);
  EXPECT_EQ(monitor.describeBlocked(),
            "0.00 m walked of the 0.96 m commanded in the 4.8 s to t = 29.9 s, since t = 9.0 s "
            "at (1.80, -0.04) m");  // the sway: 0.05 sin(2 pi 9.0 / 1.6) = -0.035
}

// Stuck from 10 s to 20.05 s, then walking on: the window that walks 0.24 m again (x(t) -
// x(t - 4.8) >= 0.24 from t >= 21.25 s) closes the stretch; a later stop opens a new one with
// its own start.
TEST(ProgressMonitor, RobotThatResumesIsNotBlocked) {
  const auto x = [](double t) {
    return t < 10.0 ? 0.2 * t : t < 20.05 ? 2.0 : 2.0 + 0.2 * (t - 20.05);
  };
  const Feed resumed{x, forward};
  ProgressMonitor monitor(kT, kWindow, kSettle, 0.25);
  bool was_blocked = false;
  double resumed_at = -1.0;
  for (int k = 0; k < 400; ++k) {
    monitor.addSample(k * kT, com(resumed, k * kT), resumed.v(k * kT));
    if (monitor.blocked()) was_blocked = true;
    if (was_blocked && resumed_at < 0.0 && !monitor.blocked()) resumed_at = k * kT;
  }
  EXPECT_TRUE(was_blocked);
  EXPECT_FALSE(monitor.blocked());
  EXPECT_NEAR(resumed_at, 21.3, 1e-9);

  // Stopped again at 30.03 s (x = 3.996 m): 3.996 - x(t - 4.8) < 0.24 from t - 4.8 > 28.83 s,
  // since 28.9 s: the new stretch's own start.
  const auto again = [&](double t) { return x(std::min(t, 30.03)); };
  const ProgressMonitor second = run({again, forward}, 400);
  ASSERT_TRUE(second.blocked());
  EXPECT_NEAR(second.blockedSince(), 28.9, 1e-9);
}

// Without a linear command (standing, or turning on the spot) no window counts: nothing opens,
// and a stretch already open is not closed by windows that ask for no progress.
TEST(ProgressMonitor, WindowsWithoutLinearCommandJudgeNothing) {
  const Feed standing{[](double) { return 0.0; }, [](double) { return Eigen::Vector2d(0, 0); }};
  const ProgressMonitor idle = run(standing, 300);
  EXPECT_FALSE(idle.blocked());
  EXPECT_TRUE(std::isnan(idle.progressRatio()));  // no command: the ratio does not apply

  // A command below kMinLinearCommand is none either.
  const Feed tiny{
      [](double) { return 0.0; },
      [](double) { return Eigen::Vector2d(0.5 * ProgressMonitor::kMinLinearCommand, 0); }};
  EXPECT_FALSE(run(tiny, 300).blocked());

  // Stuck at 2 m, then the command stops at 20 s: still blocked at the end, since 9.0 s.
  const Feed stopped{
      [](double t) { return std::min(0.2 * t, 2.03); },
      [](double t) { return t < 20.0 ? Eigen::Vector2d(0.2, 0) : Eigen::Vector2d(0, 0); }};
  const ProgressMonitor after = run(stopped, 300);
  EXPECT_TRUE(after.blocked());
  EXPECT_NEAR(after.blockedSince(), 9.0, 1e-9);

  // One sample without command inside each window: none counts, the robot never stuck.
  const Feed gaps{[](double) { return 0.0; },
                  [](double t) {
                    const long k = std::lround(t / kT);
                    return k % 40 == 0 ? Eigen::Vector2d(0, 0) : Eigen::Vector2d(0.2, 0);
                  }};
  EXPECT_FALSE(run(gaps, 300).blocked());
}

// A start that takes its time: the robot stands until 3.7 s, then walks at the command. The
// window that starts with the command walks 0.22 m of 0.96 (0.23 < 0.25); one gait cycle later
// the first counted window [1.6, 6.4] s walks 0.54 m. Judged from the start, it would be
// blocked since 0 s.
TEST(ProgressMonitor, FirstGaitCycleOfACommandIsNotJudged) {
  const Feed late{[](double t) { return std::max(0.0, 0.2 * (t - 3.7)); }, forward};
  EXPECT_FALSE(run(late, 100).blocked());
  ProgressMonitor unsettled(kT, kWindow, 0, 0.25);
  for (int k = 0; k <= 48; ++k) unsettled.addSample(k * kT, com(late, k * kT), late.v(k * kT));
  ASSERT_TRUE(unsettled.blocked());
  EXPECT_NEAR(unsettled.blockedSince(), 0.0, 1e-12);
  EXPECT_NEAR(unsettled.lastBlockedWindow().walked, 0.22, 1e-12);
}

// The commanded displacement is the sum of the world-frame commands: a robot walking a
// quarter circle along its turning command progresses; a command that turns back on itself
// within a window (|D| below half the commanded path) is no direction and judges nothing.
TEST(ProgressMonitor, TurningCommandsAndCommandsThatTurnBack) {
  const double omega = 0.2;  // rad/s: 0.96 rad a window
  const auto v = [&](double t) {
    return Eigen::Vector2d(0.2 * std::cos(omega * t), 0.2 * std::sin(omega * t));
  };
  ProgressMonitor circle(kT, kWindow, kSettle, 0.25);
  for (int k = 0; k <= 300; ++k) {
    const double t = k * kT;
    circle.addSample(t, Eigen::Vector2d(std::sin(omega * t), 1.0 - std::cos(omega * t)), v(t));
  }
  EXPECT_FALSE(circle.blocked());
  EXPECT_GT(circle.progressRatio(), 0.99);  // the chords of 0.1 s arcs

  const Feed back_and_forth{[](double) { return 0.0; },
                            [](double t) {
                              return std::fmod(t, 2.0) < 1.0 ? Eigen::Vector2d(0.2, 0)
                                                             : Eigen::Vector2d(-0.2, 0);
                            }};
  EXPECT_FALSE(run(back_and_forth, 300).blocked());
}

// The threshold is the ratio walked / commanded: 0.3 of the command is progress at 0.25, not
// at 0.5.
TEST(ProgressMonitor, ThresholdIsTheRatioOfWalkedToCommanded) {
  const Feed slow{[](double t) { return 0.06 * t; }, forward};
  EXPECT_FALSE(run(slow, 300, 0.25).blocked());
  const ProgressMonitor strict = run(slow, 300, 0.5);
  ASSERT_TRUE(strict.blocked());
  EXPECT_NEAR(strict.blockedSince(), 1.6, 1e-12);  // the first window: a cycle after the start
  EXPECT_NEAR(strict.lastBlockedWindow().progress, 0.3, 1e-12);
}

// A walk that stopped at its last sample has no period after it: finish() at that instant
// adds nothing to the ratio.
TEST(ProgressMonitor, FinishAtTheLastSampleAddsNothing) {
  ProgressMonitor monitor(kT, kWindow, kSettle, 0.25);
  for (int k = 0; k < 10; ++k)
    monitor.addSample(k * kT, Eigen::Vector2d(0.02 * k, 0.0), {0.2, 0.0});
  EXPECT_NEAR(monitor.progressRatio(), 1.0, 1e-12);  // 9 periods of 0.02 m each way
  monitor.finish(0.9, Eigen::Vector2d(5.0, 0.0));    // the last sample's instant: ignored
  EXPECT_NEAR(monitor.progressRatio(), 1.0, 1e-12);
  ProgressMonitor closed(kT, kWindow, kSettle, 0.25);
  for (int k = 0; k < 10; ++k) closed.addSample(k * kT, Eigen::Vector2d(0.02 * k, 0.0), {0.2, 0.0});
  closed.finish(1.0, Eigen::Vector2d(0.19, 0.0));  // the tenth period walks 0.01 m of 0.02
  EXPECT_NEAR(closed.progressRatio(), 0.19 / 0.2, 1e-12);
}

TEST(ProgressMonitor, RefusesABadWindowOrThreshold) {
  EXPECT_THROW(ProgressMonitor(0.1, 0, 16, 0.25), std::invalid_argument);
  EXPECT_THROW(ProgressMonitor(0.1, 48, -1, 0.25), std::invalid_argument);
  EXPECT_THROW(ProgressMonitor(0.1, 48, 16, 0.0), std::invalid_argument);
  EXPECT_THROW(ProgressMonitor(0.1, 48, 16, 1.0), std::invalid_argument);
  EXPECT_THROW(ProgressMonitor(0.0, 48, 16, 0.25), std::invalid_argument);
}

}  // namespace
