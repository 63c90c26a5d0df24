// The walk loop (runWalkLoop, walk_loop.hpp) that generateWalk and the walk to a goal run does
// not allocate: whole warmed-up NMPC iterations with their control periods, a push,
// obstacles, the fall check, the progress monitor while blocked, and the recording of the
// samples, logs and landed steps (the counter: allocation_counter.hpp).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstddef>

#include "../common/wall_walk.hpp"
#include "allocation_counter.hpp"
#include "wpg/online_walking_generator.hpp"
#include "wpg/walk_loop.hpp"

namespace {

using Eigen::Vector3d;
using wpg::WalkingParameters;
using wpg_test::Counts;
using wpg_test::counterAvailable;
using wpg_test::startCounting;
using wpg_test::stopCounting;

// The request's schedule (as ScheduledCommands); counts the allocations of the iterations
// [first_counted, end) and ends the walk at `end`, so that each counted iteration runs whole:
// its command, its control periods with push and fall check, and the recording.
class CountingCommands final : public wpg::CommandSource {
 public:
  CountingCommands(const wpg::WalkRequest& request, int first_counted, int end)
      : request_(request), first_counted_(first_counted), end_(end) {}
  bool nextCommand(int iteration, double time, wpg::OnlineWalkingGenerator&,
                   Vector3d& command) override {
    if (iteration == first_counted_) startCounting();
    if (iteration == end_) {
      counts = stopCounting();
      return false;
    }
    command = request_.commandAt(time);
    return true;
  }
  Counts counts;

 private:
  const wpg::WalkRequest& request_;
  int first_counted_, end_;
};

// A walk that calls an observer too (the hooks robots/ uses), without allocating itself.
class CountingObserver final : public wpg::ControlLoopObserver {
 public:
  void beforeStep(wpg::OnlineWalkingGenerator&) override { ++before; }
  void afterStep(wpg::OnlineWalkingGenerator&, const wpg::ControlSample&) override { ++after; }
  long before = 0, after = 0;
};

TEST(NmpcAllocation, WalkLoopIterations) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  wpg::WalkRequest request;
  request.duration = 20.0;
  request.reference = {{0.0, Vector3d(0.2, 0.0, 0.0)}, {7.0, Vector3d(0.2, 0.0, 0.2)},
                       {10.0, Vector3d(0.2, 0.0, 0.0)}};
  wpg::Push push;
  push.t = 8.0;
  push.force = Eigen::Vector2d(0.0, 30.0);
  push.duration = 0.1;
  request.pushes = {push};
  wpg::Obstacle circle;
  circle.center = Eigen::Vector2d(2.0, 0.9);
  circle.radius = 0.2;
  circle.margin = 0.1;
  request.obstacles = {circle};
  request.validate();
  wpg::OnlineWalkingGenerator generator(w, request.generator);
  generator.setObstacles(request.obstacles);
  const int first_counted = 30, end = 130;  // 3 s of warm-up, 10 s counted
  CountingCommands commands(request, first_counted, end);
  CountingObserver observer;
  const wpg::WalkResult result = wpg::runWalkLoop(generator, request, commands, &observer);

  EXPECT_EQ(commands.counts.allocations, 0)
      << "malloc/calloc/realloc calls in the walk loop (run under gdb, break "
         "wpg_test_allocation_seen)";
  // The counted iterations did what a walk does: NMPC iterations logged, feet landed, a push.
  EXPECT_TRUE(result.success) << result.message;
  const int periods = static_cast<int>(std::lround(w.sampling_period / w.control_period));
  EXPECT_EQ(result.trajectory.mpc.size(), static_cast<std::size_t>(end));
  EXPECT_EQ(result.trajectory.size(), static_cast<std::size_t>(end * periods + 1));
  EXPECT_EQ(observer.after, static_cast<long>(end) * periods);
  EXPECT_EQ(observer.before, observer.after);
  int landed_while_counted = 0;
  for (const wpg::Footstep& step : result.trajectory.footsteps)
    if (step.landing_time > first_counted * w.sampling_period) ++landed_while_counted;
  EXPECT_GE(landed_while_counted, 10);
  // The push is the part of the CoM acceleration the CoP does not explain (eq. 3:
  // z = c - h/g c'' of the controlled acceleration).
  const wpg::WalkTrajectory& out = result.trajectory;
  const double push_acceleration = push.force.y() / request.robot_mass;
  bool pushed = false;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double controlled = (out.com[i].y() - out.cop[i].y()) * w.gravity / w.com_height;
    if (out.time[i] > first_counted * w.sampling_period && out.time[i] < end * w.sampling_period)
      pushed = pushed || std::abs(out.com_acc[i].y() - controlled - push_acceleration) < 1e-6;
  }
  EXPECT_TRUE(pushed) << "the push must act inside the counted iterations";
}

// The progress monitor (wpg/progress_monitor.hpp) fed at every NMPC sample while the robot
// is blocked: walking into a wall with no way round (wall_walk.hpp), counted from 10 s to 25 s (found blocked
// at 13.7 s), the windows judged and the stretch kept without allocating.
TEST(NmpcAllocation, WalkLoopIterationsWhileBlocked) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  const wpg::WalkRequest request = wpg_test::wallWalkRequest();
  wpg::OnlineWalkingGenerator generator(w, request.generator);
  generator.setObstacles(request.obstacles);
  CountingCommands commands(request, 100, 250);
  const wpg::WalkResult result = wpg::runWalkLoop(generator, request, commands);
  EXPECT_EQ(commands.counts.allocations, 0)
      << "malloc/calloc/realloc calls in the walk loop while blocked";
  EXPECT_TRUE(result.blocked) << result.message;
  EXPECT_LT(result.blocked_since + 4.8, 25.0);  // found inside the counted iterations
}

}  // namespace
