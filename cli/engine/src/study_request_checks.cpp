// The checks and set-up that every study request shares (study_request_checks.hpp).
#include "study_request_checks.hpp"

#include <filesystem>
#include <system_error>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/engine/data_paths.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {

void checkStudyRequest(const StudyRequest& request, const std::string& what_output) {
  const RequestFieldNames& names = request.names;
  if (request.jobs < 1) {
    throw datasets::InputError(names.jobs + ": expected a number of worker threads >= 1, got " +
                               std::to_string(request.jobs));
  }
  if (request.output.empty()) throw datasets::InputError(names.output + ": expected " + what_output);
  if (request.shard && request.use_mpi && mpiLaunched()) {
    throw datasets::InputError(names.shard + ": a slice runs without MPI (one task of a job "
                               "array); under an MPI launcher the ranks share the study among "
                               "themselves");
  }
  std::error_code ec;
  if (!fs::is_regular_file(request.study, ec)) {
    throw datasets::InputError(request.study + ": cannot read the study file: no such file");
  }
}

std::optional<MpiWorld> checkStudyInput(const StudyRequest& request,
                                        const std::function<void()>& check) {
  // A slice is one process, whatever launched it.
  if (request.use_mpi && !request.shard) return checkInputWhileMpiStarts(check);
  check();
  return std::nullopt;
}

std::vector<std::string> studyWarnings(const datasets::Study& study) {
  return study.warnings;
}

std::unique_ptr<StudyExecutor> makeStudyExecutor(const StudyRequest& request,
                                                 const std::optional<MpiWorld>& world) {
  // A rank per core is the usual launch: one worker per rank unless told otherwise.
  if (world) return makeMpiExecutor(*world, request.jobs_given ? request.jobs : 1, robotsDirectory());
  return makeThreadExecutor(request.jobs, robotsDirectory());
}

std::size_t sliceRuns(const datasets::Study& study, const ShardSlice& slice) {
  return datasets::sliceRunCount(study.runs.size(), slice.index, slice.count);
}

}  // namespace wpg::engine
