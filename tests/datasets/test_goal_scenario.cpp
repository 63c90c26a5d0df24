// Walks to a goal in scenario files and datasets: the goal, planner and
// known_to_planner keys, their errors, the resolved scenario, and the plans group written.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <H5Cpp.h>

#include "hand_made_run.hpp"
#include "hdf5_read.hpp"
#include "test_support.hpp"
#include "wpg/datasets/storage/read_limits.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/storage/run_scene_reader.hpp"
#include "wpg/datasets/input/scenario.hpp"

namespace {

using wpg::datasets::loadScenario;
using wpg::datasets::loadScenarioText;
using wpg::datasets::Scenario;
using wpg_test::expectInputError;
using wpg_test::kRobotsDir;
using wpg_test::kScenariosDir;

std::string shipped(const std::string& name) { return kScenariosDir + "/" + name + ".yaml"; }

TEST(GoalScenario, ShippedGoalScenariosReadTheirGoalAndPlanner) {
  const Scenario scenario = loadScenario(shipped("goal_with_yaw"), {}, kRobotsDir);
  ASSERT_TRUE(scenario.goal.enabled);
  EXPECT_EQ(scenario.goal.goal.position, Eigen::Vector2d(3.0, 1.5));
  EXPECT_TRUE(scenario.goal.goal.has_yaw);
  EXPECT_DOUBLE_EQ(scenario.goal.goal.yaw, 1.5708);
  EXPECT_DOUBLE_EQ(scenario.goal.goal.yaw_tolerance, 0.1);
  EXPECT_EQ(scenario.goal.planner.algorithm, "rrtconnect");
  EXPECT_TRUE(scenario.request.reference.empty());
  // robot_radius 0 (unset) is resolved from the robot: 0.19 / 2 + half the sole's diagonal.
  EXPECT_NEAR(scenario.goal.planner.robot_radius, 0.095 + 0.5 * std::hypot(0.2172, 0.138), 1e-12);

  const Scenario unknown = loadScenario(shipped("goal_unknown_obstacle"), {}, kRobotsDir);
  EXPECT_EQ(unknown.goal.known_to_planner, (std::vector<bool>{false, true}));
  EXPECT_FALSE(unknown.goal.knownToPlanner(0));
  EXPECT_TRUE(unknown.goal.knownToPlanner(1));
  EXPECT_FALSE(unknown.goal.goal.has_yaw);

  const Scenario plain = loadScenario(shipped("walk_forward"), {}, kRobotsDir);
  EXPECT_FALSE(plain.goal.enabled);
  EXPECT_EQ(resolvedScenarioText(plain).find("goal"), std::string::npos);
}

TEST(GoalScenario, TheResolvedScenarioLoadsAsTheSameGoalWalk) {
  for (const std::string name : {"goal_with_yaw", "goal_unknown_obstacle", "goal_u_trap"}) {
    const Scenario first = loadScenario(shipped(name), {"planner.bounds=[-3,8,-4,4]"}, kRobotsDir);
    const Scenario again =
        loadScenarioText(resolvedScenarioText(first), "resolved", {}, kRobotsDir);
    EXPECT_EQ(resolvedScenarioText(again), resolvedScenarioText(first)) << name;
    EXPECT_EQ(again.goal.known_to_planner, first.goal.known_to_planner) << name;
    EXPECT_EQ(again.goal.planner.bounds, first.goal.planner.bounds) << name;
    EXPECT_EQ(again.goal.goal.has_yaw, first.goal.goal.has_yaw) << name;
  }
}

TEST(GoalScenario, OverridesReachEveryKey) {
  const Scenario s = loadScenario(
      shipped("goal_u_trap"),
      {"planner.algorithm=rrtstar", "planner.seed=42", "planner.time_limit=0.5",
       "planner.max_iterations=300", "planner.robot_radius=0.3", "planner.replan_distance=0.2",
       "planner.sensing_range=1.5", "planner.lookahead=0.7", "goal.tolerance=0.2", "goal.yaw=0.3",
       "obstacles[1].known_to_planner=false"},
      kRobotsDir);
  const wpg::RoutePlannerSettings& p = s.goal.planner;
  EXPECT_EQ(p.algorithm, "rrtstar");
  EXPECT_EQ(p.seed, 42u);
  EXPECT_DOUBLE_EQ(p.time_limit, 0.5);
  EXPECT_EQ(p.max_iterations, 300);
  EXPECT_DOUBLE_EQ(p.robot_radius, 0.3);
  EXPECT_DOUBLE_EQ(p.replan_distance, 0.2);
  EXPECT_DOUBLE_EQ(p.sensing_range, 1.5);
  EXPECT_DOUBLE_EQ(p.lookahead, 0.7);
  EXPECT_DOUBLE_EQ(s.goal.goal.tolerance, 0.2);
  EXPECT_TRUE(s.goal.goal.has_yaw);
  EXPECT_EQ(s.goal.known_to_planner, (std::vector<bool>{true, false, true}));
}

TEST(GoalScenario, BadGoalInputIsOneLineNamingTheKey) {
  const std::string file = shipped("goal_u_trap");
  const auto load = [&](std::vector<std::string> overrides) {
    return [overrides, &file] { loadScenario(file, overrides, kRobotsDir); };
  };
  expectInputError(load({"planner.time_limit=-1"}), file, {"'planner.time_limit'", "-1"});
  expectInputError(load({"goal.tolerance=0"}), file, {"'goal.tolerance'"});
  expectInputError(load({"planner.lookahead=-0.5"}), file, {"'planner.lookahead'"});
  expectInputError(load({"planner.bounds=[3,1,0,1]"}), file, {"'planner.bounds'"});
  expectInputError(load({"planner.bounds=[1,2]"}), file, {"'planner.bounds'"});
  expectInputError(load({"goal.position=[1]"}), file, {"'goal.position'"});
  expectInputError(load({"goal.heading=1"}), file, {"heading"});
  expectInputError(load({"planner.speed=1"}), file, {"speed"});
  expectInputError(load({"planner.seed=-3"}), file, {"'planner.seed'"});
  expectInputError(load({"obstacles[0].known_to_planner=maybe"}), file,
                   {"'obstacles[0].known_to_planner'"});
  expectInputError(load({"reference=[]"}), file, {"'reference'", "not both"});
  const std::string forward = shipped("walk_forward");
  expectInputError([&] { loadScenario(forward, {"planner.seed=1"}, kRobotsDir); }, forward,
                   {"'planner'", "only with a 'goal'"});
}

class GoalDataset : public wpg_test::ScratchDirectoryTest {
 protected:
  GoalDataset() : ScratchDirectoryTest("wpg_goal_dataset") {}
};

TEST_F(GoalDataset, PlansRoutesAndGoalAttributesAreWritten) {
  const Scenario scenario = loadScenario(shipped("goal_unknown_obstacle"), {}, kRobotsDir);
  const wpg::WalkResult result = wpg_test::handMadeResult(200, 6, 10);
  wpg::datasets::GoalOutcome goal;
  goal.goal_reached = true;
  goal.time_to_goal = 0.995;
  goal.final_distance = 0.05;
  goal.outcome = "reached";
  goal.status_codes = "0=exact_solution";
  goal.trigger_codes = "0=start, 2=blocked";
  for (int i = 0; i < 2; ++i) {
    wpg::datasets::RoutePlanRecord plan;
    plan.time = 0.5 * i;
    plan.trigger = 2 * i;
    plan.graph_states = 10 + i;
    plan.route_length = 4.0 + i;
    for (int k = 0; k < 3 + i; ++k) plan.route.emplace_back(i + k, 10.0 * i + k, 0.1 * k);
    goal.plans.push_back(plan);
  }
  const std::string path = (directory_ / "goal.h5").string();
  wpg::datasets::writeRunDataset(path, scenario, result, nullptr, nullptr, &goal);

  H5::H5File file(path, H5F_ACC_RDONLY);
  const H5::Group run = file.openGroup("/runs/goal_unknown_obstacle");
  double x = 0.0, time_to_goal = 0.0;
  int reached = 0;
  run.openAttribute("goal_x").read(H5::PredType::NATIVE_DOUBLE, &x);
  run.openAttribute("time_to_goal").read(H5::PredType::NATIVE_DOUBLE, &time_to_goal);
  run.openAttribute("goal_reached").read(H5::PredType::NATIVE_INT, &reached);
  EXPECT_EQ(x, 5.0);
  EXPECT_EQ(time_to_goal, 0.995);
  EXPECT_EQ(reached, 1);
  double yaw = 0.0;
  run.openAttribute("goal_yaw").read(H5::PredType::NATIVE_DOUBLE, &yaw);
  EXPECT_TRUE(std::isnan(yaw));  // the goal has no yaw
  const H5::Group plans = run.openGroup("plans");
  std::vector<hsize_t> dims;
  const std::vector<double> routes = wpg_test::readDoubles(plans, "routes", &dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{7, 3}));
  EXPECT_EQ(wpg_test::readInts(plans, "route_start"), (std::vector<int>{0, 3}));
  EXPECT_EQ(wpg_test::readInts(plans, "route_count"), (std::vector<int>{3, 4}));
  EXPECT_EQ(wpg_test::readInts(plans, "graph_states"), (std::vector<int>{10, 11}));
  EXPECT_EQ(routes[3 * 3 + 1], 10.0);  // plan 1's first waypoint y
  EXPECT_EQ(wpg_test::readDoubles(plans, "route_length"), (std::vector<double>{4.0, 5.0}));
  const H5::Group obstacles = run.openGroup("obstacles");
  EXPECT_EQ(wpg_test::readInts(obstacles, "known_to_planner"), (std::vector<int>{0, 1}));

  // A goal outcome for a scenario without a goal is a caller's error.
  const Scenario plain = loadScenario(shipped("walk_forward"), {}, kRobotsDir);
  EXPECT_THROW(wpg::datasets::writeRunDataset((directory_ / "x.h5").string(), plain, result,
                                              nullptr, nullptr, &goal),
               std::invalid_argument);
}

// The route plans a page draws are bounded (read_limits.hpp): a crafted file whose plans each
// named every row of `routes` made a page 100 times its size.
void replaceDataset(const std::string& path, const std::string& name, const std::vector<hsize_t>& dims,
                    const H5::PredType& type, const void* data) {
  H5::H5File file(path, H5F_ACC_RDWR);
  H5::Group plans = file.openGroup("/runs/goal_unknown_obstacle/plans");
  plans.unlink(name);
  plans.createDataSet(name, type, H5::DataSpace(static_cast<int>(dims.size()), dims.data()))
      .write(data, type);
}

TEST_F(GoalDataset, RoutePlansBeyondTheirLimitsAreRefused) {
  using wpg::datasets::readRoutePlans;
  const Scenario scenario = loadScenario(shipped("goal_unknown_obstacle"), {}, kRobotsDir);
  const wpg::WalkResult result = wpg_test::handMadeResult(200, 6, 10);
  wpg::datasets::GoalOutcome goal;
  goal.outcome = "reached";
  for (int i = 0; i < 2; ++i) {
    wpg::datasets::RoutePlanRecord plan;
    plan.time = 0.5 * i;
    for (int k = 0; k < 3; ++k) plan.route.emplace_back(i + k, k, 0.0);
    goal.plans.push_back(plan);
  }
  const std::string path = (directory_ / "plans.h5").string();
  const auto write = [&] { wpg::datasets::writeRunDataset(path, scenario, result, nullptr, nullptr, &goal); };
  const std::string run = "goal_unknown_obstacle";
  write();
  ASSERT_EQ(readRoutePlans(path, run).size(), 2u);

  // Two plans naming the same rows: each route has its own, in order.
  const std::vector<int> same_rows = {0, 0};
  replaceDataset(path, "route_start", {2}, H5::PredType::NATIVE_INT, same_rows.data());
  expectInputError([&] { readRoutePlans(path, run); }, path,
                   {"route_start row 1: expected 3", "got start 0 count 3"});

  // More waypoints than kMaxStoredRouteWaypoints in all.
  write();
  const hsize_t rows = wpg::datasets::kMaxStoredRouteWaypoints + 1;
  const std::vector<double> waypoints(3 * rows, 0.0);
  replaceDataset(path, "routes", {rows, 3}, H5::PredType::NATIVE_DOUBLE, waypoints.data());
  expectInputError([&] { readRoutePlans(path, run); }, path,
                   {"plans/routes declares 100001 rows: expected at most 100000"});

  // More plans than kMaxStoredPlans.
  write();
  const hsize_t plans = wpg::datasets::kMaxStoredPlans + 1;
  const std::vector<double> times(plans, 0.0);
  replaceDataset(path, "time", {plans}, H5::PredType::NATIVE_DOUBLE, times.data());
  expectInputError([&] { readRoutePlans(path, run); }, path,
                   {"plans/time declares 10001 rows: expected at most 10000"});
}

}  // namespace
