#pragma once
// A run's result as the batch writer takes it (datasets::BatchRunRecord), for the executors.
#include <optional>

#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/engine/scenario_run.hpp"

namespace wpg::engine {

// The scenario an executor walks for `run` of `study`: when the study's runs do not store the
// NMPC's plans (a lean study without the field plan, run_fields.hpp), they are not recorded
// either. Recording only copies what each iteration predicted (libwpg's walk_loop.cpp): the walk
// is the same bits (tests/cli/lean_fields.sh), for about a fifth less CPU. A copy: the run keeps
// the study's scenario, whose resolved text its dataset stores.
inline datasets::Scenario scenarioToWalk(const datasets::Study& study,
                                         const datasets::StudyRun& run) {
  datasets::Scenario scenario = run.scenario;
  if (!study.fields.has(datasets::RunField::kPlan)) {
    scenario.request.generator.record_plan = false;
  }
  return scenario;
}

// Points into `result` (and the replay's record it holds): lives no longer than `result`.
class BatchRunRecordOf {
 public:
  // `fields`: the study's (what the batch file's runs store).
  BatchRunRecordOf(const datasets::StudyRun& run, const RunResult& result,
                   datasets::RunFields fields) {
    record_.fields = fields;
    if (result.replay) multibody_.emplace(multibodyRecordOf(*result.replay));
    record_.run = &run;
    record_.result = &result.walk.result;
    record_.clearances = result.footsteps ? &result.footsteps->clearances : nullptr;
    record_.multibody = multibody_ ? &*multibody_ : nullptr;
    record_.goal = result.walk.goal ? &*result.walk.goal : nullptr;
    record_.checks = &result.checks;  // computed by evaluateRun: not again by the writer
    record_.exit_status = result.exitStatus();
  }
  BatchRunRecordOf(const BatchRunRecordOf&) = delete;
  BatchRunRecordOf& operator=(const BatchRunRecordOf&) = delete;

  datasets::BatchRunRecord& record() { return record_; }

 private:
  std::optional<datasets::MultibodyRecord> multibody_;
  datasets::BatchRunRecord record_;
};

}  // namespace wpg::engine
