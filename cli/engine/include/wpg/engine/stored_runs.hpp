#pragma once
// What the engine does with runs already in a file: their metrics recomputed from the stored
// walks (`wpg analyze`), and a stored walk replayed on the multibody model with the dynamic
// filter (`wpg replay`). Each stored run is checked against its stored scenario first
// (datasets::checkStoredRunMatchesScenario): bad files are datasets::InputError, one line.
#include <string>
#include <vector>

#include "wpg/analysis/run_metrics.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/storage/run_dataset_reader.hpp"
#include "wpg/engine/scenario_run.hpp"
#include "wpg/robots/robot_model.hpp"

namespace wpg::engine {

// The metrics of every run of a run or batch file (datasets/METRICS.md), by run name, in the
// file's order; the ZMP errors are the stored ones (the walks are not replayed again).
struct StoredRunMetrics {
  std::string name;
  analysis::RunMetrics metrics;
};
std::vector<StoredRunMetrics> analyzeRunFile(const std::string& path,
                                             const std::string& robots_directory);

// One run of a file (`name` as datasets::readRunDataset takes it): the stored walk, its stored
// scenario (the walk checked against it) and the metrics recomputed from them, with the stored
// ZMP errors.
struct StoredRunAnalysis {
  datasets::StoredRun stored;
  datasets::Scenario scenario;
  analysis::RunMetrics metrics;
};
StoredRunAnalysis analyzeStoredRun(const std::string& path, const std::string& name,
                                   const std::string& robots_directory);

// The run of a run file with its stored scenario, the replay switched on (and the filter when
// `filter`, offline: a stored walk cannot be filtered while it is generated): the scenario the
// rewritten dataset stores. `origin` ("RUN.h5:/scenario") names it in messages.
struct StoredRunReplay {
  std::string path;  // the run file
  datasets::StoredRun stored;
  datasets::Scenario scenario;
  std::string origin;
};
StoredRunReplay loadRunForReplay(const std::string& path, bool filter,
                                 const std::string& robots_directory);

// The stored walk replayed (and filtered when the scenario says so): a result whose walk is the
// stored one. Throws datasets::InputError when the replay cannot follow it (fewer than 3
// samples, values that are not finite): there is nothing to write.
RunResult replayStoredRun(const StoredRunReplay& run, const robots::RobotModel& model,
                          int replay_threads = 1);

}  // namespace wpg::engine
