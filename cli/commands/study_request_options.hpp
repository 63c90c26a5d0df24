#pragma once
// The engine's study request (study_request.hpp) from the options of `wpg batch` or `wpg
// compare`: their shared options converted, the fields named as the options are, so that the
// engine's messages about a bad value name the option the user typed.
#include "shard_option.hpp"
#include "wpg/engine/study_request.hpp"

namespace wpg::cli {

// Options: BatchOptions or CompareOptions (command_options.hpp). Throws UsageError for a
// malformed --shard.
template <typename Options>
engine::StudyRequest studyRequestOf(const Options& options) {
  engine::StudyRequest request;
  request.study = options.study;
  request.output = options.output;
  request.jobs = options.threads;
  request.jobs_given = options.threads_given;
  request.resume = options.resume;
  if (!options.shard.empty()) request.shard = parseShardOption(options.shard);
  request.figures = options.plot;
  request.use_mpi = true;  // under an MPI launcher the ranks share the study
  request.names.jobs = "-j";
  request.names.output = "-o";
  request.names.shard = "--shard";
  request.names.ompl_log = "--ompl-log";
  return request;
}

}  // namespace wpg::cli
