// The online loop of the paper's Fig. 3 (robots/online_filter_loop.hpp) on HRP-2: it is causal
// (what it sends up to an instant does not depend on the walk after it, unlike the offline
// pass), it cuts the ZMP error, and it times every stage in the control period it runs in.
#include <gtest/gtest.h>

#include <cmath>

#include "wpg/robots/online_filter_loop.hpp"
#include "wpg/robots/walk_replay.hpp"
#include "wpg/walk_generator.hpp"
#include "../common/source_dir.hpp"

namespace {

const std::string kSource = wpg_test::sourceDir();

wpg::WalkRequest forwardThen(const Eigen::Vector3d& later, double change_time, double duration) {
  wpg::WalkRequest request;
  request.duration = duration;
  request.reference = {{0.0, Eigen::Vector3d::Zero()},
                       {1.0, Eigen::Vector3d(0.2, 0.0, 0.0)},
                       {change_time, later}};
  return request;
}

// Two walks that differ only after t_c (the command changes there): the online filter's output
// (the corrected CoM and the configuration sent to the robot) is the same up to t_c; the
// offline pass, which previews the walk's own future, changes before t_c.
TEST(OnlineFilterLoop, IsCausal) {
  const wpg::robots::RobotModel model(kSource + "/robots/hrp2/hrp2.urdf");
  wpg::WalkingParameters parameters;
  parameters.max_step_yaw_change = 0.17;
  const double change = 3.5;
  const wpg::WalkRequest a = forwardThen(Eigen::Vector3d(0.2, 0.0, 0.0), change, 5.0);
  const wpg::WalkRequest b = forwardThen(Eigen::Vector3d(0.05, 0.1, 0.2), change, 5.0);
  wpg::robots::OnlineFilterLoopSettings settings;
  settings.preview.preview_time = 0.8;
  const wpg::robots::OnlineFilterRun run_a = wpg::robots::runOnlineFilterLoop(model, parameters, a, settings);
  const wpg::robots::OnlineFilterRun run_b = wpg::robots::runOnlineFilterLoop(model, parameters, b, settings);
  ASSERT_TRUE(run_a.walk.success && run_b.walk.success);
  const std::vector<double>& time = run_a.walk.trajectory.time;
  double online_before = 0.0, online_after = 0.0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    const double d = (run_a.validation.com_filtered.row(row) - run_b.validation.com_filtered.row(row)).norm() +
                     (run_a.validation.q.row(row) - run_b.validation.q.row(row)).norm();
    (time[i] < change - 1e-9 ? online_before : online_after) =
        std::max(time[i] < change - 1e-9 ? online_before : online_after, d);
  }
  EXPECT_EQ(online_before, 0.0);
  EXPECT_GT(online_after, 1e-3);  // the walks do differ after t_c

  // The offline pass on the same two walks: its correction before t_c sees the change.
  wpg::robots::WalkReplaySettings offline;
  offline.preview.preview_time = 0.8;
  const wpg::MultibodyValidation off_a = wpg::robots::replayWalk(model, parameters, a, run_a.walk.trajectory, offline);
  const wpg::MultibodyValidation off_b = wpg::robots::replayWalk(model, parameters, b, run_b.walk.trajectory, offline);
  double offline_before = 0.0;
  for (std::size_t i = 0; i < time.size() && time[i] < change - 1e-9; ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    offline_before = std::max(offline_before, (off_a.com_filtered.row(row) - off_b.com_filtered.row(row)).norm());
  }
  EXPECT_GT(offline_before, 1e-6);
}

TEST(OnlineFilterLoop, CutsTheZmpErrorAndTimesEveryTick) {
  const wpg::robots::RobotModel model(kSource + "/robots/hrp2/hrp2.urdf");
  const wpg::WalkingParameters parameters;
  const wpg::WalkRequest request = forwardThen(Eigen::Vector3d(0.2, 0.0, 0.0), 2.0, 6.0);
  const wpg::robots::OnlineFilterRun run =
      wpg::robots::runOnlineFilterLoop(model, parameters, request, {});
  ASSERT_TRUE(run.walk.success) << run.walk.message;
  const wpg::MultibodyValidation& v = run.validation;
  const Eigen::Index n = static_cast<Eigen::Index>(run.walk.trajectory.size());
  ASSERT_EQ(v.q.rows(), n);
  ASSERT_EQ(v.com_filtered.rows(), n);
  ASSERT_EQ(v.zmp_multibody_filtered.rows(), n);
  EXPECT_EQ(v.ik_failures, 0);
  EXPECT_EQ(v.filter_mode, "online");
  EXPECT_FALSE(v.wpg_reinitialized);
  EXPECT_GT(v.before.rms, 3.0 * v.after.rms) << v.before.rms << " -> " << v.after.rms;
  // The error the loop previewed is the one of the walk as it went (same WPG motion).
  const wpg::MultibodyValidation offline =
      wpg::robots::replayWalk(model, parameters, request, run.walk.trajectory);
  EXPECT_NEAR(v.before.rms, offline.before.rms, 0.02 * offline.before.rms);

  // One timing row per control period (not the closing sample); the NMPC ticks are those of
  // the NMPC iterations, and the inverse dynamics of the filter's window runs in them only.
  ASSERT_EQ(v.tick_stage_time.rows(), n - 1);
  ASSERT_EQ(v.tick_nmpc.size(), static_cast<std::size_t>(n - 1));
  EXPECT_TRUE(v.tick_stages_measured);
  std::size_t nmpc_ticks = 0;
  for (Eigen::Index i = 0; i < n - 1; ++i) {
    const bool nmpc = v.tick_nmpc[static_cast<std::size_t>(i)] != 0;
    nmpc_ticks += nmpc;
    EXPECT_EQ(nmpc, i % 20 == 0) << i;
    EXPECT_GT(v.tick_stage_time(i, 0), 0.0);  // the generator's step
    EXPECT_GT(v.tick_stage_time(i, 1), 0.0);  // the IK of the corrected CoM
    EXPECT_GT(v.tick_stage_time(i, 3), 0.0);  // the filter step
    if (nmpc) {
      EXPECT_GT(v.tick_stage_time(i, 2), 0.0);
    } else {
      EXPECT_EQ(v.tick_stage_time(i, 2), 0.0);
    }
  }
  EXPECT_EQ(nmpc_ticks, run.walk.trajectory.mpc.size());
  EXPECT_NEAR(v.chain_time.sum(), v.tick_stage_time.sum(), 1e-12);
}

}  // namespace
