// A study and a comparison study run by the engine's thread executor
// (wpg/engine/study_executor.hpp, comparison_run.hpp): every run of the study's expansion
// (grid x random, worlds x variants x seeds) lands in the file under its name, the reports
// reach the caller in study order, the files are the same for any number of threads, a resume
// runs nothing twice, a shard slice holds its runs only, and a comparison's slices merged give
// the comparison of one run.
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../datasets/test_support.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/storage/dataset_diff.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"
#include "wpg/datasets/study_design/comparison_study.hpp"
#include "wpg/datasets/study_design/study.hpp"
#include "wpg/engine/comparison_run.hpp"
#include "wpg/engine/study_executor.hpp"
#include "wpg/engine/study_summary.hpp"

namespace fs = std::filesystem;
using wpg::engine::StudyOutput;
using wpg::engine::StudyRunHandling;

namespace {

// 2 x 2 grid points x 2 random samples: 8 walks of a few steps.
const char* const kStudy =
    "name: tiny\n"
    "base: walk_forward\n"
    "sweep:\n"
    "  grid:\n"
    "    duration: [3.0, 3.5]\n"
    "    walking.weight_cop: [300.0, 3000.0]\n"
    "  random:\n"
    "    samples: 2\n"
    "    seed: 5\n"
    "    keys: {walking.com_height: {uniform: [0.78, 0.84]}}\n";

// What the executor told its observer.
class CountingObserver : public wpg::engine::StudyObserver {
 public:
  void resuming(std::size_t done, std::size_t total, const std::string&) override {
    already = done;
    resumed_total = total;
  }
  void started(std::size_t runs_to_do) override { to_do = runs_to_do; }
  void runFinished(bool failed) override {
    ++finished_runs;
    failures += failed;
  }
  std::size_t already = 0, resumed_total = 0, to_do = 0, finished_runs = 0, failures = 0;
};

std::string resolveShipped(const std::string& base) {
  return wpg_test::kScenariosDir + "/" + base + ".yaml";
}

class StudyExecution : public wpg_test::ScratchDirectoryTest {
 protected:
  StudyExecution() : ScratchDirectoryTest("wpg_test_study_execution") {}
  std::string path(const std::string& name) const { return (directory_ / name).string(); }

  // One world (goal_with_yaw, 4 s) x two variants (no planner, rrtconnect) x 2 seeds.
  wpg::datasets::ComparisonStudy loadTinyComparison() {
    std::ofstream(path("compare.yaml"))
        << "name: tiny_compare\n"
           "seeds: 2\n"
           "set: {duration: 4.0}\n"
           "worlds:\n"
           "  - {name: yaw, scenario: goal_with_yaw}\n"
           "variants:\n"
           "  straight: {planner.algorithm: none}\n"
           "  rrt: {planner.algorithm: rrtconnect}\n";
    return wpg::datasets::loadComparisonStudy(path("compare.yaml"), resolveShipped,
                                              wpg_test::kRobotsDir);
  }

  wpg::datasets::Study loadStudy(const char* text) {
    std::ofstream(path("study.yaml")) << text;
    return wpg::datasets::loadStudy(path("study.yaml"), resolveShipped, wpg_test::kRobotsDir);
  }

  // Runs `study` into `output` on `threads` threads; the reports, in the order they came:
  // [run index, exit status, landed steps].
  std::vector<std::vector<double>> run(const wpg::datasets::Study& study, const StudyOutput& output,
                                       int threads, CountingObserver& observer) {
    std::vector<std::vector<double>> reports;
    StudyRunHandling handling;
    handling.columns = wpg::engine::runSummaryColumns();
    handling.summary_values = [](const wpg::datasets::StudyRun&, const wpg::engine::RunResult& r) {
      return wpg::engine::runSummaryValues(r);
    };
    handling.report = [](const wpg::datasets::StudyRun& run, const wpg::engine::RunResult& r) {
      return std::vector<double>{static_cast<double>(run.index),
                                 static_cast<double>(r.exitStatus()), r.metrics.steps};
    };
    handling.collect = [&](std::size_t index, std::vector<double>&& report) {
      EXPECT_EQ(static_cast<double>(index), report[0]);
      reports.push_back(std::move(report));
    };
    EXPECT_TRUE(wpg::engine::makeThreadExecutor(threads, wpg_test::kRobotsDir)
                    ->run(study, output, handling, observer));
    return reports;
  }

  // The same fields, bit for bit, but the wall times (those `wpg diff` leaves out, and the
  // planners' times of a comparison's tables).
  static void expectSameFiles(const std::string& a, const std::string& b) {
    wpg::datasets::DiffSettings settings;
    settings.ignore_patterns = {"/batch/summary/planning_time_*", "/compare/summary/planning_time_*",
                                "/compare/summary/nmpc_time_*"};
    const wpg::datasets::DatasetDiff diff = wpg::datasets::diffDatasets(a, b, settings);
    EXPECT_TRUE(diff.differences.empty()) << diff.differences.front().path;
    EXPECT_EQ(diff.max_absolute_within, 0.0) << diff.max_relative_within_path;
  }
};

}  // namespace

TEST_F(StudyExecution, EveryRunOfTheExpansionIsWrittenUnderItsNameInStudyOrder) {
  const wpg::datasets::Study study = loadStudy(kStudy);
  ASSERT_EQ(study.runs.size(), 8u);
  CountingObserver one, three;
  const auto serial = run(study, {path("one.h5"), false, std::nullopt}, 1, one);
  const auto parallel = run(study, {path("three.h5"), false, std::nullopt}, 3, three);
  ASSERT_EQ(serial.size(), study.runs.size());
  for (std::size_t i = 0; i < serial.size(); ++i) {
    EXPECT_EQ(serial[i][0], static_cast<double>(i));  // study order
    EXPECT_EQ(serial[i][1], 0.0);
    EXPECT_GT(serial[i][2], 0.0);
  }
  EXPECT_EQ(parallel, serial);
  EXPECT_EQ(one.to_do, 8u);
  EXPECT_EQ(one.finished_runs, 8u);
  EXPECT_EQ(one.failures, 0u);

  std::vector<std::string> names;
  for (const wpg::datasets::StudyRun& r : study.runs) names.push_back(r.name);
  EXPECT_EQ(names.front(), "tiny_0");
  EXPECT_EQ(wpg::datasets::listRuns(path("one.h5")), names);
  const wpg::datasets::BatchSummaryTable table = wpg::datasets::readBatchSummary(path("one.h5"));
  EXPECT_EQ(table.rows, 8u);
  // Bit for bit the same batch file (wall times aside) for 1 and 3 threads.
  expectSameFiles(path("one.h5"), path("three.h5"));
}

TEST_F(StudyExecution, AResumeRunsOnlyWhatIsMissingAndAShardOnlyItsSlice) {
  const wpg::datasets::Study study = loadStudy(kStudy);
  CountingObserver first;
  run(study, {path("batch.h5"), false, std::nullopt}, 2, first);
  CountingObserver again;
  const auto reports = run(study, {path("batch.h5"), true, std::nullopt}, 2, again);
  EXPECT_TRUE(reports.empty());
  EXPECT_EQ(again.already, 8u);
  EXPECT_EQ(again.resumed_total, 8u);
  EXPECT_EQ(again.to_do, 0u);

  CountingObserver slice;
  const auto sliced =
      run(study, {path("shard.h5"), false, wpg::engine::ShardSlice{1, 3}}, 2, slice);
  ASSERT_EQ(sliced.size(), 3u);  // runs 1, 4, 7
  EXPECT_EQ(sliced[0][0], 1.0);
  EXPECT_EQ(sliced[1][0], 4.0);
  EXPECT_EQ(sliced[2][0], 7.0);
  EXPECT_EQ(wpg::datasets::listRuns(path("shard.h5")),
            (std::vector<std::string>{study.runs[1].name, study.runs[4].name, study.runs[7].name}));
  // Another slice cannot resume it: nothing is run, the file is left as it is.
  CountingObserver refused;
  wpg_test::expectInputError(
      [&] { run(study, {path("shard.h5"), true, wpg::engine::ShardSlice{0, 3}}, 1, refused); },
      path("shard.h5"), {"cannot resume", "shard 1/3"});
  EXPECT_EQ(refused.finished_runs, 0u);
}

TEST_F(StudyExecution, AComparisonHasACellPerWorldAndVariantFromItsSeeds) {
  const wpg::datasets::ComparisonStudy comparison = loadTinyComparison();
  ASSERT_EQ(comparison.study.runs.size(), 4u);  // 1 world x 2 variants x 2 seeds
  std::vector<std::vector<wpg::analysis::ComparisonCell>> tables;
  for (const int threads : {1, 2}) {
    CountingObserver observer;
    const std::string file = path("study" + std::to_string(threads) + ".h5");
    const auto executor = wpg::engine::makeThreadExecutor(threads, wpg_test::kRobotsDir);
    const wpg::engine::ComparisonOutcome outcome =
        wpg::engine::runComparison(comparison, file, *executor, observer);
    ASSERT_TRUE(outcome.complete);
    EXPECT_EQ(observer.finished_runs, 4u);
    tables.push_back(outcome.cells);
  }
  ASSERT_EQ(tables[0].size(), 2u);
  EXPECT_EQ(tables[0][0].world, "yaw");
  EXPECT_EQ(tables[0][0].variant, "straight");
  EXPECT_EQ(tables[0][1].variant, "rrt");
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(tables[0][c].runs, 2.0);
    // The cells' numbers, wall times aside, do not depend on the threads.
    for (const wpg::analysis::ComparisonColumn& column : wpg::analysis::comparisonColumns()) {
      if (column.wall_time) continue;
      const double a = tables[0][c].*column.field, b = tables[1][c].*column.field;
      EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << column.name;
    }
  }
  expectSameFiles(path("study1.h5"), path("study2.h5"));
}

TEST_F(StudyExecution, AComparisonInSlicesMergedOrResumedIsTheComparisonOfOneRun) {
  const wpg::datasets::ComparisonStudy comparison = loadTinyComparison();
  const auto executor = wpg::engine::makeThreadExecutor(2, wpg_test::kRobotsDir);
  CountingObserver whole_observer;
  const wpg::engine::ComparisonOutcome whole =
      wpg::engine::runComparison(comparison, path("whole.h5"), *executor, whole_observer);
  ASSERT_TRUE(whole.complete);

  // Slices 0/3 (runs 0, 3), 1/3 (run 1), 2/3 (run 2): shard files without a table.
  std::vector<std::string> shards;
  for (int k = 0; k < 3; ++k) {
    CountingObserver observer;
    StudyOutput output;
    output.path = path("slice" + std::to_string(k) + ".h5");
    output.shard = wpg::engine::ShardSlice{k, 3};
    const wpg::engine::ComparisonOutcome slice =
        wpg::engine::runComparison(comparison, output, *executor, observer);
    EXPECT_FALSE(slice.complete);
    EXPECT_EQ(observer.finished_runs, k == 0 ? 2u : 1u);
    shards.push_back(output.path);
  }
  // A slice alone is not the whole comparison: its table is refused.
  EXPECT_THROW(wpg::engine::writeComparisonSummary(shards[0],
                                                   wpg::engine::comparisonLayout(comparison)),
               wpg::datasets::InputError);
  const wpg::engine::ComparisonLayout layout = wpg::engine::readComparisonLayout(shards[1]);
  EXPECT_EQ(layout.worlds, comparison.worlds);
  EXPECT_EQ(layout.variants, comparison.variants);
  EXPECT_EQ(layout.seeds, comparison.seeds);
  EXPECT_EQ(layout.runs, 4u);
  std::vector<wpg::analysis::ComparisonCell> merged;
  wpg::datasets::writeBatchIndex(path("merged.h5"), shards, wpg::datasets::IndexLayout::kLinks,
                                 [&](const std::string& index) {
                                   merged = wpg::engine::writeComparisonSummary(index, layout);
                                 });
  ASSERT_EQ(merged.size(), whole.cells.size());
  for (std::size_t c = 0; c < merged.size(); ++c) {
    EXPECT_EQ(merged[c].world, whole.cells[c].world);
    EXPECT_EQ(merged[c].variant, whole.cells[c].variant);
    for (const wpg::analysis::ComparisonColumn& column : wpg::analysis::comparisonColumns()) {
      if (column.wall_time) continue;
      const double a = whole.cells[c].*column.field, b = merged[c].*column.field;
      EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << column.name;
    }
  }
  expectSameFiles(path("whole.h5"), path("merged.h5"));

  // Resumed when complete: nothing run, the table made again from the file, the same.
  CountingObserver resumed_observer;
  StudyOutput again;
  again.path = path("whole.h5");
  again.resume = true;
  const wpg::engine::ComparisonOutcome resumed =
      wpg::engine::runComparison(comparison, again, *executor, resumed_observer);
  ASSERT_TRUE(resumed.complete);
  EXPECT_EQ(resumed_observer.to_do, 0u);
  EXPECT_EQ(resumed_observer.already, 4u);
  ASSERT_EQ(resumed.cells.size(), whole.cells.size());
  for (std::size_t c = 0; c < resumed.cells.size(); ++c) {
    for (const wpg::analysis::ComparisonColumn& column : wpg::analysis::comparisonColumns()) {
      const double a = whole.cells[c].*column.field, b = resumed.cells[c].*column.field;
      EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << column.name;  // wall times too
    }
  }
  expectSameFiles(path("whole.h5"), path("merged.h5"));
}
