// The dynamic filter on real replays (paper Sec. IV, Fig. 6): on the forward walk and the
// curve, IK reaches feet and CoM on every sample, and one filter pass cuts the distance between
// the reference CoP and the multibody ZMP at least 3x (RMS and max).
#include <gtest/gtest.h>

#include "wpg/robots/walk_replay.hpp"
#include "wpg/walk_generator.hpp"
#include "../common/source_dir.hpp"

namespace {

const std::string kSource = wpg_test::sourceDir();

struct Case {
  const char* name;
  Eigen::Vector3d command;
  double duration;
};

class FilteredWalk : public ::testing::TestWithParam<Case> {};

TEST_P(FilteredWalk, IkIsExactAndTheFilterCutsTheZmpError) {
  wpg::WalkingParameters parameters;
  parameters.max_step_yaw_change = 0.17;  // the curve turns at 0.2 rad/s
  wpg::WalkRequest request;
  request.duration = GetParam().duration;
  request.reference = {{0.0, Eigen::Vector3d::Zero()}, {1.0, GetParam().command}};
  const wpg::WalkResult walk = wpg::generateWalk(parameters, request);
  ASSERT_TRUE(walk.success) << walk.message;
  const wpg::robots::RobotModel model(kSource + "/robots/hrp2/hrp2.urdf");
  const wpg::MultibodyValidation v =
      wpg::robots::replayWalk(model, parameters, request, walk.trajectory);
  EXPECT_EQ(v.ik_failures, 0);
  EXPECT_LE(v.max_ik_com_error, 1e-8);
  EXPECT_LE(v.max_ik_foot_error, 1e-8);
  const Eigen::Index n = static_cast<Eigen::Index>(walk.trajectory.size());
  ASSERT_EQ(v.q.rows(), n);
  ASSERT_EQ(v.q.cols(), static_cast<Eigen::Index>(v.configuration_names.size()));
  ASSERT_EQ(v.zmp_multibody.rows(), n);
  ASSERT_EQ(v.zmp_multibody_filtered.rows(), n);
  ASSERT_EQ(v.com_filtered.rows(), n);
  EXPECT_TRUE(v.zmp_multibody.allFinite());
  EXPECT_TRUE(v.zmp_multibody_filtered.allFinite());
  EXPECT_GT(v.before.rms, 3.0 * v.after.rms) << v.before.rms << " -> " << v.after.rms;
  EXPECT_GT(v.before.max, 3.0 * v.after.max) << v.before.max << " -> " << v.after.max;
  RecordProperty("zmp_rms_before_after", std::to_string(v.before.rms) + " " + std::to_string(v.after.rms));
  RecordProperty("zmp_max_before_after", std::to_string(v.before.max) + " " + std::to_string(v.after.max));
  ASSERT_EQ(v.chain_time.size(), static_cast<Eigen::Index>(walk.trajectory.mpc.size()));
  EXPECT_GT(v.chain_time.minCoeff(), 0.0);
  // The filter's correction stays small: it corrects the template model, not the walk.
  double largest = 0.0;
  for (Eigen::Index i = 0; i < n; ++i)
    largest = std::max(largest, (v.com_filtered.row(i).head<2>().transpose() -
                                 walk.trajectory.com[i].head<2>()).norm());
  EXPECT_LT(largest, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Walks, FilteredWalk,
                         ::testing::Values(Case{"forward", {0.2, 0.0, 0.0}, 10.0},
                                           Case{"curve", {0.2, 0.0, 0.2}, 15.0}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(ReplayWithoutFilter, LeavesTheMotionAsGenerated) {
  wpg::WalkingParameters parameters;
  wpg::WalkRequest request;
  request.duration = 3.0;
  request.reference = {{0.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d(0.2, 0.0, 0.0)}};
  const wpg::WalkResult walk = wpg::generateWalk(parameters, request);
  const wpg::robots::RobotModel model(kSource + "/robots/hrp2/hrp2.urdf");
  wpg::robots::WalkReplaySettings settings;
  settings.filter = false;
  const wpg::MultibodyValidation v =
      wpg::robots::replayWalk(model, parameters, request, walk.trajectory, settings);
  EXPECT_EQ(v.com_filtered.rows(), 0);
  EXPECT_EQ(v.zmp_multibody_filtered.rows(), 0);
  EXPECT_DOUBLE_EQ(v.after.rms, v.before.rms);
  // Standing still before t = 1 s: the multibody ZMP is the CoM's projection (static pose).
  EXPECT_LT((v.zmp_multibody.row(50).transpose() - walk.trajectory.com[50].head<2>()).norm(), 1e-6);
}

}  // namespace
