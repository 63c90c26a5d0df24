// The walk loop's blocked verdict (walk_loop.hpp, wpg/progress_monitor.hpp): a walk that ends
// while its robot is stuck in front of a wall is blocked and failed, unless its command source
// reached what it commanded (a goal walk at its goal made its progress: CommandSource::
// reachedTarget); a walk that falls is judged by its fall.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include "wpg/online_walking_generator.hpp"
#include "wpg/walk_loop.hpp"

namespace {

// Forward at 0.2 m/s from 1 s, into a wall 0.3 m x 6 m centred 2 m ahead (the shipped
// obstacle_wall); the walk ends at 20 s, the robot blocked since 2.6 s (it slides along the
// wall's border, sideways more than forward).
wpg::WalkRequest wallRequest() {
  wpg::WalkRequest request;
  request.duration = 30.0;
  request.reference = {{0.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d(0.2, 0.0, 0.0)}};
  wpg::Obstacle wall;
  wall.type = wpg::ObstacleType::kBox;
  wall.center = Eigen::Vector2d(2.0, 0.0);
  wall.size = Eigen::Vector2d(0.3, 6.0);
  wall.margin = 0.2;
  request.obstacles = {wall};
  request.validate();
  return request;
}

// The schedule until 20 s, then the end of the walk, saying whether its target was reached.
class EndingCommands final : public wpg::CommandSource {
 public:
  EndingCommands(const wpg::WalkRequest& request, bool reached)
      : request_(request), reached_(reached) {}
  bool nextCommand(int, double time, wpg::OnlineWalkingGenerator&,
                   Eigen::Vector3d& command) override {
    if (time > 20.0 - 1e-9) return false;
    command = request_.commandAt(time);
    return true;
  }
  bool reachedTarget() const override { return reached_; }

 private:
  const wpg::WalkRequest& request_;
  bool reached_;
};

wpg::WalkResult walk(bool reached) {
  const wpg::WalkRequest request = wallRequest();
  wpg::OnlineWalkingGenerator generator(wpg::WalkingParameters(), request.generator);
  generator.setObstacles(request.obstacles);
  EndingCommands commands(request, reached);
  return wpg::runWalkLoop(generator, request, commands);
}

TEST(BlockedWalkLoop, EndingStuckIsBlockedUnlessTheTargetWasReached) {
  const wpg::WalkResult stuck = walk(false);
  EXPECT_NEAR(stuck.trajectory.time.back(), 20.0, 1e-9);
  ASSERT_TRUE(stuck.blocked);
  EXPECT_FALSE(stuck.success);
  EXPECT_NEAR(stuck.blocked_since, 2.6, 1e-9);
  EXPECT_EQ(stuck.message, "the robot is blocked: " + stuck.blocked_description);
  EXPECT_NE(stuck.blocked_description.find("since t = 2.6 s"), std::string::npos);

  // The same walk, its command source at its target: no verdict, the walk succeeds.
  const wpg::WalkResult reached = walk(true);
  EXPECT_FALSE(reached.blocked);
  EXPECT_TRUE(reached.success) << reached.message;
  EXPECT_EQ(reached.progress_ratio, stuck.progress_ratio);  // the same walk
}

// A fall is the walk's outcome: a robot pushed over while stuck in front of the wall is not
// also blocked.
TEST(BlockedWalkLoop, AFallIsNotJudgedBlocked) {
  wpg::WalkRequest request = wallRequest();
  wpg::Push push;
  push.t = 18.0;
  push.force = Eigen::Vector2d(0.0, 600.0);
  push.duration = 0.3;
  request.pushes = {push};
  wpg::OnlineWalkingGenerator generator(wpg::WalkingParameters(), request.generator);
  generator.setObstacles(request.obstacles);
  wpg::ScheduledCommands commands(request);
  const wpg::WalkResult fallen = wpg::runWalkLoop(generator, request, commands);
  ASSERT_TRUE(generator.fallen());
  EXPECT_FALSE(fallen.success);
  EXPECT_FALSE(fallen.blocked);
  EXPECT_EQ(fallen.message.rfind("the robot fell at t = ", 0), 0u) << fallen.message;
}

}  // namespace
