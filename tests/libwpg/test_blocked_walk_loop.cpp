// The walk loop's blocked verdict (walk_loop.hpp, wpg/progress_monitor.hpp): a walk that ends
// while its robot is stuck in front of a wall is blocked and failed, unless its command source
// reached what it commanded (a goal walk at its goal made its progress: CommandSource::
// reachedTarget); a walk that falls is judged by its fall.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include "../common/wall_walk.hpp"
#include "wpg/online_walking_generator.hpp"
#include "wpg/walk_loop.hpp"

namespace {

// The walk into the wall (wall_walk.hpp) ends at 20 s, the robot blocked since 8.9 s.
using wpg_test::wallWalkRequest;

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
  const wpg::WalkRequest request = wallWalkRequest();
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
  EXPECT_NEAR(stuck.blocked_since, 8.9, 1e-9);
  EXPECT_EQ(stuck.message, "the robot is blocked: " + stuck.blocked_description);
  EXPECT_NE(stuck.blocked_description.find("since t = 8.9 s"), std::string::npos);

  // The same walk, its command source at its target: no verdict, the walk succeeds.
  const wpg::WalkResult reached = walk(true);
  EXPECT_FALSE(reached.blocked);
  EXPECT_TRUE(reached.success) << reached.message;
  EXPECT_EQ(reached.progress_ratio, stuck.progress_ratio);  // the same walk
}

// A fall is the walk's outcome: a robot pushed over while stuck in front of the wall is not
// also blocked.
TEST(BlockedWalkLoop, AFallIsNotJudgedBlocked) {
  wpg::WalkRequest request = wallWalkRequest();
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
