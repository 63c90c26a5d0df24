// The image of a run's group (run_group_writing.hpp; layout and attribute names:
// datasets/SCHEMA.md). Written so that h5py reads everything without code of ours: plain
// numeric datasets, time-major, with `units` / `frame` / `description` attributes and
// variable-length UTF-8 string attributes. The obstacles, the goal and the multibody fields
// have files of their own, the values of the `checks` group are computed in
// dataset_checks.cpp.
#include <cmath>
#include <cstring>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "goal_dataset.hpp"
#include "hdf5_writing.hpp"
#include "obstacles_dataset.hpp"
#include "plan_dataset.hpp"
#include "run_group_writing.hpp"
#include "wpg/obstacles.hpp"

namespace wpg::datasets::detail {
namespace {

// "0=solved, 1=relaxed, ..." for every status libwpg names (iterationStatusName answers
// "unknown" for codes outside the enum), plus any other code present in the data.
std::string statusCodes(const std::vector<std::uint8_t>& present) {
  std::set<int> codes(present.begin(), present.end());
  for (int code = 0; code <= 255; ++code) {
    if (std::strcmp(iterationStatusName(static_cast<IterationStatus>(code)), "unknown") != 0) {
      codes.insert(code);
    }
  }
  std::string text;
  for (const int code : codes) {
    text += (text.empty() ? "" : ", ") + std::to_string(code) + "=" +
            iterationStatusName(static_cast<IterationStatus>(code));
  }
  return text;
}

void writeCom(GroupImage& run, const WalkTrajectory& trajectory);
void writeFeet(GroupImage& run, const WalkTrajectory& trajectory);
void writeFootsteps(GroupImage& run, const WalkTrajectory& trajectory);

// The per-sample fields and the footsteps, those of `fields` (run_fields.hpp).
void writeTrajectory(GroupImage& run, const WalkTrajectory& trajectory, RunFields fields) {
  const DatasetInfo time_info{"s", nullptr, "time of each sample, one row per control period",
                              nullptr};
  if (fields.hasSamples()) writeDoubles(run, "time", trajectory.time, 0, time_info);
  if (fields.has(RunField::kCom)) writeCom(run, trajectory);
  if (fields.has(RunField::kCop)) {
    writeDoubles(run, "cop", flatten(trajectory.cop), 2,
                 {"m", "world",
                  "centre of pressure of the linear inverted pendulum, z = c - h/g c'' (eq. 3), "
                  "on the ground",
                  "x, y"});
  }
  if (fields.has(RunField::kFeet)) writeFeet(run, trajectory);
  if (fields.has(RunField::kFootsteps)) writeFootsteps(run, trajectory);
}

void writeCom(GroupImage& run, const WalkTrajectory& trajectory) {
  writeDoubles(run, "com", flatten(trajectory.com), 3,
               {"m", "world", "centre of mass position", "x, y, z"});
  writeDoubles(run, "com_vel", flatten(trajectory.com_vel), 3,
               {"m/s", "world", "centre of mass velocity", "x, y, z"});
  writeDoubles(run, "com_acc", flatten(trajectory.com_acc), 3,
               {"m/s^2", "world", "centre of mass acceleration", "x, y, z"});
}

void writeFeet(GroupImage& run, const WalkTrajectory& trajectory) {
  writeDoubles(run, "left_foot", flatten(trajectory.left_foot), 4,
               {"m, m, m, rad", "world", "left ankle position and yaw", "x, y, z, yaw"});
  writeDoubles(run, "right_foot", flatten(trajectory.right_foot), 4,
               {"m, m, m, rad", "world", "right ankle position and yaw", "x, y, z, yaw"});
  writeDoubles(run, "free_flyer_yaw", trajectory.free_flyer_yaw, 0,
               {"rad", "world", "yaw of the free flyer (waist), mean of the two foot yaws",
                nullptr});

  std::vector<std::uint8_t> support;
  support.reserve(trajectory.support.size());
  for (const SupportState state : trajectory.support) {
    support.push_back(static_cast<std::uint8_t>(state));
  }
  DatasetImage& support_set =
      writeCodes(run, "support", support,
                 {"1", nullptr,
                  "support phase: 0 double support, 1 left foot support, 2 right foot support",
                  nullptr});
  writeStringAttribute(support_set, "codes", "0=double, 1=left, 2=right");
}

void writeFootsteps(GroupImage& run, const WalkTrajectory& trajectory) {
  const std::vector<Footstep>& steps = trajectory.footsteps;
  std::vector<double> footsteps;
  std::vector<std::uint8_t> sides;
  footsteps.reserve(4 * steps.size());
  for (const Footstep& step : steps) {
    footsteps.insert(footsteps.end(),
                     {step.landing_time, step.pose.x(), step.pose.y(), step.pose.z()});
    sides.push_back(static_cast<std::uint8_t>(step.side));
  }
  writeDoubles(run, "footsteps", footsteps, 4,
               {"s, m, m, rad", "world",
                "landed footsteps in landing order, the two initial feet first (landing time 0): "
                "landing time, ankle x, y, yaw",
                "landing_time, x, y, yaw"});
  writeDoubles(run, "footstep_lift_off",
               column(steps, [](const Footstep& step) { return step.lift_off_time; }), 0,
               {"s", nullptr,
                "lift-off time of each row of footsteps' swing (0 for the initial feet): its "
                "single support is the landing time minus it",
                nullptr});
  DatasetImage& side_set = writeCodes(
      run, "footstep_side", sides,
      {"1", nullptr, "side of each row of footsteps: 1 left, 2 right", nullptr});
  writeStringAttribute(side_set, "codes", "1=left, 2=right");
}

// The NMPC's constraint families as the per-iteration slacks name them; a trajectory made by
// hand without them gets one column named "unknown".
std::vector<ConstraintFamilyInfo> slackColumns(const WalkTrajectory& trajectory) {
  if (!trajectory.constraint_families.empty()) return trajectory.constraint_families;
  return {ConstraintFamilyInfo{"unknown", "m or rad", "unknown"}};
}

void writeIterations(GroupImage& mpc, const WalkTrajectory& trajectory);

// mpc/: its `time` with any of the fields mpc, plan, goal (their rows are its rows), the
// iterations' log with mpc, their plans with plan.
void writeMpcLog(GroupImage& run, const WalkTrajectory& trajectory, RunFields fields) {
  if (!fields.has(RunField::kMpc) && !fields.has(RunField::kPlan) && !fields.has(RunField::kGoal))
    return;
  const std::vector<MpcIterationLog>& log = trajectory.mpc;
  GroupImage& mpc = run.createGroup("mpc");
  writeDoubles(mpc, "time", column(log, [](const MpcIterationLog& r) { return r.time; }), 0,
               {"s", nullptr, "time of each NMPC iteration (one per sampling period)", nullptr});
  if (fields.has(RunField::kMpc)) writeIterations(mpc, trajectory);
  if (fields.has(RunField::kPlan)) writePlans(mpc, trajectory);
}

void writeIterations(GroupImage& mpc, const WalkTrajectory& trajectory) {
  const std::vector<MpcIterationLog>& log = trajectory.mpc;
  writeDoubles(mpc, "solve_time",
               column(log, [](const MpcIterationLog& r) { return r.solve_time; }), 0,
               {"s", nullptr, "wall time of the iteration: linearization and QP(s)", nullptr});
  std::vector<int> qp_iterations, sqp_iterations;
  std::vector<std::uint8_t> status;
  for (const MpcIterationLog& row : log) {
    qp_iterations.push_back(row.qp_iterations);
    sqp_iterations.push_back(row.sqp_iterations);
    status.push_back(static_cast<std::uint8_t>(row.status));
  }
  writeInts(mpc, "qp_iterations", qp_iterations,
            {"1", nullptr,
             "working-set updates of the QP solver (warm start included), summed over the "
             "QPs of the iteration",
             nullptr});
  writeInts(mpc, "sqp_iterations", sqp_iterations,
            {"1", nullptr, "QPs solved in this iteration (Gauss-Newton SQP iterations)", nullptr});
  DatasetImage& status_set = writeCodes(
      mpc, "status", status,
      {"1", nullptr, "outcome of the iteration, see the codes attribute", nullptr});
  writeStringAttribute(status_set, "codes", statusCodes(status));
  writeDoubles(mpc, "cost", column(log, [](const MpcIterationLog& r) { return r.cost; }), 0,
               {"1", nullptr, "value of the NMPC cost (eq. 5) at the applied solution", nullptr});
  // One slack column per constraint family, each in its family's unit (relaxation stages:
  // libwpg/include/wpg/nmpc/solver.hpp), and the bit mask of the families that gave way.
  const std::vector<ConstraintFamilyInfo> families = slackColumns(trajectory);
  std::string names, units, groups;
  for (const ConstraintFamilyInfo& family : families) {
    names += (names.empty() ? "" : ", ") + family.name;
    units += (units.empty() ? "" : ", ") + family.unit;
    groups += (groups.empty() ? "" : ", ") + family.group;
  }
  std::vector<double> slack;
  std::vector<std::uint8_t> relaxed;
  slack.reserve(log.size() * families.size());
  for (const MpcIterationLog& row : log) {
    for (std::size_t k = 0; k < families.size(); ++k) slack.push_back(row.slack[k]);
    relaxed.push_back(static_cast<std::uint8_t>(row.relaxed_families));
  }
  DatasetImage& slack_set = writeDataset(
      mpc, "slack", slack.data(), log.size(), families.size(), ElementType::kFloat64,
      {units.c_str(), nullptr,
       "relaxation slack of each constraint family when the QP was infeasible (one column per "
       "family, in its unit), else 0",
       names.c_str()});
  writeStringAttribute(slack_set, "groups", groups);
  writeCodes(mpc, "relaxed_families", relaxed,
             {"1", nullptr,
              "bit k set when constraint family k (column k of slack) had to be relaxed",
              nullptr});
  // What the walk was asked to progress along (libwpg's progress_monitor.hpp); unknown for a
  // walk read back from a file written before it was stored: nothing rather than NaN.
  std::vector<double> velocity;
  velocity.reserve(2 * log.size());
  for (const MpcIterationLog& row : log) {
    if (!row.commanded_velocity.allFinite()) {
      velocity.clear();
      break;
    }
    velocity.insert(velocity.end(), {row.commanded_velocity.x(), row.commanded_velocity.y()});
  }
  if (!velocity.empty() || log.empty()) {
    writeDoubles(mpc, "commanded_velocity", velocity, 2,
                 {"m/s", "world",
                  "linear part of the velocity command the iteration's NMPC tracked, clamped to "
                  "the robot's limits, turned into the world by the heading the generator "
                  "expressed it in (walking.heading_reference); 0 in a fallen row",
                  "x, y"});
  }
}

// Footsteps against the obstacles (when there are any): the step centres computed by
// dataset_checks.cpp with libwpg's exact 2-D distance; the soles from the caller's FCL world.
void writeObstacleChecks(GroupImage& checks, const FootstepObstacleChecks& steps,
                         const FootstepClearances* clearances) {
  writeDoubles(checks, "step_centre_clearance", steps.step_centre_clearance, 0,
               {"m", nullptr,
                "per footstep, min over obstacles of (signed distance of the ankle point to the "
                "obstacle - margin - obstacle_foot_radius): the margin of the NMPC's obstacle "
                "constraint (eq. 18-19), >= 0 when it holds; with walking.obstacle_distance_form "
                "paper the bound is the paper's instead (sqrt(radius^2 + margin^2) - radius for "
                "a circle, margin for other shapes)",
                nullptr});
  writeInts(checks, "step_centre_clearance_obstacle", steps.step_centre_clearance_obstacle,
            {"1", nullptr, "index (row of obstacles/) of the obstacle of step_centre_clearance",
             nullptr});
  writeDoubleAttribute(checks, "min_step_centre_clearance", steps.min_step_centre_clearance);
  if (!clearances) return;
  writeDoubles(checks, "step_clearance", clearances->clearance, 0,
               {"m", nullptr,
                "per footstep, min over obstacles of (signed distance between the sole rectangle "
                "and the obstacle - margin), from the FCL world; < 0: the sole enters the margin",
                nullptr});
  writeInts(checks, "step_clearance_obstacle", clearances->clearance_obstacle,
            {"1", nullptr, "index (row of obstacles/) of the obstacle of step_clearance", nullptr});
  writeDoubles(checks, "step_foot_distance", clearances->foot_distance, 0,
               {"m", nullptr,
                "per footstep, min over obstacles of the signed distance between the sole "
                "rectangle and the obstacle itself (margin not counted); < 0: the foot touches it",
                nullptr});
  writeDoubleAttribute(checks, "min_step_clearance", steps.min_step_clearance);
  writeDoubleAttribute(checks, "min_step_foot_distance", steps.min_step_foot_distance);
}

// Physical invariants of the walk (dataset_checks.hpp), so that a dataset says whether it is sound
// without any code of ours.
void writeChecks(GroupImage& run, const DatasetChecks& checked, const FootstepClearances* clearances) {
  const WalkCheckReport& report = checked.walk;
  GroupImage& checks = run.createGroup("checks");
  writeStringAttribute(checks, "description",
                       "invariants of the walk; distances in m (<= 0: inside), yaw in rad, "
                       "speed in m/s, acceleration in m/s^2");
  writeDoubleAttribute(checks, "cop_sample_violation", report.cop_sample_violation);
  writeDoubleAttribute(checks, "cop_sample_violation_time", report.cop_sample_violation_time);
  writeDoubleAttribute(checks, "cop_control_violation", report.cop_control_violation);
  writeDoubleAttribute(checks, "cop_control_violation_time", report.cop_control_violation_time);
  writeDoubleAttribute(checks, "cop_margin_excursion", report.cop_margin_excursion);
  writeDoubleAttribute(checks, "feasibility_violation", report.feasibility_violation);
  writeDoubleAttribute(checks, "max_step_yaw_change", report.max_step_yaw_change);
  writeIntAttribute(checks, "landed_steps", report.landed_steps);
  writeDoubleAttribute(checks, "speed_after_two_steps", report.speed_after_two_steps);
  writeDoubleAttribute(checks, "swing_foot_speed_max", report.swing_foot_speed_max);
  writeDoubleAttribute(checks, "swing_foot_speed_max_time", report.swing_foot_speed_max_time);
  writeDoubleAttribute(checks, "swing_foot_acceleration_max", report.swing_foot_acceleration_max);
  writeDoubleAttribute(checks, "swing_foot_acceleration_max_time",
                       report.swing_foot_acceleration_max_time);
  if (checked.has_obstacles) writeObstacleChecks(checks, checked.footsteps, clearances);
}

}  // namespace

std::shared_ptr<const GroupImage> buildWalkPart(const Scenario& scenario,
                                                const wpg::WalkResult& result, RunFields fields) {
  auto part = std::make_shared<GroupImage>();
  writeTrajectory(*part, result.trajectory, fields);
  writeMpcLog(*part, result.trajectory, fields);
  if (fields.has(RunField::kObstacles)) writeObstacles(*part, scenario.request.obstacles);
  return part;
}

std::shared_ptr<const GroupImage> buildMultibodyPart(const Scenario& scenario,
                                                     const MultibodyRecord& multibody) {
  auto part = std::make_shared<GroupImage>();
  writeMultibody(*part, scenario, multibody);
  return part;
}

GroupImage& buildRunGroup(GroupImage& runs, const std::string& group_name,
                          const Scenario& scenario, const WalkResult& result,
                          const FootstepClearances* clearances, const MultibodyRecord* multibody,
                          const GoalOutcome* goal, const RunGroupParts& parts, RunFields fields) {
  checkRunInputs(scenario, result, clearances, multibody);
  GroupImage& run = runs.createGroup(group_name);
  writeStringAttribute(run, "algorithm",
                       generatorAlgorithmName(scenario.request.generator.algorithm));
  writeIntAttribute(run, "success", result.success ? 1 : 0);
  writeStringAttribute(run, "message", result.message);
  writeStringAttribute(run, "robot", scenario.robot);
  writeLinesAttribute(run, "warnings", scenario.warnings);  // the loader's; none: no attribute
  // Stuck is an outcome: the start of the stretch only when there is one (no NaN, no
  // sentinel); the whole walk's ratio only when some sample had a linear command.
  writeIntAttribute(run, "blocked", result.blocked ? 1 : 0);
  if (result.blocked) {
    writeDoubleAttribute(run, "blocked_since", result.blocked_since);
    writeDoubleAttribute(run, "blocked_x", result.blocked_position.x());
    writeDoubleAttribute(run, "blocked_y", result.blocked_position.y());
  }
  if (std::isfinite(result.progress_ratio)) {
    writeDoubleAttribute(run, "progress_ratio", result.progress_ratio);
  }
  run.addPart(parts.walk ? parts.walk : buildWalkPart(scenario, result, fields));
  if (parts.checks) {
    writeChecks(run, *parts.checks, clearances);
  } else {
    writeChecks(run, computeDatasetChecks(scenario, result.trajectory, clearances), clearances);
  }
  if (multibody && fields.has(RunField::kMultibody)) {
    run.addPart(parts.multibody ? parts.multibody : buildMultibodyPart(scenario, *multibody));
  }
  if (goal) writeGoal(run, scenario, *goal, fields);  // below, the follower's commands (replay too)
  if (scenario.goal.enabled && fields.has(RunField::kGoal)) {
    writeGoalCommands(run, result.trajectory);
  }
  // A lean run names what it holds (a run stored whole has no attribute: every field), so that
  // readers say what it lacks rather than that a dataset is missing.
  if (!fields.isAll()) writeStringListAttribute(run, "fields", fields.names());
  return run;
}

}  // namespace wpg::datasets::detail
