#pragma once
// One scenario end to end, as `wpg run`, every run of `wpg batch` and `wpg compare` and every
// walk of the push search run it: the walk (to a goal, or on a velocity command), its replay on
// the multibody model and the dynamic filter (offline or online) when the scenario asks, the
// footsteps against the obstacles (FCL world), the checks a dataset holds and the metrics of
// analysis/. runScenario prints nothing and never exits: bad input is a datasets::InputError,
// a walk that failed is a result (RunResult::outcome). The dataset of a result is written by
// writeRunDataset below.
#include <optional>
#include <string>

#include "wpg/analysis/run_metrics.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/storage/dataset_checks.hpp"
#include "wpg/engine/pipeline_stages.hpp"
#include "wpg/engine/robot_models.hpp"

namespace wpg::engine {

struct RunSettings {
  // The robots directory (robots/): the multibody models of a scenario that replays.
  std::string robots_directory;
  // Models already loaded (one cache per worker thread), used instead of loading them again;
  // may be null: runScenario then loads the model it needs from robots_directory.
  RobotModelCache* models = nullptr;
  // Threads of the validation replay of this one walk (WalkReplaySettings::threads): a single
  // run may use every core; a study's workers keep 1. The results do not depend on it.
  int replay_threads = 1;
};

// How a run ended. Not kSucceeded: the walk and what was computed of it are still a result
// (and a dataset), with exit status 1.
enum class RunOutcome {
  kSucceeded,
  kWalkFailed,    // the walk failed (an NMPC iteration failed, the robot fell, ...)
  kReplayFailed,  // the walk succeeded, the replay or the filter could not follow it
  // The robot stopped making progress along its command and had not resumed at the end
  // (WalkResult::blocked, libwpg's progress_monitor.hpp), whatever else failed the walk.
  kBlocked,
};
// "succeeded", "walk_failed", "replay_failed", "blocked"
const char* runOutcomeName(RunOutcome outcome);
// The outcome of a walk before any replay: kSucceeded, kBlocked or kWalkFailed.
RunOutcome walkOutcome(const WalkResult& walk);

struct RunResult {
  // The walk: walk.result (trajectory, success, message: a failed replay is recorded there
  // too, as the dataset stores it) and, for a walk to a goal, its plans and outcome.
  WalkOutcome walk;
  std::optional<ReplayOutcome> replay;     // when the scenario replays and the replay succeeded
  std::optional<FootstepCheck> footsteps;  // the FCL world's sole clearances, with obstacles
  datasets::DatasetChecks checks;          // what the dataset's `checks` group holds
  analysis::RunMetrics metrics;            // datasets/METRICS.md
  RunOutcome outcome = RunOutcome::kSucceeded;
  std::string failure;  // why it failed (one line), empty on success
  // The walk's datasets compressed while the replay ran (WalkAndReplay), for writeRunDataset.
  std::optional<datasets::PreparedRun> prepared_walk;

  // 0 when it succeeded, else 1: `wpg run`'s exit status and /batch/summary's exit_status.
  int exitStatus() const { return outcome == RunOutcome::kSucceeded ? 0 : 1; }
};

// Runs `scenario` (loaded and checked by datasets/input; checkRunInput, run_input_checks.hpp,
// checks the rest). Throws datasets::InputError, naming the scenario's file, for input that
// cannot run (no robot model, parameters the generator rejects).
RunResult runScenario(const datasets::Scenario& scenario, const RunSettings& settings);

// The rest of a result whose walk (and replay) are set: its outcome from the walk's success
// and blocked (kSucceeded, kBlocked or kWalkFailed), the FCL footstep check, the dataset checks
// and the metrics.
void evaluateRun(const datasets::Scenario& scenario, RunResult& result);

// The dataset of `result` (run dataset, datasets/SCHEMA.md) at `path`, atomically, as
// datasets::writeRunDataset (which see for the errors), with the result's footstep clearances,
// replay and goal outcome.
void writeRunDataset(const std::string& path, const datasets::Scenario& scenario,
                     const RunResult& result);

// What the velocity metrics of the scenario's walk are measured against (datasets/METRICS.md):
// the path follower's commands for a walk to a goal, else the scenario's reference.
inline analysis::VelocityReference velocityReferenceOf(const datasets::Scenario& scenario) {
  return scenario.goal.enabled ? analysis::VelocityReference::kIterationCommands
                               : analysis::VelocityReference::kSchedule;
}

// What a dataset stores of a replay: the replay and its chain timing's summary (analysis/).
datasets::MultibodyRecord multibodyRecordOf(const ReplayOutcome& replay);

}  // namespace wpg::engine
