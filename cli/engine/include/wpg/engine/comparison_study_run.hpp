#pragma once
// A comparison study end to end, as `wpg compare` and wpg.compare run it: the study file
// (datasets/SCENARIOS.md, "Comparison studies": worlds x variants x seeds of walks to a goal),
// every input and every output checked before any work (DIR a folder; DIR/study.h5, summary.csv,
// summary.md and, when the front end draws them, the figures; a slice's shard file
// DIR/study.shards/slice-K-of-N.h5 alone; the OMPL log folder), the runs on threads or MPI
// ranks (comparison_run.hpp), then /compare/summary, summary.csv, summary.md and the OMPL
// benchmark logs. The front end parses, draws the figures and prints; it checks nothing itself.
#include <cstddef>
#include <string>
#include <vector>

#include "wpg/engine/comparison_run.hpp"
#include "wpg/engine/study_request.hpp"

namespace wpg::engine {

struct ComparisonStudyResult {
  // This process holds the whole study file and wrote the table: false on an MPI rank other
  // than 0 and for a slice.
  bool complete = false;
  std::string study_file;  // DIR/study.h5
  std::string runs_file;   // what this process wrote the runs into: study_file, or the slice's
  std::size_t runs = 0;        // runs of the study
  std::size_t slice_runs = 0;  // with a slice: its runs
  // When complete: the table's layout and rows (world-major), its files, the OMPL logs.
  ComparisonLayout layout;
  std::vector<analysis::ComparisonCell> cells;
  ComparisonTableFiles tables;
  std::vector<std::string> ompl_logs;
};

// DIR/study.shards/slice-K-of-N.h5: the shard file of a slice (the folder of an MPI
// comparison's rank shards too; `wpg merge DIR/study.h5 DIR/study.shards` joins them).
std::string comparisonSliceFile(const std::string& folder, const ShardSlice& slice);

// Throws as runBatchStudy (batch_study_run.hpp); also for a world whose scenario is not a walk
// to a goal, an output that is not a folder, and an OMPL log folder with a slice.
ComparisonStudyResult runComparisonStudy(const StudyRequest& request, StudyObserver& observer);

}  // namespace wpg::engine
