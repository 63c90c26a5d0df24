// One scenario run by the engine to a result object (wpg/engine/scenario_run.hpp), then written:
// the result's checks, footstep clearances, chain timing and metrics are what the dataset holds
// (read back with the plain HDF5 API and with the engine's own reader of stored runs); a failed
// walk is a result with its outcome, not an exception; input that cannot run is an InputError.
#include <cmath>
#include <string>
#include <vector>

#include <H5Cpp.h>
#include <gtest/gtest.h>

#include "../datasets/hdf5_read.hpp"
#include "../datasets/test_support.hpp"
#include "wpg/analysis/sample_statistics.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/engine/scenario_run.hpp"
#include "wpg/engine/stored_runs.hpp"

using wpg::datasets::Scenario;
using wpg::engine::RunOutcome;
using wpg::engine::RunResult;

namespace {

Scenario shipped(const std::string& name, const std::vector<std::string>& overrides) {
  return wpg::datasets::loadScenario(wpg_test::kScenariosDir + "/" + name + ".yaml", overrides,
                                     wpg_test::kRobotsDir);
}

// NaN equals NaN: a metric that does not apply is NaN on both sides.
void expectSame(double expected, double actual, const char* what) {
  if (std::isnan(expected)) {
    EXPECT_TRUE(std::isnan(actual)) << what;
  } else {
    EXPECT_EQ(expected, actual) << what;
  }
}

class ScenarioRun : public wpg_test::ScratchDirectoryTest {
 protected:
  ScenarioRun() : ScratchDirectoryTest("wpg_test_scenario_run") {}
  std::string path(const std::string& name) const { return (directory_ / name).string(); }
};

}  // namespace

TEST_F(ScenarioRun, TheResultIsWhatTheDatasetHolds) {
  // Obstacles (the FCL footstep check and the step centres) and the replay with the offline
  // filter (the chain timing).
  const Scenario scenario =
      shipped("obstacle_boxes", {"duration=6", "filter=true", "filter_settings.mode=offline"});
  const RunResult result = wpg::engine::runScenario(scenario, {wpg_test::kRobotsDir, nullptr});
  ASSERT_EQ(result.outcome, RunOutcome::kSucceeded) << result.failure;
  EXPECT_EQ(result.exitStatus(), 0);
  EXPECT_TRUE(result.failure.empty());
  ASSERT_TRUE(result.replay.has_value());
  ASSERT_TRUE(result.footsteps.has_value());
  ASSERT_TRUE(result.checks.has_obstacles);

  wpg::engine::writeRunDataset(path("run.h5"), scenario, result);
  using namespace wpg_test;
  const H5::H5File file(path("run.h5"), H5F_ACC_RDONLY);
  const H5::Group run = file.openGroup("/runs/" + scenario.name);
  EXPECT_EQ(intAttribute(run, "success"), 1);

  const H5::Group checks = run.openGroup("checks");
  const wpg::WalkCheckReport& walk = result.checks.walk;
  EXPECT_EQ(doubleAttribute(checks, "cop_sample_violation"), walk.cop_sample_violation);
  EXPECT_EQ(doubleAttribute(checks, "cop_control_violation"), walk.cop_control_violation);
  EXPECT_EQ(doubleAttribute(checks, "feasibility_violation"), walk.feasibility_violation);
  EXPECT_EQ(doubleAttribute(checks, "max_step_yaw_change"), walk.max_step_yaw_change);
  EXPECT_EQ(intAttribute(checks, "landed_steps"), walk.landed_steps);
  EXPECT_GT(walk.landed_steps, 3);
  EXPECT_EQ(readDoubles(checks, "step_centre_clearance"),
            result.checks.footsteps.step_centre_clearance);
  EXPECT_EQ(doubleAttribute(checks, "min_step_centre_clearance"),
            result.checks.footsteps.min_step_centre_clearance);
  EXPECT_EQ(readDoubles(checks, "step_clearance"), result.footsteps->clearances.clearance);
  EXPECT_EQ(doubleAttribute(checks, "min_step_clearance"), result.footsteps->least.sole);
  // The NMPC's obstacle constraint holds on every landed step centre.
  EXPECT_GE(result.footsteps->least.step_centre, -1e-9);

  // The chain timing's summary is analysis/'s statistics of the replay's chain times.
  const wpg::analysis::SampleStatistics chain =
      wpg::analysis::describeSample(result.replay->validation.chain_time);
  ASSERT_GT(chain.count, 10u);
  const H5::Group timing = run.openGroup("timing");
  EXPECT_EQ(doubleAttribute(timing, "chain_time_average"), chain.mean);
  EXPECT_EQ(doubleAttribute(timing, "chain_time_std"), chain.std_dev);
  EXPECT_EQ(doubleAttribute(timing, "chain_time_min"), chain.min);
  EXPECT_EQ(doubleAttribute(timing, "chain_time_max"), chain.max);
  EXPECT_EQ(doubleAttribute(run.openGroup("multibody"), "zmp_error_rms_after"),
            result.replay->validation.after.rms);

  // The metrics recomputed from the stored walk (`wpg analyze`) are the result's.
  const std::vector<wpg::engine::StoredRunMetrics> stored =
      wpg::engine::analyzeRunFile(path("run.h5"), wpg_test::kRobotsDir);
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].name, scenario.name);
  for (const wpg::analysis::MetricDefinition& metric : wpg::analysis::runMetricTable()) {
    expectSame(result.metrics.*metric.field, stored[0].metrics.*metric.field, metric.name);
  }
  EXPECT_EQ(result.metrics.steps, static_cast<double>(walk.landed_steps));
}

TEST_F(ScenarioRun, AFailedWalkIsAResultWithItsOutcome) {
  // A QP capped at one active-set iteration: the walk is generated, some iteration fails.
  const Scenario scenario = shipped("walk_forward", {"duration=2", "generator.max_qp_iterations=1"});
  const RunResult result = wpg::engine::runScenario(scenario, {wpg_test::kRobotsDir, nullptr});
  EXPECT_EQ(result.outcome, RunOutcome::kWalkFailed);
  EXPECT_EQ(result.exitStatus(), 1);
  EXPECT_FALSE(result.walk.result.success);
  EXPECT_NE(result.failure.find("iteration_limit"), std::string::npos) << result.failure;
  EXPECT_EQ(result.metrics.success, 0.0);
  EXPECT_GT(result.metrics.failed_iterations, 0.0);
  EXPECT_GT(result.walk.result.trajectory.size(), 300u);  // the walk itself is there
  wpg::engine::writeRunDataset(path("failed.h5"), scenario, result);
  const H5::H5File file(path("failed.h5"), H5F_ACC_RDONLY);
  EXPECT_EQ(wpg_test::intAttribute(file.openGroup("/runs/walk_forward"), "success"), 0);
}

// Stuck is an outcome: the wall with no way round is blocked (exit 1), its dataset says so,
// and the metrics read back are the result's; the whole walk's progress ratio the monitor
// summed during the walk is the metric analysis/ recomputes from the trajectory, bit for bit.
TEST_F(ScenarioRun, ABlockedWalkIsAResultWithItsOutcome) {
  const Scenario scenario = shipped("obstacle_wall", {});
  const RunResult result = wpg::engine::runScenario(scenario, {wpg_test::kRobotsDir, nullptr});
  EXPECT_EQ(result.outcome, RunOutcome::kBlocked);
  EXPECT_STREQ(wpg::engine::runOutcomeName(result.outcome), "blocked");
  EXPECT_EQ(result.exitStatus(), 1);
  EXPECT_EQ(result.failure, result.walk.result.message);
  EXPECT_EQ(result.metrics.blocked, 1.0);
  EXPECT_EQ(result.metrics.blocked_since, result.walk.result.blocked_since);
  EXPECT_EQ(result.metrics.progress_ratio, result.walk.result.progress_ratio);
  wpg::engine::writeRunDataset(path("wall.h5"), scenario, result);
  const H5::H5File file(path("wall.h5"), H5F_ACC_RDONLY);
  const H5::Group run = file.openGroup("/runs/obstacle_wall");
  EXPECT_EQ(wpg_test::intAttribute(run, "blocked"), 1);
  EXPECT_EQ(wpg_test::intAttribute(run, "success"), 0);
  const std::vector<wpg::engine::StoredRunMetrics> stored =
      wpg::engine::analyzeRunFile(path("wall.h5"), wpg_test::kRobotsDir);
  ASSERT_EQ(stored.size(), 1u);
  for (const wpg::analysis::MetricDefinition& metric : wpg::analysis::runMetricTable()) {
    expectSame(result.metrics.*metric.field, stored[0].metrics.*metric.field, metric.name);
  }
  // A walk that makes progress: not blocked, its ratio the metric's too.
  const RunResult walk =
      wpg::engine::runScenario(shipped("walk_forward", {}), {wpg_test::kRobotsDir, nullptr});
  EXPECT_EQ(walk.outcome, RunOutcome::kSucceeded);
  EXPECT_EQ(walk.metrics.blocked, 0.0);
  EXPECT_TRUE(std::isnan(walk.metrics.blocked_since));
  EXPECT_EQ(walk.metrics.progress_ratio, walk.walk.result.progress_ratio);
}

TEST_F(ScenarioRun, TheSameScenarioGivesTheSameWalk) {
  // 5 s: the velocity error's first window, one gait cycle after the start at 1 s, ends at 4.2 s.
  const Scenario scenario = shipped("walk_forward", {"duration=5"});
  const RunResult a = wpg::engine::runScenario(scenario, {wpg_test::kRobotsDir, nullptr});
  const RunResult b = wpg::engine::runScenario(scenario, {wpg_test::kRobotsDir, nullptr});
  EXPECT_EQ(a.walk.result.trajectory.com, b.walk.result.trajectory.com);
  EXPECT_EQ(a.walk.result.trajectory.cop, b.walk.result.trajectory.cop);
  EXPECT_TRUE(std::isfinite(a.metrics.velocity_error_rms));
  EXPECT_EQ(a.metrics.velocity_error_rms, b.metrics.velocity_error_rms);
  EXPECT_FALSE(a.replay.has_value());  // the scenario does not replay
  EXPECT_FALSE(a.footsteps.has_value());  // nor has obstacles
}

