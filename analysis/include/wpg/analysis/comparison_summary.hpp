#pragma once
// The table of a comparison study (`wpg compare`): one row per world x variant, from the runs
// of its seeds. Each column is defined once here, with its unit; datasets/SCHEMA.md
// ("Comparison studies") describes them for readers of study.h5 and summary.csv.
#include <string>
#include <vector>

namespace wpg::analysis {

// Below -kMarginTolerance [m] a step centre is inside a margin (the FCL check's rounding is far
// smaller): counted in margin_entered, and never printed as 0.
inline constexpr double kMarginTolerance = 1e-9;

// What one run of a comparison contributes to its cell.
struct ComparisonRunSample {
  bool goal_reached = false;
  bool blocked = false;             // the walk ended blocked (WalkResult::blocked)
  double time_to_goal = 0.0;        // [s], NaN when not reached
  double walked_length = 0.0;       // [m] horizontal CoM path
  double route_length = 0.0;        // [m] the first plan's route (the straight line without a planner), NaN without a route
  double steps = 0.0;               // [1] landed footsteps
  double clearance_min = 0.0;       // [m] least step-centre clearance to the margins (FCL check), NaN without obstacles
  int replans = 0;                  // plans after the first
  std::vector<double> planning_times;   // [s] every plan's solve() wall time
  std::vector<double> nmpc_solve_times; // [s] every NMPC iteration's wall time
};

// One row of the table.
struct ComparisonCell {
  std::string world, variant;
  double runs = 0.0;                  // [1]
  double reached = 0.0;               // [1] runs that reached the goal
  double success_rate = 0.0;          // [1] reached / runs
  double blocked = 0.0;               // [1] runs that ended blocked (stuck, not at the goal)
  double margin_entered = 0.0;        // [1] runs with a step centre inside a margin (clearance < -1e-9 m)
  double time_to_goal_median = 0.0;   // [s] over the runs that reached the goal (NaN: none)
  double time_to_goal_q1 = 0.0;       // [s] 25th percentile
  double time_to_goal_q3 = 0.0;       // [s] 75th percentile (IQR = q3 - q1)
  double walked_length_median = 0.0;  // [m] over every run
  double route_length_median = 0.0;   // [m] over the runs with a route
  double steps_median = 0.0;          // [1]
  double clearance_min = 0.0;         // [m] least over every run
  double replans_mean = 0.0;          // [1]
  double replans_max = 0.0;           // [1]
  double planning_time_median = 0.0;  // [s] over every plan of every run (NaN: no planner)
  double planning_time_max = 0.0;     // [s]
  double nmpc_time_median = 0.0;      // [s] over every NMPC iteration of every run
  double nmpc_time_p99 = 0.0;         // [s] 99th percentile
};

ComparisonCell summarizeComparisonCell(const std::string& world, const std::string& variant,
                                       const std::vector<ComparisonRunSample>& runs);

// The numeric columns in table order: name, unit, whether it is a wall time (differs between
// two runs of the same study), the field.
struct ComparisonColumn {
  const char* name;
  const char* unit;
  bool wall_time;
  double ComparisonCell::*field;
};
const std::vector<ComparisonColumn>& comparisonColumns();

}  // namespace wpg::analysis
