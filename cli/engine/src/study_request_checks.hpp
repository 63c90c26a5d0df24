#pragma once
// What runBatchStudy and runComparisonStudy share: the request's own checks, its input and
// output checks run where MPI may be starting, the runs' warnings, and the executor to run on.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "wpg/datasets/study_design/study.hpp"
#include "wpg/engine/mpi_executor.hpp"
#include "wpg/engine/study_request.hpp"

namespace wpg::engine {

// The request itself, before its study file is read: jobs >= 1, an output (`what_output`
// says what it is: "the batch file to write (OUT.h5)"), no shard under an MPI launcher, the
// study a file. Throws datasets::InputError naming the field as the front end calls it.
void checkStudyRequest(const StudyRequest& request, const std::string& what_output);

// Runs `check` (load the study, check every input and output: nothing written yet) on this
// process, or while MPI starts when the request may use it (checkInputWhileMpiStarts); returns
// the MPI world the study then runs on, if any.
std::optional<MpiWorld> checkStudyInput(const StudyRequest& request,
                                        const std::function<void()>& check);

// The checked runs' scenario warnings (every run's in a study of at most kCheckedStudyRuns), in
// study order.
std::vector<std::string> studyWarnings(const datasets::Study& study);

// The executor of the request: the ranks of `world` (one worker per rank unless jobs was
// given), else request.jobs threads.
std::unique_ptr<StudyExecutor> makeStudyExecutor(const StudyRequest& request,
                                                 const std::optional<MpiWorld>& world);

// How many of the study's runs slice `slice` holds.
std::size_t sliceRuns(const datasets::Study& study, const ShardSlice& slice);

}  // namespace wpg::engine
