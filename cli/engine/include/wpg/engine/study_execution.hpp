#pragma once
// What `wpg batch` and `wpg compare` share once a study is expanded: the per-run columns of
// /batch/summary (NMPC statuses and the metrics of analysis/), running the study's runs on the
// worker threads into the batch writer (scenario_runner.hpp), the checks of the output place,
// and the summary tables as CSV and Markdown.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "scenario_run.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/study_design/study.hpp"

namespace wpg::cli {

class BatchProgress;

// The result columns of /batch/summary of `wpg batch`: NMPC iterations per status, then every
// metric of analysis::runMetricTable(); runSummaryValues gives a run's values in that order.
std::vector<datasets::SummaryColumn> runSummaryColumns();
std::vector<double> runSummaryValues(const ScenarioOutcome& outcome);

// Runs `runs` on `threads` workers (their datasets compressed on the workers) and writes each
// into `writer` in study order with `values(run, outcome)` as its summary row; `delivered(run,
// outcome)` (may be empty) then sees each outcome, one at a time, in order.
void runStudyInto(const std::vector<const datasets::StudyRun*>& runs, int threads,
                  BatchProgress* progress, datasets::BatchDatasetWriter* writer,
                  const std::function<std::vector<double>(const datasets::StudyRun&,
                                                          const ScenarioOutcome&)>& values,
                  const std::function<void(const datasets::StudyRun&, const ScenarioOutcome&)>&
                      delivered);

// The runs of one rank of a distributed study (distributed_study.hpp), pulled one at a time:
// `next(finished, report)` gets the run the calling worker just finished (null at its first
// call) with `report(*finished, outcome)`, and returns the worker's next run (null: no more).
// Each run goes through the same pipeline as runStudyInto's (runScenarioPipeline, prepare on the
// worker, write with `values`), on `threads` workers, written into `writer` as it finishes: the
// order of the groups in the file differs, not their contents. Exceptions stop the workers and
// the first is rethrown.
using RunSource = std::function<const datasets::StudyRun*(const datasets::StudyRun* finished,
                                                          std::vector<double>&& report)>;
void runStudyPulled(const RunSource& next, int threads, datasets::BatchDatasetWriter* writer,
                    const std::function<std::vector<double>(const datasets::StudyRun&,
                                                            const ScenarioOutcome&)>& values,
                    const std::function<std::vector<double>(const datasets::StudyRun&,
                                                            const ScenarioOutcome&)>& report);

// Throws UsageError unless the nearest existing folder above `output` is a writable directory.
void checkWritableParent(const std::filesystem::path& output);

// A table as text cells (numbers in shortest round-trip form) to CSV, and to Markdown under
// `title` with the paragraph `intro`; units from column_units in the Markdown header.
void writeTableCsv(const datasets::BatchSummaryTable& table, const std::string& path);
void writeTableMarkdown(const datasets::BatchSummaryTable& table, const std::string& path,
                        const std::string& title, const std::string& intro);

}  // namespace wpg::cli
