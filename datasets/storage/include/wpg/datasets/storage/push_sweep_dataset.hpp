#pragma once
// The file of `wpg push-sweep` (paper Sec. V-B): one table, one row per
// situation x direction x phase, with the largest push force the walk recovers from
// (datasets/SCHEMA.md, "Push sweep files"). Written atomically (temporary file, then rename).
#include <string>
#include <vector>

namespace wpg::datasets {

struct PushSweepRow {
  std::string situation;  // "forward" or "on_spot"
  std::string direction;  // "sagittal+", "sagittal-", "coronal+", "coronal-"
  std::string scenario;   // the scenario that replays the row's push (shipped name or file)
  double phase = 0.0;     // fraction of the step period since the swing foot's lift-off
  double t = 0.0;         // [s] push start
  double force = 0.0;     // [N] largest recovered force, signed along the direction's axis
  double fx = 0.0, fy = 0.0;  // [N] the same as a world-frame vector
  double impulse = 0.0;   // [N s] force x duration
  double duration = 0.1;  // [s] of the push
  bool at_upper_bound = false;  // the search's upper bound itself was recovered
  int walks = 0;          // walks the search generated for this row
  // The swing foot's peak speed [m/s] and acceleration [m/s^2] of the walk at `force`
  // (checks/swing_foot_*_max of that run; 0 when no force was recovered).
  double swing_speed_max = 0.0, swing_acceleration_max = 0.0;
};

struct PushSweepFile {
  std::vector<PushSweepRow> rows;
  std::vector<std::string> situations;       // in the order of `scenarios`
  std::vector<std::string> scenarios;        // each situation's resolved base scenario (YAML)
  std::vector<double> step_lift_off;         // [s] the lift-off of each situation's swept step
  std::vector<std::string> overrides;        // --set, applied to every base scenario
  double max_force = 0.0;                    // [N] the search's upper bound
  double tolerance = 0.0;                    // [N] the search's bracket width at the end
  double stronger_factor = 1.15;             // a push this much stronger than `force` fails
  double max_swing_speed = 0.0;              // [m/s] swing-foot limit of "recovered" (0: none)
  double max_swing_acceleration = 0.0;       // [m/s^2] the same for its acceleration
};

// Throws std::runtime_error when the file cannot be written (nothing left behind).
void writePushSweepFile(const std::string& path, const PushSweepFile& file);

}  // namespace wpg::datasets
