#pragma once
// Reading what a picture of a run needs beyond the walk itself (readRunDataset): the joint
// angles of the multibody replay, the multibody ZMP, the goal's outcome and the planner's
// routes (layout: datasets/SCHEMA.md). Read by `wpg view`; as strict as readRunDataset: sizes
// checked before anything is allocated, numbers finite, row counts consistent.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/datasets/input/input_error.hpp"

namespace wpg::datasets {

// /runs/<name>/plans/ row i: when, why and with what outcome a route was planned, and the route.
struct StoredRoutePlan {
  double time = 0.0;     // walk time of the plan [s]
  int trigger = 0;       // 0=start, 1=strayed, 2=blocked, 3=retry (the dataset's `codes`)
  int status = 0;        // 0=exact_solution ... 5=invalid_goal (the dataset's `codes`)
  std::string trigger_name, status_name;  // by the datasets' `codes` ("start", "exact_solution")
  double planning_time = 0.0;  // wall time of solve() [s]
  // The statistics named as ompl::tools::Benchmark names its run properties (NaN, or -1 for
  // the counts, when the file does not hold them).
  double route_length = kUnknown, solution_length = kUnknown,
         simplified_solution_length = kUnknown, solution_clearance = kUnknown,
         simplification_time = kUnknown;
  long long graph_states = -1, graph_motions = -1;
  std::vector<Eigen::Vector3d> route;  // x, y, yaw waypoints (empty: no route)

  static constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
};

// The goal attributes of a walk to a goal (/runs/<name>: goal_x, ..., goal_outcome).
struct StoredGoalOutcome {
  double x = 0.0, y = 0.0;
  double yaw = 0.0;             // NaN: no goal yaw
  double tolerance = 0.0;       // [m]
  double yaw_tolerance = 0.0;   // [rad]
  bool reached = false;
  double time_to_goal = 0.0;    // [s], NaN when not reached
  std::string outcome;          // "reached", or why not
};

struct StoredRunScene {
  // q: one row of `q_names.size()` values per sample (row-major), empty when the run was not
  // replayed; the names are the dataset's `names` attribute (base_x ... base_qz, the joints).
  std::vector<std::string> q_names;
  std::vector<double> q;
  // (n, 2) multibody ZMP before / after the dynamic filter, (n, 3) filtered CoM; empty when absent.
  std::vector<double> zmp_multibody, zmp_multibody_filtered, com_filtered;
  std::optional<StoredGoalOutcome> goal;
  std::vector<StoredRoutePlan> plans;
};

// Reads the above from /runs/<run_name> of `path` (a run, batch or index file); `samples` is
// the number of rows of the run's `time` (readRunDataset), which the per-sample datasets must
// have. Holds hdf5Mutex() while it reads. Throws InputError, one line naming the file, the
// dataset or attribute and what was expected.
StoredRunScene readRunScene(const std::string& path, const std::string& run_name,
                            std::size_t samples);

// The plans of /runs/<run_name> alone (empty without a plans/ group), checked as above.
std::vector<StoredRoutePlan> readRoutePlans(const std::string& path, const std::string& run_name);

}  // namespace wpg::datasets
