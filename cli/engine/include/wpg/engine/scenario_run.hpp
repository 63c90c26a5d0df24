#pragma once
// Resolved scenarios run on N worker threads, outcomes handed over in list order: the runner
// of `wpg batch`, for any command that runs many scenarios (a push sweep, `wpg compare`). Each
// run is the pipeline of `wpg run` (pipeline_stages.hpp) without the file: runScenario (the
// walk, to a goal or on a velocity command, the multibody replay and the filter, offline or
// online, when the scenario asks), the FCL footstep check with obstacles,
// and the metrics of analysis/. Every worker builds its own problem (generateWalk constructs
// the NMPC per call) and loads its own robot model; nothing a run writes is shared.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "pipeline_stages.hpp"
#include "wpg/analysis/run_metrics.hpp"
#include "wpg/datasets/input/scenario.hpp"

namespace wpg::cli {

class BatchProgress;

struct ScenarioOutcome {
  WalkResult result;
  std::optional<datasets::GoalOutcome> goal;    // a walk to a goal: its plans and outcome
  std::optional<ReplayOutcome> replay;          // when the scenario replays
  std::optional<FootstepCheck> footsteps;       // when it has obstacles
  analysis::RunMetrics metrics;
  int exit_status = kExitSuccess;  // kExitSuccess, or kExitRunFailed when the walk failed
  std::string failure;             // why it failed (one line), empty on success
};

// The robot models one worker has loaded, by robot name.
using RobotModelCache = std::map<std::string, std::unique_ptr<robots::RobotModel>>;

// One scenario through the pipeline; `models` caches the robot models of this worker.
ScenarioOutcome runScenarioPipeline(const datasets::Scenario& scenario, RobotModelCache* models);

// Runs `scenarios` on `threads` workers; `in_worker(position, outcome)` (may be empty) right
// after each run on the worker that ran it, in parallel (the heavy, thread-safe part of the
// caller's handling: compressing its datasets); `deliver(position, outcome)` in list order, one
// call at a time; `progress` (may be null) counts each run as it is delivered. Exceptions of
// either (an I/O error of the writer) stop the batch and are rethrown.
void runScenarios(const std::vector<const datasets::Scenario*>& scenarios, int threads,
                  BatchProgress* progress,
                  const std::function<void(std::size_t position, ScenarioOutcome& outcome)>& in_worker,
                  const std::function<void(std::size_t position, ScenarioOutcome&& outcome)>& deliver);

}  // namespace wpg::cli
