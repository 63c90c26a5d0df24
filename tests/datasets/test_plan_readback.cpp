// A run's mpc/plan/ (datasets/SCHEMA.md) read back by readRunDataset equals what the walk
// recorded, number for number (a replayed or reloaded run keeps its plan); and a scenario with
// `constraints:` resolves to a text that loads the same extensions again.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"
#include "wpg/walk_generator.hpp"
#include "../common/source_dir.hpp"

namespace {

const std::string kSource = wpg_test::sourceDir();

wpg::datasets::Scenario corridor() {
  return wpg::datasets::loadScenario(kSource + "/datasets/scenarios/corridor.yaml",
                                     {"duration=4"}, kSource + "/robots");
}

TEST(PlanReadback, ReadRunDatasetReturnsTheRecordedPlan) {
  const wpg::datasets::Scenario scenario = corridor();
  const wpg::WalkResult result = wpg::generateWalk(scenario.walking, scenario.request);
  const wpg::PlanLog& written = result.trajectory.plans;
  ASSERT_EQ(written.size(), result.trajectory.mpc.size());
  ASSERT_GT(written.size(), 30u);
  const std::string path =
      (std::filesystem::temp_directory_path() / ("wpg_plan_readback_" +
                                                 std::to_string(::getpid()) + ".h5")).string();
  wpg::datasets::writeRunDataset(path, scenario, result);
  const wpg::datasets::StoredRun stored = wpg::datasets::readRunDataset(path);
  std::filesystem::remove(path);
  const wpg::PlanLog& read = stored.result.trajectory.plans;
  EXPECT_EQ(read.max_samples, written.max_samples);
  EXPECT_EQ(read.steps, written.steps);
  EXPECT_EQ(read.families, written.families);
  EXPECT_EQ(read.sampling_period, written.sampling_period);
  EXPECT_EQ(read.samples, written.samples);
  EXPECT_EQ(read.com_position, written.com_position);
  EXPECT_EQ(read.com_velocity, written.com_velocity);
  EXPECT_EQ(read.com_acceleration, written.com_acceleration);
  EXPECT_EQ(read.jerk, written.jerk);
  EXPECT_EQ(read.cop, written.cop);
  EXPECT_EQ(read.step, written.step);
  EXPECT_EQ(read.step_side, written.step_side);
  EXPECT_EQ(read.active_rows, written.active_rows);
  // The corridor is a family of the run: its column is there, and its rows were active.
  ASSERT_EQ(stored.result.trajectory.constraint_families.back().name, "corridor");
}

TEST(PlanReadback, ResolvedScenarioKeepsItsExtensions) {
  const wpg::datasets::Scenario scenario = corridor();
  ASSERT_EQ(scenario.request.generator.constraints.size(), 1u);
  const wpg::datasets::Scenario again = wpg::datasets::loadScenarioText(
      resolvedScenarioText(scenario), "resolved", {}, kSource + "/robots");
  ASSERT_EQ(again.request.generator.constraints.size(), 1u);
  EXPECT_EQ(again.request.generator.constraints[0].name, "corridor");
  EXPECT_EQ(again.request.generator.constraints[0].arguments,
            scenario.request.generator.constraints[0].arguments);
  EXPECT_EQ(resolvedScenarioText(again), resolvedScenarioText(scenario));
}

}  // namespace
