#pragma once
// The runs of a comparison study file read back (`wpg compare`, its `--resume`, and `wpg merge`
// of its shards): what /compare/summary is computed from (datasets/SCHEMA.md, "Comparison
// studies"), taken from the file alone, so that a study finished in one go, resumed after a
// kill, or merged from shards gives the same table.
#include <string>
#include <vector>

namespace wpg::datasets {

// One row of /batch/summary with the per-plan and per-iteration times of its run group.
struct StoredComparisonRun {
  std::string name, world, variant;  // `name`, `sweep.world`, `sweep.variant`
  double seed = 0.0;                 // `sweep.seed`
  bool done = false;                 // the run is in the file
  // The summary's goal columns (meaningful when done).
  bool goal_reached = false;
  bool blocked = false;  // the metric column `blocked`: the walk ended blocked
  double time_to_goal = 0.0, path_length = 0.0, steps = 0.0, route_length = 0.0;
  double clearance_min = 0.0;  // step_centre_clearance_min
  int replans = 0;
  // plans/planning_time when the run had a planner (plans' `algorithm` not "none"), else empty;
  // mpc/solve_time.
  std::vector<double> planning_times, nmpc_solve_times;
};

// Every row of the study file at `path` (a batch file of `wpg compare`, a shard of one, or an
// index whose runs link into shards), in index order; the run groups of the done rows are read.
// Throws InputError (one line naming the file) when it is not a comparison study file or a
// run of a done row cannot be read.
std::vector<StoredComparisonRun> readComparisonRuns(const std::string& path);

}  // namespace wpg::datasets
