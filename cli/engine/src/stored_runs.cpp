// Runs already in a file: metrics and replay (stored_runs.hpp).
#include "wpg/engine/stored_runs.hpp"

#include <stdexcept>

#include "wpg/analysis/zmp_error.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/stored_run_consistency.hpp"

namespace wpg::engine {

StoredRunAnalysis analyzeStoredRun(const std::string& path, const std::string& name,
                                   const std::string& robots_directory) {
  StoredRunAnalysis run;
  run.stored = datasets::readRunDataset(path, name);
  const datasets::StoredRun& stored = run.stored;
  run.scenario = datasets::loadScenarioText(
      stored.scenario_yaml, path + ":/runs/" + stored.name + "/scenario", {}, robots_directory);
  datasets::checkStoredRunMatchesScenario(path, stored, run.scenario);
  analysis::ZmpErrorComparison zmp;
  if (stored.zmp_error) {
    zmp.filtered = stored.zmp_error->filtered;
    zmp.before.rms = stored.zmp_error->rms_before;
    zmp.before.max = stored.zmp_error->max_before;
    zmp.after.rms = stored.zmp_error->rms_after;
    zmp.after.max = stored.zmp_error->max_after;
  }
  run.metrics = analysis::computeRunMetrics(run.scenario.walking, run.scenario.request,
                                            stored.result, stored.zmp_error ? &zmp : nullptr,
                                            velocityReferenceOf(run.scenario));
  return run;
}

std::vector<StoredRunMetrics> analyzeRunFile(const std::string& path,
                                             const std::string& robots_directory) {
  std::vector<StoredRunMetrics> runs;
  for (const std::string& name : datasets::listRuns(path)) {
    runs.push_back({name, analyzeStoredRun(path, name, robots_directory).metrics});
  }
  return runs;
}

StoredRunReplay loadRunForReplay(const std::string& path, bool filter,
                                 const std::string& robots_directory) {
  StoredRunReplay run;
  run.path = path;
  run.origin = path + ":/scenario";
  run.stored = datasets::readRunDataset(path);
  // The file's resolved scenario, with the replay switched on: the rewritten dataset's
  // scenario says what ran.
  run.scenario = datasets::loadScenarioText(
      run.stored.scenario_yaml, run.origin,
      // A stored walk can only be filtered offline: the online loop (Fig. 3) filters while the
      // walk is generated, and re-initialises the WPG (mode online or both).
      {"replay=true", std::string("filter=") + (filter ? "true" : "false"),
       "filter_settings.mode=offline"},
      robots_directory);
  // A walk the stored scenario did not generate would be replayed at the wrong period.
  datasets::checkStoredRunMatchesScenario(path, run.stored, run.scenario);
  if (run.scenario.name != run.stored.name) {
    throw datasets::InputError(path + ": the run /runs/" + run.stored.name +
                               " does not belong to its scenario '" + run.scenario.name + "'");
  }
  return run;
}

RunResult replayStoredRun(const StoredRunReplay& run, const robots::RobotModel& model,
                          int replay_threads) {
  const WalkTrajectory& walk = run.stored.result.trajectory;
  if (walk.size() < 3) {
    throw datasets::InputError(run.path + ": the run /runs/" + run.stored.name + " has " +
                               std::to_string(walk.size()) + " samples, the replay needs at least 3");
  }
  RunResult result;
  try {
    result.replay =
        replayScenarioWalk(model, run.scenario, walk, run.scenario.filter, replay_threads);
  } catch (const std::runtime_error& e) {
    throw datasets::InputError(run.path + ": " + e.what());
  }
  result.walk.result = run.stored.result;
  evaluateRun(run.scenario, result);
  return result;
}

}  // namespace wpg::engine
