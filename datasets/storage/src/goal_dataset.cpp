// The goal walk's groups of a run dataset (goal_dataset.hpp).
#include "goal_dataset.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "hdf5_writing.hpp"

namespace wpg::datasets::detail {

void writeGoalCommands(GroupImage& run, const wpg::WalkTrajectory& trajectory) {
  std::vector<double> commands;
  commands.reserve(3 * trajectory.mpc.size());
  for (const MpcIterationLog& row : trajectory.mpc) {
    if (!row.command.allFinite()) return;  // not known: nothing rather than NaN
    commands.insert(commands.end(), {row.command.x(), row.command.y(), row.command.z()});
  }
  GroupImage& mpc = run.openGroup("mpc");
  writeDoubles(mpc, "command", commands, 3,
               {"m/s, m/s, rad/s", nullptr,
                "velocity command of the path follower that the iteration's NMPC tracked, robot "
                "frame (the frame of walking.heading_reference): vx, vy, omega",
                "vx, vy, omega"});
}

void writeGoal(GroupImage& run, const Scenario& scenario, const GoalOutcome& goal,
               RunFields fields) {
  const WalkGoal& g = scenario.goal.goal;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  writeDoubleAttribute(run, "goal_x", g.position.x());
  writeDoubleAttribute(run, "goal_y", g.position.y());
  writeDoubleAttribute(run, "goal_yaw", g.has_yaw ? g.yaw : nan);
  writeDoubleAttribute(run, "goal_tolerance", g.tolerance);
  writeDoubleAttribute(run, "goal_yaw_tolerance", g.yaw_tolerance);
  writeIntAttribute(run, "goal_reached", goal.goal_reached ? 1 : 0);
  writeDoubleAttribute(run, "time_to_goal", goal.goal_reached ? goal.time_to_goal : nan);
  writeDoubleAttribute(run, "goal_final_distance", goal.final_distance);
  writeDoubleAttribute(run, "goal_final_yaw_error", goal.final_yaw_error);
  writeStringAttribute(run, "goal_outcome", goal.outcome);

  // Which obstacles the planner knew from the start (the others it learnt by sensing them).
  if (fields.has(RunField::kObstacles)) {
    GroupImage& obstacles = run.openGroup("obstacles");  // made by writeObstacles
    std::vector<std::uint8_t> known;
    for (std::size_t i = 0; i < scenario.request.obstacles.size(); ++i)
      known.push_back(scenario.goal.knownToPlanner(i) ? 1 : 0);
    writeCodes(obstacles, "known_to_planner", known,
               {"1", nullptr,
                "1 when the route planner knows the obstacle from the start, 0 when it learns "
                "of it within planner.sensing_range (the NMPC avoids every obstacle)",
                nullptr});
  }
  if (!fields.has(RunField::kGoal)) return;

  const RoutePlannerSettings& settings = scenario.goal.planner;
  GroupImage& plans = run.createGroup("plans");
  writeStringAttribute(plans, "description",
                       "one row per (re)plan of the global route planner (OMPL, SE(2)); "
                       "statistics named as ompl::tools::Benchmark names them");
  writeStringAttribute(plans, "algorithm", settings.algorithm);
  writeIntAttribute(plans, "seed", static_cast<int>(settings.seed));
  writeDoubleAttribute(plans, "robot_radius", settings.robot_radius);
  writeIntAttribute(plans, "count", static_cast<int>(goal.plans.size()));
  std::vector<std::uint8_t> status, trigger;
  std::vector<double> time, start, planning_time, route_length, solution_length, simplified_length,
      clearance, simplification_time, waypoints;
  std::vector<int> graph_states, graph_motions, iterations, known_obstacles, route_start,
      route_count;
  for (const RoutePlanRecord& plan : goal.plans) {
    time.push_back(plan.time);
    status.push_back(static_cast<std::uint8_t>(plan.status));
    trigger.push_back(static_cast<std::uint8_t>(plan.trigger));
    start.insert(start.end(), plan.start.data(), plan.start.data() + 3);
    known_obstacles.push_back(plan.known_obstacles);
    planning_time.push_back(plan.planning_time);
    route_length.push_back(plan.route_length);
    solution_length.push_back(plan.solution_length);
    simplified_length.push_back(plan.simplified_solution_length);
    clearance.push_back(plan.solution_clearance);
    simplification_time.push_back(plan.simplification_time);
    graph_states.push_back(plan.graph_states);
    graph_motions.push_back(plan.graph_motions);
    iterations.push_back(plan.iterations);
    route_start.push_back(static_cast<int>(waypoints.size() / 3));
    route_count.push_back(static_cast<int>(plan.route.size()));
    for (const Eigen::Vector3d& w : plan.route)
      waypoints.insert(waypoints.end(), w.data(), w.data() + 3);
  }
  writeDoubles(plans, "time", time, 0, {"s", nullptr, "walk time when the plan was made", nullptr});
  DatasetImage& status_set = writeCodes(
      plans, "status", status,
      {"1", nullptr, "the planner's outcome in OMPL's terms, see the codes attribute", nullptr});
  writeStringAttribute(status_set, "codes", goal.status_codes);
  DatasetImage& trigger_set =
      writeCodes(plans, "trigger", trigger,
                 {"1", nullptr, "why the plan was made, see the codes attribute", nullptr});
  writeStringAttribute(trigger_set, "codes", goal.trigger_codes);
  writeDoubles(plans, "start", start, 3, {"m, m, rad", "world", "pose planned from", "x, y, yaw"});
  writeInts(plans, "known_obstacles", known_obstacles,
            {"1", nullptr, "obstacles the planner knew", nullptr});
  writeDoubles(plans, "planning_time", planning_time, 0,
               {"s", nullptr, "wall time of the planner's solve() (Benchmark: time)", nullptr});
  writeDoubles(plans, "route_length", route_length, 0,
               {"m", nullptr, "length of the x-y polyline followed (simplified)", nullptr});
  writeDoubles(plans, "solution_length", solution_length, 0,
               {"1", nullptr,
                "SE(2) length before simplification: x-y metres + 0.5 x |yaw change| rad "
                "(Benchmark: solution length)",
                nullptr});
  writeDoubles(plans, "simplified_solution_length", simplified_length, 0,
               {"1", nullptr, "SE(2) length after simplification", nullptr});
  writeDoubles(plans, "solution_clearance", clearance, 0,
               {"m", nullptr,
                "least clearance of the route's states to the known obstacles grown by their "
                "margin, minus the robot radius (Benchmark: solution clearance)",
                nullptr});
  writeDoubles(plans, "simplification_time", simplification_time, 0,
               {"s", nullptr, "wall time of OMPL's path simplification", nullptr});
  writeInts(plans, "graph_states", graph_states,
            {"1", nullptr, "vertices of the planner's graph or tree", nullptr});
  writeInts(plans, "graph_motions", graph_motions,
            {"1", nullptr, "edges of the planner's graph or tree", nullptr});
  writeInts(plans, "iterations", iterations,
            {"1", nullptr, "termination checks made by the planner (its iterations)", nullptr});
  writeDoubles(plans, "routes", waypoints, 3,
               {"m, m, rad", "world",
                "every route's waypoints, concatenated: rows route_start[i] to route_start[i] + "
                "route_count[i] - 1 belong to plan i",
                "x, y, yaw"});
  writeInts(plans, "route_start", route_start,
            {"1", nullptr, "first row of each plan's route in routes", nullptr});
  writeInts(plans, "route_count", route_count,
            {"1", nullptr, "rows of each plan's route in routes (0: no route)", nullptr});
}

}  // namespace wpg::datasets::detail
