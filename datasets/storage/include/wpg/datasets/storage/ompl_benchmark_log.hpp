#pragma once
// Benchmark logs in the format of OMPL's benchmarking tools (ompl::tools::Benchmark's log
// files, "The benchmark logfile format" of OMPL's documentation), so that OMPL's
// ompl_benchmark_statistics.py and Planner Arena read the comparison studies of `wpg compare`:
// one experiment (file) per world, one planner per variant, one run per seed. Written by
// `wpg compare ... --ompl-log DIR` (docs/viewer.md, "OMPL benchmark logs").
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace wpg::datasets {

// A property is named "<name> <TYPE>" (TYPE: REAL, INTEGER, BOOLEAN or ENUM, the last word),
// its value text: a number, "nan", "inf" or "" (not measured).
using BenchmarkValue = std::pair<std::string, std::string>;

struct BenchmarkPlanner {
  std::string name;
  std::vector<BenchmarkValue> common;  // "name" = value lines: the planner's settings
  std::vector<std::string> properties;                // run properties "<name> <TYPE>", sorted
  std::vector<std::vector<std::string>> runs;         // one value per property, per run
};

struct BenchmarkExperiment {
  std::string library = "wpg";      // the version line: "<library> version <version>"
  std::string version;
  std::string name;                 // one word (spaces become '_')
  std::vector<BenchmarkValue> properties;  // experiment properties "<name> <TYPE>" = value
  std::string host, date;
  std::string setup, cpu_info;      // multi-line texts
  long long seed = 0;
  double time_limit = 0.0;          // [s] per run
  double memory_limit = 0.0;        // [MB] per run (0: none)
  long long runs_per_planner = 0;
  double total_time = 0.0;          // [s] spent to collect the data
  std::vector<BenchmarkPlanner> planners;
};

// A number as a log value: the shortest text that reads back the same double; "nan", "inf"
// ("nan" for -inf: the format has no negative infinity).
std::string benchmarkNumber(double value);

// OMPL's planner status names in the order of ompl::base::PlannerStatus::StatusType (OMPL
// 1.5): the enum line of every log ("status|Unknown status|...").
const std::vector<std::string>& plannerStatusNames();

// Writes the experiment in OMPL's log format. Throws std::invalid_argument when a run does not
// have one value per property or a name cannot be written on its line (a line break).
void writeBenchmarkLog(std::ostream& out, const BenchmarkExperiment& experiment);

// The experiments of a comparison study file (`wpg compare`'s study.h5): per world, its
// variants with their planner settings (the `planner:` keys of their runs' scenarios) and one
// run per seed: OMPL's run properties from the first plan of the walk (time, status, solved,
// approximate solution, solution length, clearance, segments, simplification, graph states
// and motions) and the walk's (time to goal, steps, least clearance, replans, reached, walked
// length, planning time of every plan, seed). `total_time` is the study's wall time.
// Throws InputError naming the file when it is not a comparison study file.
std::vector<BenchmarkExperiment> comparisonBenchmarkExperiments(const std::string& study_file,
                                                                double total_time);

// Writes one log per experiment into `folder` (<experiment>.log, atomically), returns the paths.
std::vector<std::string> writeBenchmarkLogs(const std::vector<BenchmarkExperiment>& experiments,
                                            const std::string& folder);

}  // namespace wpg::datasets
