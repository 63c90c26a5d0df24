// What the Python package asks of the engine, as the `wpg` subcommands ask it (engine_calls.hpp).
#include "engine_calls.hpp"

#include <algorithm>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/yaml_input.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"
#include "wpg/datasets/storage/stored_strings_check.hpp"
#include "wpg/engine/batch_study_run.hpp"
#include "wpg/engine/comparison_study_run.hpp"
#include "wpg/engine/stored_runs.hpp"

namespace wpg::python {
namespace {

engine::StudyRequest studyRequest(const std::string& study, const std::string& output, int jobs,
                                  bool figures) {
  engine::StudyRequest request;
  request.study = study;
  request.output = output;
  request.jobs = jobs;
  request.jobs_given = true;
  request.figures = figures;
  return request;  // the field names are the keyword arguments' (the defaults)
}

// Quiet, as the package is; asks `stop` after each run.
class StoppableObserver : public engine::StudyObserver {
 public:
  explicit StoppableObserver(const StopCheck& stop) : stop_(stop) {}
  void runFinished(bool) override {
    if (stop_) stop_();
  }

 private:
  const StopCheck& stop_;
};

}  // namespace

datasets::Scenario loadOnlineScenario(const std::string& scenario,
                                      const std::vector<std::string>& overrides) {
  const std::string path = resolveScenarioPath(scenario);
  try {
    return datasets::loadScenario(path, overrides, robotsDirectory());
  } catch (const datasets::InputError& e) {
    throw datasets::InputError(datasets::detail::renameOverrides(e.what(), kOverridesName));
  }
}

std::shared_ptr<RunSession> runScenarioFile(const std::string& scenario,
                                            std::vector<std::string> overrides, bool replay,
                                            bool filter) {
  auto run = std::make_shared<RunSession>();
  engine::RobotModelCache models(robotsDirectory());
  run->loaded = engine::loadScenarioRequest(
      {scenario, std::move(overrides), replay, filter, kOverridesName}, models);
  run->result = engine::runScenario(run->loaded.scenario, {robotsDirectory(), &models});
  return run;
}

void saveRun(const RunSession& run, const std::string& path) {
  if (!run.stored_file.empty()) {
    throw datasets::InputError("save: a run read back from '" + run.stored_file +
                               "' is already stored there (wpg.run() gives runs to save)");
  }
  engine::saveRun(run.loaded, run.result, path);
}

void checkStoredStrings(const std::string& path, const std::string& group) {
  datasets::checkStoredStrings(path, group);
}

std::vector<std::string> storedRunNames(const std::string& path) {
  return datasets::listRuns(path);
}

std::shared_ptr<RunSession> loadStoredRun(const std::string& path, const std::string& name) {
  auto run = std::make_shared<RunSession>();
  // As `wpg analyze`: the walk checked against its stored scenario, the metrics recomputed
  // from it with the stored ZMP errors.
  engine::StoredRunAnalysis analyzed = engine::analyzeStoredRun(path, name, robotsDirectory());
  datasets::StoredRun& stored = analyzed.stored;
  run->stored_file = path;
  run->stored_name = stored.name;
  run->loaded.scenario = std::move(analyzed.scenario);
  engine::RunResult& result = run->result;
  result.metrics = std::move(analyzed.metrics);
  result.outcome = engine::walkOutcome(stored.result);
  result.failure = stored.result.message;
  result.walk.result = std::move(stored.result);
  return run;
}

namespace {
// The name of `code` in a `codes` text ("0=start, 1=strayed, ..."), or the code itself.
std::string codeName(const std::string& codes, int code) {
  const std::string key = std::to_string(code) + "=";
  for (std::size_t at = 0; at < codes.size();) {
    const std::size_t end = std::min(codes.find(", ", at), codes.size());
    if (codes.compare(at, key.size(), key) == 0) return codes.substr(at + key.size(), end - at - key.size());
    at = end + 2;
  }
  return std::to_string(code);
}
}  // namespace

std::vector<datasets::StoredRoutePlan> routePlans(const RunSession& run) {
  if (!run.stored_file.empty()) return datasets::readRoutePlans(run.stored_file, run.stored_name);
  std::vector<datasets::StoredRoutePlan> plans;
  if (!run.result.walk.goal) return plans;
  const datasets::GoalOutcome& goal = *run.result.walk.goal;
  for (const datasets::RoutePlanRecord& record : goal.plans) {
    datasets::StoredRoutePlan plan;
    plan.time = record.time;
    plan.trigger = record.trigger;
    plan.status = record.status;
    plan.trigger_name = codeName(goal.trigger_codes, record.trigger);
    plan.status_name = codeName(goal.status_codes, record.status);
    plan.planning_time = record.planning_time;
    plan.route_length = record.route_length;
    plan.solution_length = record.solution_length;
    plan.simplified_solution_length = record.simplified_solution_length;
    plan.solution_clearance = record.solution_clearance;
    plan.simplification_time = record.simplification_time;
    plan.graph_states = record.graph_states;
    plan.graph_motions = record.graph_motions;
    plan.route = record.route;
    plans.push_back(std::move(plan));
  }
  return plans;
}

StudyFiles runBatch(const std::string& study, const std::string& output, int jobs, bool resume,
                    bool figure, const std::optional<std::vector<std::string>>& fields,
                    const StopCheck& stop) {
  engine::StudyRequest request = studyRequest(study, output, jobs, figure);
  request.resume = resume;
  request.fields = fields;
  StoppableObserver observer(stop);
  const engine::BatchStudyResult result = engine::runBatchStudy(request, observer);
  return {output, result.summary.runs, result.summary.failed_runs};
}

StudyFiles runCompare(const std::string& study, const std::string& folder, int jobs,
                      bool figures, const StopCheck& stop) {
  StoppableObserver observer(stop);
  const engine::ComparisonStudyResult result =
      engine::runComparisonStudy(studyRequest(study, folder, jobs, figures), observer);
  return {result.study_file, result.runs, 0};
}

}  // namespace wpg::python
