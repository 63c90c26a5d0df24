#pragma once
// A comparison study as OMPL benchmark logs, one per world (wpg/datasets/storage/
// ompl_benchmark_log.hpp), for OMPL's ompl_benchmark_statistics.py and Planner Arena: the
// folder checked before the study runs, the logs written from its study file after.
#include <string>
#include <vector>

namespace wpg::engine {

// `folder`/benchmark.db: the logs as the SQLite database Planner Arena opens (the front end
// writes it after the logs, analysis/ompl_benchmark_database.py).
std::string benchmarkDatabasePath(const std::string& folder);

// Before the study runs: `folder` may be created, `folder`/<world>.log and
// `folder`/benchmark.db written. Throws
// datasets::InputError naming the path when not.
void checkBenchmarkLogOutputs(const std::string& folder, const std::vector<std::string>& worlds);

// After it ran: reads `study_file` (the comparison's study.h5) and writes the logs into
// `folder` (created); `seconds`: the study's wall time. Returns the logs' paths. Throws
// datasets::InputError when the folder cannot be created or the file is not a comparison's.
std::vector<std::string> writeComparisonBenchmarkLogs(const std::string& study_file,
                                                      const std::string& folder, double seconds);

}  // namespace wpg::engine
