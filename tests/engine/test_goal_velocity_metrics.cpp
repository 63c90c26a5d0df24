// The velocity metrics of a walk to a goal (datasets/METRICS.md): measured against the path
// follower's command of each NMPC iteration (stored as mpc/command), not against zero. A goal
// straight ahead, walked at the follower's cruise speed, tracks its command about as well as a
// velocity-command walk at that speed does; and `wpg analyze` of the stored walk (the engine's
// reader of stored runs) gives the run-time numbers bit for bit.
#include <cmath>
#include <string>
#include <vector>

#include <H5Cpp.h>
#include <gtest/gtest.h>

#include "../datasets/hdf5_read.hpp"
#include "../datasets/test_support.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/engine/scenario_run.hpp"
#include "wpg/engine/stored_runs.hpp"

using wpg::datasets::Scenario;
using wpg::engine::RunResult;

namespace {

// The walking settings of the shipped goal scenarios (goal_with_yaw.yaml).
const std::string kWalking =
    "robot: hrp2\n"
    "generator: {algorithm: nmpc, sqp_iterations: 1}\n"
    "walking: {velocity_tracking: with_sway, heading_reference: command, "
    "max_step_yaw_change: 0.17}\n";

// 4 m straight ahead, no obstacle, no planner: the follower cruises at 0.75 x 0.4 = 0.3 m/s,
// then slows within 1 m of the goal.
Scenario goalAhead() {
  return wpg::datasets::loadScenarioText(
      "name: goal_ahead\nduration: 40.0\n" + kWalking +
          "goal: {position: [4.0, 0.0], tolerance: 0.15}\nplanner: {algorithm: none}\n",
      "goal_ahead.yaml", {}, wpg_test::kRobotsDir);
}

// The same walk commanded at the cruise speed for 12 s.
Scenario commandedAhead() {
  return wpg::datasets::loadScenarioText(
      "name: commanded_ahead\nduration: 12.0\n" + kWalking +
          "reference: [{t: 0.0, v: [0.3, 0.0, 0.0]}]\n",
      "commanded_ahead.yaml", {}, wpg_test::kRobotsDir);
}

class GoalVelocityMetrics : public wpg_test::ScratchDirectoryTest {
 protected:
  GoalVelocityMetrics() : ScratchDirectoryTest("wpg_test_goal_velocity_metrics") {}
  std::string path(const std::string& name) const { return (directory_ / name).string(); }
};

}  // namespace

TEST_F(GoalVelocityMetrics, AGoalWalkIsMeasuredAgainstItsCommand) {
  const Scenario goal = goalAhead();
  const RunResult walked = wpg::engine::runScenario(goal, {wpg_test::kRobotsDir, nullptr});
  ASSERT_TRUE(walked.walk.goal && walked.walk.goal->goal_reached) << walked.failure;
  const RunResult commanded =
      wpg::engine::runScenario(commandedAhead(), {wpg_test::kRobotsDir, nullptr});

  // The walk's mean speed: what an error measured against zero comes to.
  const double mean_speed = walked.metrics.path_length / walked.metrics.duration;
  EXPECT_GT(mean_speed, 0.15);
  const double goal_error = walked.metrics.velocity_error_rms;
  const double commanded_error = commanded.metrics.velocity_error_rms;
  ASSERT_TRUE(std::isfinite(goal_error));
  ASSERT_TRUE(std::isfinite(commanded_error));
  // Small against the speed, and comparable to the commanded walk at the same speed (the goal
  // walk's command also ramps down and stops: a little more lag to track).
  EXPECT_LT(goal_error, 0.25 * mean_speed) << "mean speed " << mean_speed;
  EXPECT_LT(goal_error, 2.0 * commanded_error + 0.01) << "commanded walk " << commanded_error;
  EXPECT_LE(walked.metrics.velocity_error_max, 0.3);
  // Steady-state tracking applies to a constant command only (a goal walk's is not).
  EXPECT_TRUE(std::isnan(walked.metrics.steady_tracking));

  // Stored: the follower's command per NMPC iteration, and the same metrics read back.
  wpg::engine::writeRunDataset(path("goal.h5"), goal, walked);
  {
    const H5::H5File file(path("goal.h5"), H5F_ACC_RDONLY);
    const H5::Group mpc = file.openGroup("/runs/goal_ahead/mpc");
    const std::vector<double> command = wpg_test::readDoubles(mpc, "command");
    const std::vector<wpg::MpcIterationLog>& log = walked.walk.result.trajectory.mpc;
    ASSERT_EQ(command.size(), 3 * log.size());
    double cruise = 0.0;
    for (std::size_t k = 0; k < log.size(); ++k) {
      EXPECT_EQ(command[3 * k], log[k].command.x());
      EXPECT_EQ(command[3 * k + 1], log[k].command.y());
      EXPECT_EQ(command[3 * k + 2], log[k].command.z());
      cruise = std::max(cruise, command[3 * k]);
    }
    EXPECT_NEAR(cruise, 0.3, 0.01);  // 0.75 x max_forward_velocity (and a lateral correction)
    EXPECT_EQ(command[3 * (log.size() - 1)], 0.0);  // stopped at the goal
  }
  const wpg::engine::StoredRunAnalysis stored =
      wpg::engine::analyzeStoredRun(path("goal.h5"), "goal_ahead", wpg_test::kRobotsDir);
  EXPECT_EQ(stored.metrics.velocity_error_rms, walked.metrics.velocity_error_rms);
  EXPECT_EQ(stored.metrics.velocity_error_max, walked.metrics.velocity_error_max);
}
