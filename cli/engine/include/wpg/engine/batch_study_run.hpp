#pragma once
// A batch study end to end, as `wpg batch` and wpg.batch run it: the study file expanded into
// runs (datasets/SCENARIOS.md, "Studies"), every input and every output checked before any work
// (the batch file, OUT.summary.csv and OUT.summary.md beside it, OUT.summary.png when the front
// end draws it; a shard file alone for a slice), the runs on threads or MPI ranks into the batch
// file (datasets/SCHEMA.md, "Batch files"), then the summary files. The front end parses,
// draws the figure and prints; it checks nothing itself.
#include <cstddef>
#include <string>

#include "wpg/engine/study_request.hpp"
#include "wpg/engine/study_summary.hpp"

namespace wpg::engine {

struct BatchStudyResult {
  // This process holds the whole batch file and wrote its summary files: false on an MPI rank
  // other than 0 and for a slice.
  bool complete = false;
  std::size_t runs = 0;        // runs of the study
  std::size_t slice_runs = 0;  // with a slice: its runs
  BatchSummaryFiles summary;   // when complete (runs, failed runs, the CSV and Markdown files)
  std::string figure;          // when complete and the request draws figures: OUT.summary.png
};

// Throws datasets::InputError, nothing written, for bad input (the request, the study, an
// output that may not be written, a batch file in use or of another study to resume); an error
// while running (I/O) stops the study and is rethrown, the runs written so far kept for a resume.
// `observer` hears the study accepted (with its warnings) and its progress.
BatchStudyResult runBatchStudy(const StudyRequest& request, StudyObserver& observer);

}  // namespace wpg::engine
