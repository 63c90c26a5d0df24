// Stuck is an outcome: a walk whose robot stops making progress along its command ends blocked
// (libwpg's progress_monitor.hpp, fed by the walk loop at every NMPC sample), one that resumes
// does not. The shipped wall (obstacle_wall: no way round) and the paper's experiment B
// (an obstacle across its circle), run as `wpg run` runs them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/walk_generator.hpp"

namespace {

wpg::datasets::Scenario load(const std::string& name,
                             const std::vector<std::string>& overrides = {}) {
  return wpg::datasets::loadScenario(wpg_test::kScenariosDir + "/" + name + ".yaml", overrides,
                                     wpg_test::kRobotsDir);
}

// The sample at time t (samples every control period from 0).
std::size_t sampleAt(const wpg::WalkTrajectory& t, double time) {
  std::size_t i = 0;
  while (i + 1 < t.time.size() && t.time[i] < time - 1e-9) ++i;
  return i;
}

// The wall's way round lies 3.6 m aside of the robot, beyond generator.max_detour: the robot
// walks up to its margin and steps in place there, every NMPC iteration solved: only its
// progress says it is stuck. Blocked since the
// start of the first counted 4.8 s window (three gait cycles, from one gait cycle after the
// command starts at 1 s), in which the CoM walked less than a quarter of the 0.96 m commanded.
TEST(BlockedWalks, WallWithNoWayRoundEndsBlocked) {
  const wpg::datasets::Scenario scenario = load("obstacle_wall");
  const wpg::WalkResult walk = wpg::generateWalk(scenario.walking, scenario.request);
  const wpg::WalkTrajectory& t = walk.trajectory;
  for (const wpg::MpcIterationLog& log : t.mpc)
    EXPECT_EQ(log.status, wpg::IterationStatus::kSolved) << "t = " << log.time;
  EXPECT_NEAR(t.time.back(), 30.0, 1e-9);  // the walk ran its duration out
  ASSERT_TRUE(walk.blocked);
  EXPECT_FALSE(walk.stopped_blocked);
  EXPECT_FALSE(walk.success);
  // The stretch starts with the first window that walks less than a quarter, [8.9, 13.7] s:
  // x walked < 0.24 m.
  const double since = walk.blocked_since;
  EXPECT_NEAR(since, 8.9, 1e-9);
  const auto x = [&](double time) { return t.com[sampleAt(t, time)].x(); };
  EXPECT_LT(x(since + 4.8) - x(since), 0.24);
  EXPECT_EQ(walk.blocked_position, t.com[sampleAt(t, since)].head<2>());
  // In front of the wall's margin (near face 1.85 m, margin 0.2 m) all along.
  for (std::size_t i = 0; i < t.size(); ++i) ASSERT_LT(t.com[i].x(), 1.65);
  EXPECT_EQ(walk.message,
            "the robot is blocked: 0.00 m walked of the 0.96 m commanded in the 4.8 s to t = "
            "29.9 s, since t = 8.9 s at (1.29, -0.01) m");
  // The whole walk: 1.23 m along x of the 0.2 m/s commanded for 29 s.
  EXPECT_NEAR(walk.progress_ratio, t.com.back().x() / (0.2 * 29.0), 1e-3);
}

// generator.stop_when_blocked: the walk ends at the sample it is found blocked (13.7 s: the end
// of the window that starts the stretch), which closes it; what came before is the same walk.
TEST(BlockedWalks, StopWhenBlockedEndsTheWalkWhereItIsFound) {
  const wpg::datasets::Scenario full = load("obstacle_wall");
  const wpg::datasets::Scenario stopping =
      load("obstacle_wall", {"generator.stop_when_blocked=true"});
  const wpg::WalkResult whole = wpg::generateWalk(full.walking, full.request);
  const wpg::WalkResult walk = wpg::generateWalk(stopping.walking, stopping.request);
  ASSERT_TRUE(walk.blocked);
  EXPECT_TRUE(walk.stopped_blocked);
  EXPECT_FALSE(walk.success);
  EXPECT_NEAR(walk.blocked_since, 8.9, 1e-9);
  const wpg::WalkTrajectory& t = walk.trajectory;
  EXPECT_NEAR(t.time.back(), 13.7, 1e-9);
  EXPECT_NEAR(t.mpc.back().time, 13.7, 1e-9);  // its NMPC iteration ran, as a fall's does
  ASSERT_LT(t.size(), whole.trajectory.size());
  for (std::size_t i = 0; i < t.size(); ++i) ASSERT_EQ(t.com[i], whole.trajectory.com[i]) << i;
  EXPECT_NE(walk.message.find("in the 4.8 s to t = 13.7 s, since t = 8.9 s"), std::string::npos)
      << walk.message;
}

// Experiment B: the border of its obstacle turns the robot aside before the margin; no window
// walks less than half its command (0.56), the walk does not end blocked, and
// stop_when_blocked does not stop it: the same walk to its end.
TEST(BlockedWalks, PaperExperimentBIsNotBlocked) {
  const wpg::datasets::Scenario scenario = load("paper_experiment_b");
  const wpg::WalkResult walk = wpg::generateWalk(scenario.walking, scenario.request);
  EXPECT_TRUE(walk.success) << walk.message;
  EXPECT_FALSE(walk.blocked);
  EXPECT_GT(walk.progress_ratio, 0.8);  // 0.87

  const wpg::datasets::Scenario stopping =
      load("paper_experiment_b", {"generator.stop_when_blocked=true"});
  const wpg::WalkResult stopped = wpg::generateWalk(stopping.walking, stopping.request);
  EXPECT_FALSE(stopped.blocked);
  EXPECT_FALSE(stopped.stopped_blocked);
  EXPECT_EQ(stopped.trajectory.com, walk.trajectory.com);
}

// The window is the scenario's: with one gait cycle (1.6 s) the wall is found one cycle after
// the stretch starts, earlier than with the default three.
TEST(BlockedWalks, WindowFromTheScenario) {
  const wpg::datasets::Scenario one_cycle = load(
      "obstacle_wall", {"generator.blocked_window_cycles=1", "generator.stop_when_blocked=true"});
  const wpg::WalkResult walk = wpg::generateWalk(one_cycle.walking, one_cycle.request);
  ASSERT_TRUE(walk.blocked);
  EXPECT_NEAR(walk.trajectory.time.back() - walk.blocked_since, 1.6, 1e-9);
  EXPECT_LT(walk.trajectory.time.back(), 13.7);  // found with three cycles
}

}  // namespace
