#pragma once
// `wpg compare ... --ompl-log DIR`: the study as OMPL benchmark logs, one per world
// (wpg/datasets/ompl_benchmark_log.hpp), for OMPL's ompl_benchmark_statistics.py and Planner
// Arena. Kept out of compare_command.cpp: the command calls these two functions only.
#include <string>
#include <vector>

namespace wpg::cli {

// Before the study runs: DIR may be created and DIR/<world>.log written (UsageError if not).
void checkOmplLogOutputs(const std::string& folder, const std::vector<std::string>& worlds);

// After it ran: reads the study file and writes the logs; returns their paths.
std::vector<std::string> writeOmplLogs(const std::string& study_file, const std::string& folder,
                                       double seconds);

}  // namespace wpg::cli
