// Writing one run to HDF5 (layout and attribute names: datasets/SCHEMA.md). Written so that
// h5py reads everything without code of ours: plain numeric datasets, time-major, with
// `units` / `frame` / `description` attributes and variable-length UTF-8 string attributes.
// This file lays out the groups and writes the file atomically; the HDF5 helpers are in
// hdf5_writing.cpp, the values of the `checks` group are computed in dataset_checks.cpp, the
// timing summaries by the caller (analysis/).
//
// Why ~600 lines: one writer per group of the schema (run, mpc, obstacles, checks, multibody,
// timing), each a list of datasets with units and descriptions; the rest is in its own files.
#include "wpg/datasets/storage/run_dataset.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <future>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <H5Cpp.h>

#include "goal_dataset.hpp"
#include "obstacles_dataset.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "external_link_guard.hpp"
#include "hdf5_writing.hpp"
#include "provenance_attributes.hpp"
#include "run_group_writing.hpp"
#include "wpg/datasets/storage/dataset_checks.hpp"
#include "wpg/obstacles.hpp"
#include <unistd.h>

#ifndef WPG_VERSION_STRING
#error "WPG_VERSION_STRING must be defined (libwpg's CMake target gives it)"
#endif

namespace wpg::datasets {

std::mutex& hdf5Mutex() {
  static std::mutex mutex;
  [[maybe_unused]] static const bool links_checked = (detail::installExternalLinkGuard(), true);
  return mutex;
}

namespace {

namespace fs = std::filesystem;
using namespace detail;  // NOLINT: the HDF5 helpers and the checks of this writer

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

// --- the inputs, checked before anything is written -----------------------------------------

// "writeRunDataset: <array> has <count> <unit>, expected <expected> (one per <per>)"
void requireCount(const std::string& array, std::size_t count, std::size_t expected,
                  const char* unit, const char* per) {
  if (count != expected) {
    throw std::invalid_argument("writeRunDataset: " + array + " has " + std::to_string(count) +
                                " " + unit + ", expected " + std::to_string(expected) +
                                " (one per " + per + ")");
  }
}

void checkSizes(const WalkTrajectory& trajectory) {
  const std::size_t n = trajectory.time.size();
  const auto check = [n](const char* name, std::size_t rows) {
    requireCount(std::string("trajectory.") + name, rows, n, "rows", "trajectory.time sample");
  };
  check("com", trajectory.com.size());
  check("com_vel", trajectory.com_vel.size());
  check("com_acc", trajectory.com_acc.size());
  check("cop", trajectory.cop.size());
  check("left_foot", trajectory.left_foot.size());
  check("right_foot", trajectory.right_foot.size());
  check("free_flyer_yaw", trajectory.free_flyer_yaw.size());
  check("support", trajectory.support.size());
  if (trajectory.constraint_families.size() > static_cast<std::size_t>(kMaxConstraintFamilies)) {
    throw std::invalid_argument("trajectory.constraint_families: expected at most " +
                                std::to_string(kMaxConstraintFamilies) + " families, got " +
                                std::to_string(trajectory.constraint_families.size()));
  }
}

void checkClearanceSizes(const FootstepClearances& clearances, const WalkTrajectory& trajectory) {
  const std::size_t m = trajectory.footsteps.size();
  const auto check = [m](const char* name, std::size_t rows) {
    requireCount(std::string("clearances.") + name, rows, m, "entries",
                 "trajectory.footsteps row");
  };
  check("clearance", clearances.clearance.size());
  check("clearance_obstacle", clearances.clearance_obstacle.size());
  check("foot_distance", clearances.foot_distance.size());
}

void checkGroupName(const std::string& name) {
  if (name.empty() || name == "." || name.find('/') != std::string::npos) {
    throw std::invalid_argument("writeRunDataset: scenario name '" + name +
                                "' cannot be an HDF5 group name (expected non-empty, no '/')");
  }
}

void writeTrajectory(H5::Group& run, const WalkTrajectory& trajectory) {
  const DatasetInfo time_info{"s", nullptr, "time of each sample, one row per control period",
                              nullptr};
  writeDoubles(run, "time", trajectory.time, 0, time_info);
  writeDoubles(run, "com", flatten(trajectory.com), 3,
               {"m", "world", "centre of mass position", "x, y, z"});
  writeDoubles(run, "com_vel", flatten(trajectory.com_vel), 3,
               {"m/s", "world", "centre of mass velocity", "x, y, z"});
  writeDoubles(run, "com_acc", flatten(trajectory.com_acc), 3,
               {"m/s^2", "world", "centre of mass acceleration", "x, y, z"});
  writeDoubles(run, "cop", flatten(trajectory.cop), 2,
               {"m", "world",
                "centre of pressure of the linear inverted pendulum, z = c - h/g c'' (eq. 3), "
                "on the ground",
                "x, y"});
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
  H5::DataSet support_set =
      writeCodes(run, "support", support,
                 {"1", nullptr,
                  "support phase: 0 double support, 1 left foot support, 2 right foot support",
                  nullptr});
  writeStringAttribute(support_set, "codes", "0=double, 1=left, 2=right");

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
  H5::DataSet side_set = writeCodes(
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

void writeMpcLog(H5::Group& run, const WalkTrajectory& trajectory) {
  const std::vector<MpcIterationLog>& log = trajectory.mpc;
  H5::Group mpc = createGroup(run, "mpc");
  writeDoubles(mpc, "time", column(log, [](const MpcIterationLog& r) { return r.time; }), 0,
               {"s", nullptr, "time of each NMPC iteration (one per sampling period)", nullptr});
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
  H5::DataSet status_set = writeCodes(
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
  H5::DataSet slack_set = writeDataset(
      mpc, "slack", slack.data(), log.size(), families.size(), H5::PredType::NATIVE_DOUBLE,
      H5::PredType::IEEE_F64LE,
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
    if (!row.commanded_velocity.allFinite()) return;
    velocity.insert(velocity.end(), {row.commanded_velocity.x(), row.commanded_velocity.y()});
  }
  writeDoubles(mpc, "commanded_velocity", velocity, 2,
               {"m/s", "world",
                "linear part of the velocity command the iteration's NMPC tracked, clamped to "
                "the robot's limits, turned into the world by the heading the generator "
                "expressed it in (walking.heading_reference); 0 in a fallen row",
                "x, y"});
}

// Footsteps against the obstacles (when there are any): the step centres computed by
// dataset_checks.cpp with libwpg's exact 2-D distance; the soles from the caller's FCL world.
void writeObstacleChecks(H5::Group& checks, const FootstepObstacleChecks& steps,
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
void writeChecks(H5::Group& run, const DatasetChecks& checked, const FootstepClearances* clearances) {
  const WalkCheckReport& report = checked.walk;
  H5::Group checks = createGroup(run, "checks");
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

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

void checkMultibodySizes(const MultibodyValidation& multibody, const WalkTrajectory& trajectory) {
  const Eigen::Index n = static_cast<Eigen::Index>(trajectory.size());
  const auto check = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("writeRunDataset: multibody." + what);
  };
  const auto shape = [](const Eigen::MatrixXd& m) {
    return std::to_string(m.rows()) + " x " + std::to_string(m.cols());
  };
  const Eigen::Index nq = static_cast<Eigen::Index>(multibody.configuration_names.size());
  check(multibody.q.rows() == n && multibody.q.cols() == nq && nq > 0,
        "q is " + shape(multibody.q) + ", expected " + std::to_string(n) + " x " +
            std::to_string(nq) + " (one row per sample, one column per configuration name)");
  check(multibody.zmp_multibody.rows() == n && multibody.zmp_multibody.cols() == 2,
        "zmp_multibody is " + shape(multibody.zmp_multibody) + ", expected " +
            std::to_string(n) + " x 2");
  const bool filtered = multibody.com_filtered.size() > 0;
  check(!filtered || (multibody.com_filtered.rows() == n && multibody.com_filtered.cols() == 3),
        "com_filtered is " + shape(multibody.com_filtered) + ", expected " + std::to_string(n) +
            " x 3 or empty");
  check(filtered ? multibody.zmp_multibody_filtered.rows() == n &&
                       multibody.zmp_multibody_filtered.cols() == 2
                 : multibody.zmp_multibody_filtered.size() == 0,
        "zmp_multibody_filtered is " + shape(multibody.zmp_multibody_filtered) + ", expected " +
            (filtered ? std::to_string(n) + " x 2 (com_filtered is given)"
                      : std::string("empty (com_filtered is empty)")));
  check(multibody.tick_stage_time.size() == 0 ||
            (multibody.tick_stage_time.cols() == 4 &&
             multibody.tick_stage_time.rows() ==
                 static_cast<Eigen::Index>(multibody.tick_nmpc.size())),
        "tick_stage_time is " + shape(multibody.tick_stage_time) + ", expected " +
            std::to_string(multibody.tick_nmpc.size()) + " x 4 (one row per tick_nmpc entry)");
  check(multibody.chain_stage_time.rows() == multibody.chain_time.size() &&
            multibody.chain_stage_time.cols() == 4,
        "chain_stage_time is " + shape(multibody.chain_stage_time) + ", expected " +
            std::to_string(multibody.chain_time.size()) + " x 4 (one row per chain_time entry)");
}

// The multibody replay and the dynamic filter (paper Sec. IV, Fig. 6): the motion sent to the
// robot, the multibody ZMP before and after the filter, and how far they are from the
// reference CoP.
void writeMultibody(H5::Group& run, const Scenario& scenario, const MultibodyRecord& multibody) {
  const MultibodyValidation& mb = multibody.validation;
  const hsize_t nq = mb.configuration_names.size();
  std::vector<std::string> units;
  for (hsize_t j = 0; j < nq; ++j) units.push_back(j < 3 ? "m" : j < 7 ? "1" : "rad");
  const bool filtered = mb.com_filtered.size() > 0;
  const std::string q_units = joined(units);
  const std::string q_columns = joined(mb.configuration_names);
  H5::DataSet q = writeDataset(
      run, "q", rowMajor(mb.q).data(), static_cast<hsize_t>(mb.q.rows()), nq,
      H5::PredType::NATIVE_DOUBLE, H5::PredType::IEEE_F64LE,
      {q_units.c_str(), "world",
       filtered ? "configuration of the robot following the filtered CoM (com_filtered), from the "
                  "walking IK: base position, base orientation quaternion (w, x, y, z), joint "
                  "values in the URDF's order"
                : "configuration of the robot following the generated CoM, from the walking IK: "
                  "base position, base orientation quaternion (w, x, y, z), joint values in the "
                  "URDF's order",
       q_columns.c_str()});
  writeStringListAttribute(q, "names", mb.configuration_names);
  writeDoubles(run, "zmp_multibody", rowMajor(mb.zmp_multibody), 2,
               {"m", "world",
                "ZMP of the multibody model (inverse dynamics of the IK motion of the generated "
                "CoM and feet), before the dynamic filter",
                "x, y"});
  if (filtered) {
    writeDoubles(run, "com_filtered", rowMajor(mb.com_filtered), 3,
                 {"m", "world",
                  "centre of mass corrected by the dynamic filter: com + the preview controller's "
                  "correction of the ZMP error (paper Sec. IV)",
                  "x, y, z"});
    writeDoubles(run, "zmp_multibody_filtered", rowMajor(mb.zmp_multibody_filtered), 2,
                 {"m", "world", "ZMP of the multibody model following com_filtered", "x, y"});
  }

  H5::Group group = createGroup(run, "multibody");
  writeStringAttribute(group, "description",
                       "multibody replay of the walk (walking IK, inverse dynamics) and dynamic "
                       "filter; ZMP errors are |cop - zmp| in m, RMS and max over the samples "
                       "(after = before without the filter)");
  writeIntAttribute(group, "filtered", filtered ? 1 : 0);
  writeDoubleAttribute(group, "zmp_error_rms_before", mb.before.rms);
  writeDoubleAttribute(group, "zmp_error_max_before", mb.before.max);
  writeDoubleAttribute(group, "zmp_error_rms_after", mb.after.rms);
  writeDoubleAttribute(group, "zmp_error_max_after", mb.after.max);
  writeIntAttribute(group, "ik_failures", mb.ik_failures);
  writeDoubleAttribute(group, "max_ik_com_error", mb.max_ik_com_error);
  writeDoubleAttribute(group, "max_ik_foot_error", mb.max_ik_foot_error);
  writeIntAttribute(group, "samples_with_limit_violations", mb.samples_with_limit_violations);
  writeDoubleAttribute(group, "max_limit_violation", mb.max_limit_violation);
  writeStringListAttribute(group, "violated_joints", mb.violated_joints);
  writeDoubleAttribute(group, "filter_error_weight", scenario.filter_settings.error_weight);
  writeDoubleAttribute(group, "filter_input_weight", scenario.filter_settings.input_weight);
  writeDoubleAttribute(group, "filter_preview_time", scenario.filter_settings.preview_time);
  const double online_r = scenario.filter_loop.online_input_weight;  // R of the online loop
  writeDoubleAttribute(group, "filter_online_input_weight", online_r);
  writeStringAttribute(group, "filter_mode", mb.filter_mode);  // closed_loop, online, offline, ""
  writeIntAttribute(group, "wpg_reinitialized", mb.wpg_reinitialized ? 1 : 0);
  if (mb.has_offline_comparison) {
    // filter_settings.mode both: the offline pass over the open-loop walk, for comparison.
    writeDoubleAttribute(group, "offline_zmp_error_rms_before", mb.offline_before.rms);
    writeDoubleAttribute(group, "offline_zmp_error_max_before", mb.offline_before.max);
    writeDoubleAttribute(group, "offline_zmp_error_rms_after", mb.offline_after.rms);
    writeDoubleAttribute(group, "offline_zmp_error_max_after", mb.offline_after.max);
  }

  // Timing profile of the control chain per NMPC iteration (paper Sec. V-C).
  H5::Group timing = createGroup(run, "timing");
  writeStringAttribute(timing, "description",
                       "wall time of the control chain per NMPC iteration (paper Sec. V-C): NMPC, "
                       "walking IK, multibody ZMP, dynamic filter; the whole-walk stages (ZMP, "
                       "filter) spread evenly over the iterations");
  const Eigen::VectorXd& chain = mb.chain_time;
  writeDoubles(timing, "chain_time", std::vector<double>(chain.data(), chain.data() + chain.size()),
               0, {"s", nullptr, "wall time of the whole chain in each NMPC iteration", nullptr});
  writeDoubles(timing, "chain_stage_time", rowMajor(mb.chain_stage_time), 4,
               {"s", nullptr, "wall time of each stage of the chain in each NMPC iteration",
                "nmpc, ik, multibody_zmp, filter"});
  writeDoubleAttribute(timing, "chain_time_average", multibody.chain_time.average);
  writeDoubleAttribute(timing, "chain_time_std", multibody.chain_time.std_dev);
  writeDoubleAttribute(timing, "chain_time_min", multibody.chain_time.min);
  writeDoubleAttribute(timing, "chain_time_max", multibody.chain_time.max);

  // Per control period (the paper's unit: one 5 ms tick, Sec. V-C).
  if (mb.tick_stage_time.rows() > 0) {
    writeDoubles(timing, "tick_stage_time", rowMajor(mb.tick_stage_time), 4,
                 {"s", nullptr,
                  mb.tick_stages_measured
                      ? "wall time of each stage in each control period (online loop: every "
                        "stage measured in its own tick); wpg = the generator's step (the NMPC "
                        "when it runs, the interpolation, the preview of the plan)"
                      : "wall time of each stage in each control period (offline pass: the NMPC "
                        "and the IK measured per tick, the multibody ZMP and the filter over the "
                        "whole walk spread evenly)",
                  "wpg, ik, multibody_zmp, filter"});
    writeInts(timing, "tick_nmpc", std::vector<int>(mb.tick_nmpc.begin(), mb.tick_nmpc.end()),
              {"1", nullptr, "1 when the NMPC ran in that control period", nullptr});
    writeIntAttribute(timing, "tick_stages_measured", mb.tick_stages_measured ? 1 : 0);
  }
}

void writeFile(const std::string& file_path, const Scenario& scenario, const WalkResult& result,
               const FootstepClearances* clearances, const MultibodyRecord* multibody,
               const GoalOutcome* goal, const PreparedRun* prepared,
               PendingRecording* multibody_chunks) {
  // Closing the file closes every object still open and flushes them (a strong close): a write
  // that fails there (disk full) is an error of file.close(), not a message of a destructor
  // that the commit would never hear of.
  H5::FileAccPropList access;
  access.setFcloseDegree(H5F_CLOSE_STRONG);
  auto owned = std::make_unique<H5::H5File>(createHdf5File(file_path, access));
  H5::H5File& file = *owned;
  writeIntAttribute(file, "schema_version", kRunDatasetSchemaVersion);
  writeStringAttribute(file, "wpg_version", WPG_VERSION_STRING);
  writeProvenanceAttributes(file);
  writeStringAttribute(file, "scenario", scenario.resolved_yaml);
  writeStringAttribute(file, "created_by", "wpg");  // wpg run, wpg replay or a program of yours

  {
    H5::Group runs = file.createGroup("runs");
    auto* recording = prepared && prepared->recording
                          ? static_cast<ChunkRecording*>(prepared->recording.get())
                          : nullptr;
    if (recording) recording->replayed = 0;
    const RecordingScope scope(recording, RecordingMode::kReplay);
    writeRunGroup(runs, scenario.name, scenario, result, clearances, multibody, goal, nullptr,
                  multibody_chunks);
  }
  try {
    file.close();  // inside the try of the caller: a failed flush is an error, not a warning
  } catch (const H5::Exception&) {
    // HDF5 1.10 crashes when a file whose close failed is closed again (as ~H5File would):
    // the handle is let go. The temporary file is removed by the caller; the CLI exits without
    // HDF5's termination (exit code 3, cli/main.cpp).
    static_cast<void>(owned.release());
    throw;
  }
}

}  // namespace

namespace detail {

void checkRunInputs(const Scenario& scenario, const wpg::WalkResult& result,
                    const FootstepClearances* clearances, const MultibodyRecord* multibody) {
  checkSizes(result.trajectory);
  if (clearances) checkClearanceSizes(*clearances, result.trajectory);
  if (multibody) checkMultibodySizes(multibody->validation, result.trajectory);
  checkGroupName(scenario.name);
}

H5::Group writeRunGroup(H5::Group& runs, const std::string& group_name, const Scenario& scenario,
                        const WalkResult& result, const FootstepClearances* clearances,
                        const MultibodyRecord* multibody, const GoalOutcome* goal,
                        const DatasetChecks* given_checks, PendingRecording* multibody_chunks) {
  H5::Group run = createGroup(runs, group_name);
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
  writeTrajectory(run, result.trajectory);
  writeMpcLog(run, result.trajectory);
  writeObstacles(run, scenario.request.obstacles);
  // The checks are computed at most once: by the caller (a batch run's result holds them), else
  // here, while recording (a batch worker, off the lock) when there is a recording, and kept
  // for the replay.
  std::shared_ptr<const DatasetChecks> computed;
  if (!given_checks) {
    if (ChunkRecording* replay = activeReplay(); replay && replay->cache) {
      computed = std::static_pointer_cast<const DatasetChecks>(replay->cache);
    } else {
      computed = std::make_shared<DatasetChecks>(
          computeDatasetChecks(scenario, result.trajectory, clearances));
      if (ChunkRecording* recording = activeRecording()) recording->cache = computed;
    }
  }
  writeChecks(run, given_checks ? *given_checks : *computed, clearances);
  if (multibody) {
    std::unique_ptr<ChunkRecording> chunks;
    if (multibody_chunks && multibody_chunks->valid()) {
      try {
        chunks = multibody_chunks->get();
      } catch (...) {  // compressed below instead, which reports its own errors
      }
    }
    if (chunks) {
      const RecordingScope scope(chunks.get(), RecordingMode::kReplay);
      writeMultibody(run, scenario, *multibody);
    } else {
      writeMultibody(run, scenario, *multibody);
    }
  }
  if (goal) writeGoal(run, scenario, *goal);  // and below, the follower's commands (replay too)
  if (scenario.goal.enabled) writeGoalCommands(run, result.trajectory);
  return run;
}

}  // namespace detail

PreparedRun prepareWalkDatasets(const Scenario& scenario, const wpg::WalkResult& result) {
  checkRunInputs(scenario, result, nullptr, nullptr);
  auto recording = std::make_shared<ChunkRecording>();
  recording->partial = true;
  {
    const RecordingScope scope(recording.get(), RecordingMode::kRecord);
    H5::Group placeholder;  // never used by HDF5 while recording
    // The first datasets writeRunGroup writes, in its order.
    writeTrajectory(placeholder, result.trajectory);
    writeMpcLog(placeholder, result.trajectory);
    writeObstacles(placeholder, scenario.request.obstacles);
  }
  return PreparedRun{recording};
}

void writeRunDataset(const std::string& path, const Scenario& scenario,
                     const wpg::WalkResult& result, const FootstepClearances* clearances,
                     const MultibodyRecord* multibody, const GoalOutcome* goal,
                     const PreparedRun* prepared) {
  checkRunInputs(scenario, result, clearances, multibody);
  if (goal && !scenario.goal.enabled) {
    throw std::invalid_argument("writeRunDataset: a goal outcome for a scenario without a goal");
  }
  if (path.empty() || !fs::path(path).has_filename()) {
    throw std::invalid_argument("writeRunDataset: '" + path + "' is not a file path");
  }
  // The multibody fields (a replayed run: most of the file's bytes) are compressed on another
  // thread while this one writes everything before them; the same chunks as compressed here.
  PendingRecording multibody_chunks;
  if (multibody) {
    try {
      multibody_chunks = std::async(std::launch::async, [&] {
        auto chunks = std::make_unique<ChunkRecording>();
        const RecordingScope scope(chunks.get(), RecordingMode::kRecord);
        H5::Group placeholder;  // never used by HDF5 while recording
        writeMultibody(placeholder, scenario, *multibody);
        return chunks;
      });
    } catch (const std::system_error&) {  // no thread to spare: compressed by the writer
    }
  }
  // Written beside the target under an unpredictable name, then renamed over it (atomic on one
  // file system); removed on failure and on SIGINT / SIGTERM (output_file.hpp).
  TemporaryOutput temporary(path);
  {
    std::lock_guard<std::mutex> lock(hdf5Mutex());
    H5::Exception::dontPrint();  // errors become exceptions with messages, not stderr dumps
    try {
      writeFile(temporary.path(), scenario, result, clearances, multibody, goal, prepared,
                &multibody_chunks);
    } catch (const H5::Exception& error) {
      throw std::runtime_error(path + ": cannot write the HDF5 file (" + error.getFuncName() +
                               ": " + error.getDetailMsg() + ")");
    }
  }
  temporary.commit();
}

}  // namespace wpg::datasets
