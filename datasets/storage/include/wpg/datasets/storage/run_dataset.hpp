#pragma once
// One run, written to HDF5 (layout: datasets/SCHEMA.md, a contract with every reader).
#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/multibody_validation.hpp"
#include "wpg/walk_generator.hpp"

namespace wpg::datasets {

// The HDF5 schema version written in the root attribute `schema_version` (its history:
// datasets/SCHEMA.md).
constexpr int kRunDatasetSchemaVersion = 2;

// The sole rectangles of the landed footsteps against the obstacles, one entry per row of
// WalkTrajectory::footsteps, as computed by the caller with the FCL world (planning/:
// wpg::planning::checkFootsteps returns these columns under the same names). datasets/ does
// not link FCL; the step centres' clearances it computes itself (libwpg's exact 2-D distance,
// against the NMPC's constraint: sd(ankle, obstacle) - margin - obstacle_foot_radius, or the
// paper's bound with obstacle_distance_form paper: wpg::stepCentreClearance).
struct FootstepClearances {
  std::vector<double> clearance;        // min over obstacles of sd(sole, obstacle) - margin [m]
  std::vector<int> clearance_obstacle;  // index of the obstacle of that minimum
  std::vector<double> foot_distance;    // min over obstacles of sd(sole, obstacle) [m]
};

// One (re)plan of a walk to a goal, as planning/ made it (wpg::planning::PlanRecord; datasets/
// does not link OMPL: the caller copies the fields). Statistics are named as
// ompl::tools::Benchmark names them.
struct RoutePlanRecord {
  double time = 0.0;         // [s] of the walk
  int trigger = 0;           // code of trigger_codes (start, strayed, blocked, retry)
  int status = 0;            // code of status_codes (exact_solution, ..., timeout, ...)
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // (x, y, yaw) planned from
  int known_obstacles = 0;
  double planning_time = 0.0;        // [s] ("time")
  double route_length = 0.0;         // [m] of the x-y polyline followed
  double solution_length = 0.0;      // SE(2) metric, before simplification
  double simplified_solution_length = 0.0;
  double solution_clearance = 0.0;   // [m]
  double simplification_time = 0.0;  // [s]
  int graph_states = 0;
  int graph_motions = 0;
  int iterations = 0;
  std::vector<Eigen::Vector3d> route;  // waypoints (x, y, yaw), empty without a solution
};

// What a walk to a goal adds to its run (datasets/SCHEMA.md: /runs/<name>/plans and the goal
// attributes); the goal itself is the scenario's.
struct GoalOutcome {
  bool goal_reached = false;
  double time_to_goal = 0.0;  // [s], NaN when not reached
  Eigen::Vector3d final_pose = Eigen::Vector3d::Zero();
  double final_distance = 0.0;   // [m]
  double final_yaw_error = 0.0;  // [rad]
  std::string outcome;           // "reached" or why not
  std::string status_codes;      // "0=exact_solution, ..."
  std::string trigger_codes;     // "0=start, ..."
  std::vector<RoutePlanRecord> plans;
};

// The statistics of the control chain's wall time per NMPC iteration
// (MultibodyValidation::chain_time) that /runs/<name>/timing holds as attributes
// (chain_time_average, _std, _min, _max) [s]. The caller computes them (analysis/:
// wpg::analysis::chainTiming): datasets/ stores statistics, it does not compute them.
struct ChainTimeSummary {
  double average = 0.0;
  double std_dev = 0.0;  // sample standard deviation (k - 1 denominator)
  double min = 0.0;
  double max = 0.0;
};

// A walk's multibody replay and dynamic filter as the caller computed them (robots/:
// wpg::robots::replayWalk; datasets/ does not link Simbody), with its chain timing's summary.
struct MultibodyRecord {
  const wpg::MultibodyValidation& validation;
  ChainTimeSummary chain_time;
};

namespace detail {
class GroupImage;  // datasets/storage/src/hdf5_image.hpp
}

// A run built ahead of writing (BatchDatasetWriter::prepare: its whole group; or the walk's
// datasets, prepareWalkDatasets): its attributes and groups, and its datasets' chunks
// compressed (most of the writing time), without any HDF5 call, where there is a core to
// spare; the writer only commits it to the file, under the HDF5 lock.
struct PreparedRun {
  std::shared_ptr<const detail::GroupImage> image;
  // The walk's part (prepareWalkDatasets): the sizes of what it was built from, so that
  // writeRunDataset refuses the part of another walk (std::logic_error).
  std::size_t samples = 0, iterations = 0, footsteps = 0, obstacles = 0;
};

// Writes `result` of `scenario` to `path` (group /runs/<scenario.name>), atomically: the file
// is written as a temporary file created exclusively under an unpredictable name in the same
// folder (TemporaryOutput, output_file.hpp), then renamed over `path`; on any error, SIGINT or
// SIGTERM the temporary file is removed and `path` is left as it was. Creates the parent
// directory when missing. The caller checks `path` first (checkOutputPath).
//
// The scenario's obstacles go to /runs/<name>/obstacles/, the footstep clearances to
// /runs/<name>/checks/ (when the scenario has obstacles; `clearances` may be null, then only
// the step centres are checked).
//
// `multibody` (may be null: not replayed), the multibody replay and the dynamic filter of the
// walk, adds q, zmp_multibody (and com_filtered, zmp_multibody_filtered when filtered) to
// the run group, the ZMP error and IK summary to /runs/<name>/multibody/ and the timing
// profile of the control chain to /runs/<name>/timing/.
//
// Throws std::invalid_argument when the trajectory's per-sample arrays differ in length, a
// column of `clearances` does not have one entry per footstep, a matrix of `multibody` does
// not have one row per sample (q: one column per configuration name; the filtered pair both
// empty or both n rows), chain_time and chain_stage_time (k x 4) disagree, or the scenario name
// cannot be an HDF5 group name; std::runtime_error on I/O errors (message names the path).
//
// `goal` (may be null: not a goal walk, or a goal walk replayed from its dataset, whose plans
// are not read back) adds the goal's attributes and the /runs/<name>/plans group; only for a
// scenario with a goal.
//
// `prepared` (may be null): the walk's datasets compressed ahead (prepareWalkDatasets, of
// this scenario and result); written as they are, the rest compressed here.
void writeRunDataset(const std::string& path, const Scenario& scenario,
                     const wpg::WalkResult& result, const FootstepClearances* clearances = nullptr,
                     const MultibodyRecord* multibody = nullptr,
                     const GoalOutcome* goal = nullptr, const PreparedRun* prepared = nullptr);

// The walk's datasets of a run file (the trajectory, the NMPC log, the obstacles: the first
// the writer writes), built without the file and without an HDF5 call, so that any thread may
// build them at any time: `wpg run` does it on a second core while the replay runs, and
// writeRunDataset then commits them as they are. The same bytes as built there.
PreparedRun prepareWalkDatasets(const Scenario& scenario, const wpg::WalkResult& result);

// Debian's HDF5 is built without thread safety: every use of the HDF5 library in this process
// (writeRunDataset takes it itself) must hold this lock, e.g. when batch workers write files.
std::mutex& hdf5Mutex();

}  // namespace wpg::datasets
