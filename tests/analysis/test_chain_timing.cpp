// The Sec. V-C chain timing and the real-time factor from hand-made replay timings.
#include <cmath>

#include <gtest/gtest.h>

#include "wpg/analysis/chain_timing.hpp"

using wpg::MultibodyValidation;
using wpg::analysis::ChainStage;
using wpg::analysis::chainTiming;
using wpg::analysis::ChainTiming;
using wpg::analysis::realTimeFactor;

TEST(ChainTiming, StatisticsPerIterationAndStageMedians) {
  MultibodyValidation v;
  v.chain_time.resize(4);
  v.chain_time << 1e-3, 2e-3, 3e-3, 4e-3;  // mean 2.5 ms; squared deviations sum 5 ms^2
  v.chain_stage_time.resize(4, 4);
  // columns: NMPC, IK, multibody ZMP, filter
  v.chain_stage_time << 4e-5, 1e-3, 7e-4, 1e-5,  //
      1e-5, 2e-3, 7e-4, 1e-5,                   //
      2e-5, 9e-3, 7e-4, 1e-5,                   //
      3e-5, 3e-3, 7e-4, 5e-5;
  const ChainTiming t = chainTiming(v);
  EXPECT_EQ(t.per_iteration.count, 4u);
  EXPECT_DOUBLE_EQ(t.per_iteration.mean, 2.5e-3);
  EXPECT_NEAR(t.per_iteration.std_dev, 1e-3 * std::sqrt(5.0 / 3.0), 1e-15);
  EXPECT_DOUBLE_EQ(t.per_iteration.min, 1e-3);
  EXPECT_DOUBLE_EQ(t.per_iteration.max, 4e-3);
  EXPECT_DOUBLE_EQ(t.stageMedian(ChainStage::kNmpc), 2.5e-5);
  EXPECT_DOUBLE_EQ(t.stageMedian(ChainStage::kIk), 2.5e-3);
  EXPECT_DOUBLE_EQ(t.stageMedian(ChainStage::kMultibodyZmp), 7e-4);
  EXPECT_DOUBLE_EQ(t.stageMedian(ChainStage::kFilter), 1e-5);
}

TEST(ChainTiming, OddIterationCount) {
  MultibodyValidation v;
  v.chain_time.resize(3);
  v.chain_time << 5e-3, 1e-3, 3e-3;  // mean 3 ms, sample variance (4 + 4) / 2 = 4 ms^2
  v.chain_stage_time = Eigen::MatrixXd::Zero(3, 4);
  v.chain_stage_time.col(1) << 3.0, 1.0, 2.0;
  const ChainTiming t = chainTiming(v);
  EXPECT_DOUBLE_EQ(t.per_iteration.mean, 3e-3);
  EXPECT_NEAR(t.per_iteration.std_dev, 2e-3, 1e-15);
  EXPECT_DOUBLE_EQ(t.stageMedian(ChainStage::kIk), 2.0);
  EXPECT_DOUBLE_EQ(t.stageMedian(ChainStage::kNmpc), 0.0);
}

TEST(ChainTiming, ReplayWithoutTimingGivesZeros) {
  const ChainTiming t = chainTiming(MultibodyValidation());
  EXPECT_EQ(t.per_iteration.count, 0u);
  EXPECT_EQ(t.per_iteration.mean, 0.0);
  for (const double median : t.stage_median) EXPECT_EQ(median, 0.0);
}

TEST(RealTimeFactor, WalkDurationOverWallTime) {
  EXPECT_DOUBLE_EQ(realTimeFactor(10.0, 0.25), 40.0);
  EXPECT_DOUBLE_EQ(realTimeFactor(3.0, 6.0), 0.5);  // slower than real time
  EXPECT_EQ(realTimeFactor(10.0, 0.0), 0.0);        // nothing measured
  EXPECT_EQ(realTimeFactor(10.0, -1.0), 0.0);
}

// The paper's unit: the ticks that contain an NMPC iteration, apart from the others.
TEST(TickTiming, NmpcTicksApartFromTheOthers) {
  MultibodyValidation v;
  v.tick_stage_time.resize(5, 4);
  // columns: WPG, IK, multibody ZMP, filter; ticks 0 and 3 ran the NMPC
  v.tick_stage_time << 1e-4, 1e-3, 3e-3, 1e-5,  // 4.11 ms
      1e-5, 1e-4, 0.0, 1e-5,                   // 0.12 ms
      1e-5, 1e-4, 0.0, 1e-5,                   // 0.12 ms
      3e-4, 1e-3, 2e-3, 1e-5,                  // 3.31 ms
      1e-5, 1e-4, 0.0, 1e-5;                   // 0.12 ms
  v.tick_nmpc = {1, 0, 0, 1, 0};
  v.tick_stages_measured = true;
  const wpg::analysis::TickTiming t = wpg::analysis::tickTiming(v);
  EXPECT_TRUE(t.measured);
  EXPECT_EQ(t.nmpc_ticks.count, 2u);
  EXPECT_NEAR(t.nmpc_ticks.mean, 3.71e-3, 1e-15);
  EXPECT_NEAR(t.nmpc_ticks.min, 3.31e-3, 1e-15);
  EXPECT_NEAR(t.nmpc_ticks.max, 4.11e-3, 1e-15);
  EXPECT_NEAR(t.nmpc_ticks.std_dev, 0.8e-3 / std::sqrt(2.0), 1e-15);
  EXPECT_EQ(t.all_ticks.count, 5u);
  EXPECT_NEAR(t.all_ticks.mean, (4.11e-3 + 3.31e-3 + 3 * 0.12e-3) / 5, 1e-15);
  EXPECT_NEAR(t.stage_nmpc_ticks[2].mean, 2.5e-3, 1e-15);
  EXPECT_NEAR(t.stage_all_ticks[2].mean, 1e-3, 1e-15);
  // inconsistent sizes: nothing
  v.tick_nmpc.pop_back();
  EXPECT_EQ(wpg::analysis::tickTiming(v).all_ticks.count, 0u);
}
