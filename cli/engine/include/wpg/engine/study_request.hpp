#pragma once
// A study as a front end asks for it (`wpg batch` / `wpg compare`, wpg.batch / wpg.compare): the
// study file, where its outputs go and how to run it. The engine's runBatchStudy
// (batch_study_run.hpp) and runComparisonStudy (comparison_study_run.hpp) take it and own every
// check of it, so that every front end refuses the same input the same way, before any work.
#include <optional>
#include <string>
#include <vector>

#include "wpg/engine/study_executor.hpp"

namespace wpg::engine {

// What a front end calls the request's fields in its messages (an option, a keyword argument):
// a bad value is reported under the name its user typed.
struct RequestFieldNames {
  std::string jobs = "jobs";
  std::string output = "output";
  std::string shard = "shard";
  std::string ompl_log = "ompl_log";
  std::string fields = "fields";
};

struct StudyRequest {
  std::string study;   // the study file (YAML)
  std::string output;  // a batch: the batch file OUT.h5; a comparison: the folder DIR
  int jobs = 1;        // worker threads (per rank under MPI)
  // Whether `jobs` was given: under an MPI launcher the default is 1 worker per rank.
  bool jobs_given = false;
  bool resume = false;  // finish the output of the same study
  std::optional<ShardSlice> shard;  // only this slice, into a shard file (never under MPI)
  // The front end draws the study's figures after it ran (OUT.summary.png; a comparison's
  // success_rates.png, time_to_goal.png, top_<world>.png): their paths are checked with the
  // other outputs, before any work.
  bool figures = false;
  std::string ompl_log;  // a comparison: the folder of its OMPL benchmark logs (empty: none)
  // A batch: what each run stores (run_fields.hpp), instead of the study's `fields:`; none:
  // the study's (every field when it names none).
  std::optional<std::vector<std::string>> fields;
  // Under an MPI launcher the ranks share the study (mpi_executor.hpp); otherwise the study
  // runs on this process's threads whatever launched it.
  bool use_mpi = false;
  RequestFieldNames names;
};

}  // namespace wpg::engine
