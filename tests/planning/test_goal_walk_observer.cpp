// A controller around the WPG of a walk to a goal (walkToGoal's ControlLoopObserver, as the
// dynamic filter's loop of the paper's Fig. 3 uses it): called around every control period of
// the walk the path follower commands, without changing a walk it does not touch, and what it
// re-initialises is the CoM the follower then steers from.
#include <gtest/gtest.h>

#include <vector>

#include "wpg/online_walking_generator.hpp"
#include "../common/goal_walking.hpp"
#include "wpg/planning/goal_walk.hpp"

namespace {

using wpg_test::goalWalking;

wpg::GoalRequest goalAt(double x, double y) {
  wpg::GoalRequest goal;
  goal.enabled = true;
  goal.goal.position = Eigen::Vector2d(x, y);
  return goal;
}

// Counts the calls and the times it saw; shifts the WPG's CoM sideways by `shift` at every NMPC
// iteration after the first (a stand-in for the closed loop's re-initialisation).
class CountingObserver final : public wpg::ControlLoopObserver {
 public:
  explicit CountingObserver(double shift = 0.0) : shift_(shift) {}
  void beforeStep(wpg::OnlineWalkingGenerator& generator) override {
    ++before;
    if (shift_ != 0.0 && generator.atSamplingInstant() && generator.time() > 0.0) {
      Eigen::Vector3d y = generator.comStateY();
      y(0) += shift_;
      generator.reinitializeCom(generator.comStateX(), y);
    }
  }
  void afterStep(wpg::OnlineWalkingGenerator&, const wpg::ControlSample& sample) override {
    ++after;
    times.push_back(sample.time);
  }
  int before = 0, after = 0;
  std::vector<double> times;

 private:
  double shift_;
};

TEST(GoalWalkObserver, IsCalledAroundEveryControlPeriodAndLeavesAnUntouchedWalkAsItWas) {
  const wpg::WalkingParameters parameters = goalWalking();
  wpg::WalkRequest request;
  request.duration = 30.0;
  const wpg::GoalRequest goal = goalAt(1.5, 0.5);
  const wpg::planning::GoalWalkResult plain = wpg::planning::walkToGoal(parameters, request, goal);
  CountingObserver observer;
  const wpg::planning::GoalWalkResult observed =
      wpg::planning::walkToGoal(parameters, request, goal, {}, &observer);
  ASSERT_TRUE(observed.goal_reached) << observed.outcome;
  // One call before and one after each control period; the closing sample (standing at the
  // goal) is recorded after the last one, without a step.
  const auto samples = static_cast<int>(observed.walk.trajectory.size());
  EXPECT_EQ(observer.before, samples - 1);
  EXPECT_EQ(observer.after, samples - 1);
  ASSERT_EQ(observer.times.size(), observed.walk.trajectory.time.size() - 1);
  for (std::size_t i = 0; i < observer.times.size(); ++i)
    ASSERT_EQ(observer.times[i], observed.walk.trajectory.time[i]) << "sample " << i;
  EXPECT_EQ(observed.walk.trajectory.com, plain.walk.trajectory.com);
  EXPECT_EQ(observed.time_to_goal, plain.time_to_goal);
}

TEST(GoalWalkObserver, TheFollowerSteersFromTheCoMTheObserverSet) {
  const wpg::WalkingParameters parameters = goalWalking();
  wpg::WalkRequest request;
  request.duration = 30.0;
  const wpg::GoalRequest goal = goalAt(1.5, 0.5);
  const wpg::planning::GoalWalkResult plain = wpg::planning::walkToGoal(parameters, request, goal);
  CountingObserver shifting(2e-4);  // 0.2 mm per NMPC iteration, sideways
  const wpg::planning::GoalWalkResult shifted =
      wpg::planning::walkToGoal(parameters, request, goal, {}, &shifting);
  // The walk changed, and still reached the goal: the follower corrected the drift.
  EXPECT_NE(shifted.walk.trajectory.com, plain.walk.trajectory.com);
  ASSERT_TRUE(shifted.goal_reached) << shifted.outcome;
  EXPECT_LE(shifted.final_distance, goal.goal.tolerance);
}

}  // namespace
