#pragma once
// A run's result as the batch writer takes it (datasets::BatchRunRecord), for the executors.
#include <optional>

#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/engine/scenario_run.hpp"

namespace wpg::engine {

// Points into `result` (and the replay's record it holds): lives no longer than `result`.
class BatchRunRecordOf {
 public:
  BatchRunRecordOf(const datasets::StudyRun& run, const RunResult& result) {
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
