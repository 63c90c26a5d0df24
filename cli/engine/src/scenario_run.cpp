// One scenario end to end (scenario_run.hpp).
#include "wpg/engine/scenario_run.hpp"

#include <optional>
#include <stdexcept>
#include <string>

#include "wpg/analysis/chain_timing.hpp"
#include "wpg/analysis/zmp_error.hpp"
#include "wpg/datasets/input/input_error.hpp"

namespace wpg::engine {

const char* runOutcomeName(RunOutcome outcome) {
  switch (outcome) {
    case RunOutcome::kSucceeded: return "succeeded";
    case RunOutcome::kWalkFailed: return "walk_failed";
    case RunOutcome::kReplayFailed: return "replay_failed";
    case RunOutcome::kBlocked: return "blocked";
  }
  return "unknown";
}

RunOutcome walkOutcome(const WalkResult& walk) {
  if (walk.success) return RunOutcome::kSucceeded;
  return walk.blocked ? RunOutcome::kBlocked : RunOutcome::kWalkFailed;
}

RunResult runScenario(const datasets::Scenario& scenario, const RunSettings& settings) {
  const robots::RobotModel* model = nullptr;
  std::optional<RobotModelCache> own_models;
  if (scenario.replay) {
    RobotModelCache* models = settings.models;
    if (!models) models = &own_models.emplace(settings.robots_directory);
    model = &models->model(scenario.robot, scenario.multibody);
  }
  WalkAndReplay run;
  try {
    run = runWalkAndReplay(model, scenario, settings.replay_threads);
  } catch (const std::invalid_argument& e) {  // parameters the generator rejects: bad input
    const std::string message = e.what();
    throw datasets::InputError(message.find(scenario.source_path) != std::string::npos
                                   ? message
                                   : scenario.source_path + ": " + message);
  }
  RunResult result;
  result.walk = std::move(run.walk);
  result.replay = std::move(run.replay);
  result.prepared_walk = std::move(run.prepared_walk);
  evaluateRun(scenario, result);
  if (result.outcome == RunOutcome::kWalkFailed && !run.replay_failure.empty() &&
      run.walk_succeeded) {
    result.outcome = RunOutcome::kReplayFailed;
  }
  return result;
}

void evaluateRun(const datasets::Scenario& scenario, RunResult& result) {
  const WalkResult& walk = result.walk.result;
  result.outcome = walkOutcome(walk);
  result.failure = walk.success ? "" : walk.message.empty() ? "the walk failed" : walk.message;
  result.footsteps = checkScenarioFootsteps(scenario, walk);
  result.checks = datasets::computeDatasetChecks(
      scenario, walk.trajectory, result.footsteps ? &result.footsteps->clearances : nullptr);
  analysis::ZmpErrorComparison zmp;
  if (result.replay) zmp = analysis::compareZmpError(result.replay->validation);
  result.metrics =
      analysis::computeRunMetrics(scenario.walking, scenario.request, walk,
                                  result.replay ? &zmp : nullptr, velocityReferenceOf(scenario));
}

datasets::MultibodyRecord multibodyRecordOf(const ReplayOutcome& replay) {
  const analysis::SampleStatistics chain = analysis::chainTiming(replay.validation).per_iteration;
  return {replay.validation, {chain.mean, chain.std_dev, chain.min, chain.max}};
}

void writeRunDataset(const std::string& path, const datasets::Scenario& scenario,
                     const RunResult& result) {
  std::optional<datasets::MultibodyRecord> multibody;
  if (result.replay) multibody.emplace(multibodyRecordOf(*result.replay));
  datasets::writeRunDataset(path, scenario, result.walk.result,
                            result.footsteps ? &result.footsteps->clearances : nullptr,
                            multibody ? &*multibody : nullptr,
                            result.walk.goal ? &*result.walk.goal : nullptr,
                            result.prepared_walk ? &*result.prepared_walk : nullptr);
}

}  // namespace wpg::engine
