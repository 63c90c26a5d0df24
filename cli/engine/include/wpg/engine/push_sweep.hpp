#pragma once
// The paper's push-recovery test (Sec. V-B) behind `wpg push-sweep`: for each walking situation
// (a base scenario with its push replaced), each direction (sagittal +/-, coronal +/-) and K
// phases spread over one steady step, the largest recovered force of a 100 ms push
// (push_recovery_search.hpp). One search per job on worker threads (ordered_parallel.hpp): the
// same numbers for any number of threads.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/storage/push_sweep_dataset.hpp"
#include "wpg/engine/push_recovery_search.hpp"

namespace wpg::engine {

// A walking situation of the push test: a base scenario whose pushes[0] is replaced by the
// swept push, and the step over which the phases are spread.
struct PushSituation {
  std::string name;      // "forward" or "on_spot"
  std::string scenario;  // the argument that replays it: a shipped name or a scenario file
  datasets::Scenario base;
  double lift_off = 0.0;      // [s] lift-off of the swept step (of the unpushed walk)
  double step_period = 0.0;   // [s] single + double support
};

// The situation `name` of `base` (loaded from `scenario`, which names it in messages): the
// unpushed walk (pushes[0] removed) is run to find the swept step, the third lift-off, where the
// gait is periodic, with at least 2 s of walk after its last push. Throws datasets::InputError
// when the base is a walk to a goal, fails without its push, takes too few steps or ends too
// soon after the swept step.
PushSituation preparePushSituation(const std::string& name, const std::string& scenario,
                                   const datasets::Scenario& base,
                                   const std::string& robots_directory);

// Runs the sweep: situation x direction x phase (`phases` phases over the swept step, push
// starts rounded to 1 ms), in that order, on `threads` workers; `finished()` (may be empty) after
// each row, in order. Returns the rows of the table (datasets/SCHEMA.md, "Push sweeps").
std::vector<datasets::PushSweepRow> runPushSweep(const std::vector<PushSituation>& situations,
                                                 int phases, const PushSearchSettings& settings,
                                                 int threads, const std::string& robots_directory,
                                                 const std::function<void()>& finished);

// The shortest decimal text that reads back as the same double (the sweep's JSON, its
// messages); "null" for NaN.
std::string shortestNumber(double value);

}  // namespace wpg::engine
