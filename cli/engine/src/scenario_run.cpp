// Resolved scenarios on N worker threads (scenario_runner.hpp).
#include "scenario_run.hpp"

#include <exception>

#include "batch_progress.hpp"
#include "ordered_parallel.hpp"
#include "wpg/analysis/zmp_error.hpp"

namespace wpg::cli {

ScenarioOutcome runScenarioPipeline(const datasets::Scenario& scenario, RobotModelCache* models) {
  ScenarioOutcome outcome;
  const robots::RobotModel* robot = nullptr;
  if (scenario.replay) {
    auto model = models->find(scenario.robot);
    if (model == models->end()) {
      model = models->emplace(scenario.robot, std::make_unique<robots::RobotModel>(
                                                  loadRobotModel(scenario.robot)))
                  .first;
    }
    robot = model->second.get();
  }
  try {
    ScenarioRun run = runScenario(robot, scenario);
    outcome.result = std::move(run.walk.result);
    outcome.goal = std::move(run.walk.goal);
    outcome.replay = std::move(run.replay);
  } catch (const std::runtime_error& e) {  // a walk too short to replay: a failed run
    WalkOutcome walk = runScenarioWalk(scenario);
    outcome.result = std::move(walk.result);
    outcome.goal = std::move(walk.goal);
    outcome.exit_status = kExitRunFailed;
    outcome.failure = e.what();
  }
  if (!outcome.result.success) {
    outcome.exit_status = kExitRunFailed;
    if (outcome.failure.empty())
      outcome.failure = outcome.result.message.empty() ? "the walk failed" : outcome.result.message;
  }
  outcome.footsteps = checkScenarioFootsteps(scenario, outcome.result);
  analysis::ZmpErrorComparison zmp;
  if (outcome.replay) zmp = analysis::compareZmpError(outcome.replay->validation);
  outcome.metrics =
      analysis::computeRunMetrics(scenario.walking, scenario.request, outcome.result.trajectory,
                                  outcome.result.success, outcome.replay ? &zmp : nullptr);
  return outcome;
}

void runScenarios(const std::vector<const datasets::Scenario*>& scenarios, int threads,
                  BatchProgress* progress,
                  const std::function<void(std::size_t, ScenarioOutcome&)>& in_worker,
                  const std::function<void(std::size_t, ScenarioOutcome&&)>& deliver) {
  const int workers = threads < 1 ? 1 : threads;
  std::vector<RobotModelCache> models(static_cast<std::size_t>(workers));
  runOrdered<ScenarioOutcome>(
      scenarios.size(), workers,
      [&](std::size_t job, int worker) {
        ScenarioOutcome outcome =
            runScenarioPipeline(*scenarios[job], &models[static_cast<std::size_t>(worker)]);
        if (in_worker) in_worker(job, outcome);
        return outcome;
      },
      [&](std::size_t job, ScenarioOutcome&& outcome) {
        const bool failed = outcome.exit_status != kExitSuccess;
        deliver(job, std::move(outcome));
        if (progress) progress->runFinished(failed);
      });
}

}  // namespace wpg::cli
