#pragma once
// The measurement behind `wpg bench`, the paper's Sec. V-C table: a scenario run in the online
// loop of Fig. 3 (WPG + dynamic filter + IK), with the wall time of each 5 ms control tick and of
// its stages (analysis/chain_timing.hpp computes the numbers).
#include <string>

#include "wpg/analysis/chain_timing.hpp"
#include "wpg/analysis/zmp_error.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/robots/robot_model.hpp"

namespace wpg::engine {

struct ControlChainTiming {
  std::string name;                  // the scenario's
  analysis::TickTiming ticks;        // [s] per control period
  double walk_duration = 0.0;        // [s]
  double loop_wall_time = 0.0;       // [s] the whole online loop (walk, filter, validation)
  double real_time_factor = 0.0;
  int ticks_over_period = 0;         // NMPC ticks longer than the control period
  double control_period = 0.0;       // [s]
  analysis::ZmpErrorComparison zmp;  // [m]
  int ik_failures = 0;
  bool walk_success = true;
};

// The scenario in the paper's loop, whatever its filter mode (the online filter is the one that
// runs in the control period), with the paper's preview of one step (Sec. V-A). Throws
// std::runtime_error when the loop cannot replay the walk (nothing to time).
ControlChainTiming measureControlChain(const datasets::Scenario& scenario,
                                       const robots::RobotModel& model);

}  // namespace wpg::engine
