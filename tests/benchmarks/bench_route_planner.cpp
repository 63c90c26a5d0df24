// Route planning and the chained walk to a goal: rrtconnect's
// planning time from the start to the goal of each shipped goal world (median over the
// repetitions, each plan with its own seed), and a 30 s walk to a goal chained with the NMPC
// (route planner + path follower + online generator), wall time with and without the planner's
// own time.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/planning/goal_walk.hpp"
#include "wpg/planning/route_planner.hpp"
#include "../common/source_dir.hpp"

namespace {

wpg::datasets::Scenario shipped(const std::string& name,
                                const std::vector<std::string>& overrides = {}) {
  const std::string source = wpg_test::sourceDir();
  return wpg::datasets::loadScenario(source + "/datasets/scenarios/" + name + ".yaml", overrides,
                                     source + "/robots");
}

void medianCounter(benchmark::State& state, const char* name, std::vector<double>& samples) {
  if (samples.empty()) return;
  std::sort(samples.begin(), samples.end());
  state.counters[name] = samples[samples.size() / 2];
}

// All obstacles known (the worst case for the validity checks).
void BM_RrtConnectPlan(benchmark::State& state, const std::string& world) {
  const wpg::datasets::Scenario scenario = shipped(world);
  const wpg::GoalRequest& goal = scenario.goal;
  const Eigen::Vector2d start = Eigen::Vector2d::Zero();
  const wpg::planning::RoutePlanner planner(
      wpg::planning::World(scenario.request.obstacles), goal.planner,
      wpg::planning::plannerRobotRadius(scenario.walking, goal.planner),
      wpg::planning::planningBounds(scenario.request.obstacles, start, goal.goal.position,
                                    goal.planner));
  const Eigen::Vector3d goal_pose(goal.goal.position.x(), goal.goal.position.y(), 0.0);
  std::vector<double> planning_ms, route_m;
  std::uint32_t seed = 1;
  for (auto _ : state) {
    const wpg::planning::RoutePlan plan = planner.plan(Eigen::Vector3d::Zero(), goal_pose, seed++);
    if (!plan.solved()) state.SkipWithError("no route");
    planning_ms.push_back(1e3 * plan.statistics.time);
    route_m.push_back(plan.length);
  }
  medianCounter(state, "plan_median_ms", planning_ms);
  medianCounter(state, "route_median_m", route_m);
  state.counters["plan_max_ms"] = *std::max_element(planning_ms.begin(), planning_ms.end());
}
BENCHMARK_CAPTURE(BM_RrtConnectPlan, goal_cluttered, std::string("goal_cluttered"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RrtConnectPlan, goal_u_trap, std::string("goal_u_trap"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RrtConnectPlan, goal_unknown_obstacle, std::string("goal_unknown_obstacle"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RrtConnectPlan, goal_with_yaw, std::string("goal_with_yaw"))
    ->Unit(benchmark::kMillisecond);

// A chained 30 s walk: goal_cluttered's world with a 30 s budget (the goal is ~40 s away, so
// the whole 30 s are walked). Counters: the planners' time, and the wall time without it.
void BM_ChainedWalk30s(benchmark::State& state, const std::string& world) {
  const wpg::datasets::Scenario scenario = shipped(world, {"duration=30"});
  std::vector<double> without_planner_ms, planner_ms;
  for (auto _ : state) {
    const auto begin = std::chrono::steady_clock::now();
    const wpg::planning::GoalWalkResult walk =
        wpg::planning::walkToGoal(scenario.walking, scenario.request, scenario.goal);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    benchmark::DoNotOptimize(walk.walk.trajectory.com.data());
    without_planner_ms.push_back(1e3 * (wall - walk.planning_time));
    planner_ms.push_back(1e3 * walk.planning_time);
    state.counters["walk_s"] = walk.walk.trajectory.time.back();
  }
  medianCounter(state, "wall_without_planner_ms", without_planner_ms);
  medianCounter(state, "planner_ms", planner_ms);
}
BENCHMARK_CAPTURE(BM_ChainedWalk30s, goal_cluttered, std::string("goal_cluttered"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ChainedWalk30s, goal_unknown_obstacle, std::string("goal_unknown_obstacle"))
    ->Unit(benchmark::kMillisecond);

}  // namespace
