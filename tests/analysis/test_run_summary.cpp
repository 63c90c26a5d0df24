// summarizeRun on a hand-made trajectory (distances, steps, duration, statuses, solve times
// computed by hand) and on a generated walk (properties that hold for any walk).
#include <gtest/gtest.h>

#include "wpg/analysis/run_summary.hpp"
#include "wpg/walk_generator.hpp"

using wpg::IterationStatus;
using wpg::MpcIterationLog;
using wpg::WalkTrajectory;
using wpg::analysis::RunSummary;
using wpg::analysis::summarizeRun;
using wpg::analysis::walkDuration;

namespace {

MpcIterationLog iteration(IterationStatus status, double solve_time) {
  MpcIterationLog log;
  log.status = status;
  log.solve_time = solve_time;
  return log;
}

}  // namespace

TEST(RunSummary, HandMadeTrajectory) {
  WalkTrajectory t;
  t.time = {0.5, 1.5, 2.5};
  // horizontal path (0,0) -> (3,4) -> (3,0): 5 + 4 m; net (0,0) -> (3,0): 3 m; z is ignored
  t.com = {Eigen::Vector3d(0, 0, 0.8), Eigen::Vector3d(3, 4, 0.7), Eigen::Vector3d(3, 0, 0.9)};
  t.footsteps.resize(5);  // the two initial feet + 3 steps
  t.mpc = {iteration(IterationStatus::kSolved, 4e-6),
           iteration(IterationStatus::kIterationLimit, 1e-6),
           iteration(IterationStatus::kSolved, 3e-6),
           iteration(IterationStatus::kRelaxedObstacle, 2e-6),
           iteration(IterationStatus::kSolved, 10e-6)};
  const RunSummary s = summarizeRun(t);
  EXPECT_DOUBLE_EQ(s.path_length, 9.0);
  EXPECT_DOUBLE_EQ(s.displacement, 3.0);
  EXPECT_EQ(s.steps, 3u);
  EXPECT_DOUBLE_EQ(s.duration, 2.0);
  EXPECT_EQ(s.nmpc_iterations, 5u);
  // by increasing status code: solved (0), relaxed_obstacle (1), iteration_limit (3)
  ASSERT_EQ(s.status_counts.size(), 3u);
  EXPECT_EQ(s.status_counts[0].status, IterationStatus::kSolved);
  EXPECT_EQ(s.status_counts[0].count, 3u);
  EXPECT_EQ(s.status_counts[1].status, IterationStatus::kRelaxedObstacle);
  EXPECT_EQ(s.status_counts[1].count, 1u);
  EXPECT_EQ(s.status_counts[2].status, IterationStatus::kIterationLimit);
  EXPECT_EQ(s.status_counts[2].count, 1u);
  EXPECT_DOUBLE_EQ(s.median_solve_time, 3e-6);
  EXPECT_DOUBLE_EQ(s.max_solve_time, 10e-6);
}

TEST(RunSummary, EvenIterationCountMedian) {
  WalkTrajectory t;
  t.mpc = {iteration(IterationStatus::kFallback, 8e-6), iteration(IterationStatus::kSolved, 2e-6)};
  const RunSummary s = summarizeRun(t);
  EXPECT_DOUBLE_EQ(s.median_solve_time, 5e-6);
  EXPECT_DOUBLE_EQ(s.max_solve_time, 8e-6);
  ASSERT_EQ(s.status_counts.size(), 2u);
  EXPECT_EQ(s.status_counts[0].status, IterationStatus::kSolved);
  EXPECT_EQ(s.status_counts[1].status, IterationStatus::kFallback);
}

TEST(RunSummary, OnlyInitialFeetAreNoSteps) {
  WalkTrajectory t;
  t.footsteps.resize(2);
  EXPECT_EQ(summarizeRun(t).steps, 0u);
  t.footsteps.resize(1);  // a truncated trajectory must not underflow
  EXPECT_EQ(summarizeRun(t).steps, 0u);
}

TEST(RunSummary, EmptyTrajectoryIsAllZero) {
  const RunSummary s = summarizeRun(WalkTrajectory());
  EXPECT_EQ(s.path_length, 0.0);
  EXPECT_EQ(s.displacement, 0.0);
  EXPECT_EQ(s.steps, 0u);
  EXPECT_EQ(s.duration, 0.0);
  EXPECT_EQ(s.nmpc_iterations, 0u);
  EXPECT_TRUE(s.status_counts.empty());
  EXPECT_EQ(s.median_solve_time, 0.0);
  EXPECT_EQ(s.max_solve_time, 0.0);
  EXPECT_EQ(walkDuration(WalkTrajectory()), 0.0);
}

TEST(RunSummary, GeneratedWalkForward) {
  wpg::WalkingParameters parameters;
  wpg::WalkRequest request;
  request.duration = 4.0;
  request.reference = {{0.0, Eigen::Vector3d(0.2, 0.0, 0.0)}};
  const wpg::WalkResult walk = wpg::generateWalk(parameters, request);
  ASSERT_TRUE(walk.success);
  const RunSummary s = summarizeRun(walk.trajectory);
  EXPECT_EQ(s.nmpc_iterations, walk.trajectory.mpc.size());
  std::size_t counted = 0;
  for (const auto& entry : s.status_counts) counted += entry.count;
  EXPECT_EQ(counted, s.nmpc_iterations);
  EXPECT_EQ(s.steps + 2, walk.trajectory.footsteps.size());
  EXPECT_GT(s.steps, 2u);
  EXPECT_GT(s.displacement, 0.4);                // 0.2 m/s for 4 s, minus the start
  EXPECT_GE(s.path_length, s.displacement);      // a path is never shorter than its chord
  EXPECT_NEAR(s.duration, request.duration, parameters.control_period + 1e-9);
  EXPECT_GT(s.median_solve_time, 0.0);
  EXPECT_LE(s.median_solve_time, s.max_solve_time);
}
