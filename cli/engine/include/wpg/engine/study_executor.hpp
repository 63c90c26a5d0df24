#pragma once
// A study's runs executed by a pluggable executor: on this process's worker threads
// (makeThreadExecutor) or on the ranks of an MPI job (mpi_executor.hpp). Every run is
// runScenario (scenario_run.hpp) and goes to a batch file (datasets/SCHEMA.md, "Batch files");
// for the same study every executor writes the same runs, bit for bit, whatever the number of
// threads or ranks, and hands the caller each run's report in study order.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/study_design/study.hpp"
#include "wpg/engine/scenario_run.hpp"

namespace wpg::engine {

// Numbers of a finished run: its row of /batch/summary, or what the caller keeps of it (plain
// numbers, so that an MPI rank can send them to rank 0).
using RunNumbers =
    std::function<std::vector<double>(const datasets::StudyRun& run, const RunResult& result)>;

// What becomes of each run besides its group in the batch file.
struct StudyRunHandling {
  std::vector<datasets::SummaryColumn> columns;  // the result columns of /batch/summary
  RunNumbers summary_values;                     // one value per column
  // What the caller keeps of each run (may be empty: nothing), computed where the run ran and
  // given to `collect(run index, report)` on the process whose run() returns true, one call at
  // a time, in study order.
  RunNumbers report;
  std::function<void(std::size_t run, std::vector<double>&& report)> collect;
};

// Slice K of N of a study (`wpg batch --shard K/N`): runs i with i mod N = K
// (datasets::inShardSlice), written into a shard file (batch_index.hpp).
struct ShardSlice {
  int index = 0;
  int count = 1;
};

// Where the study goes.
struct StudyOutput {
  std::string path;  // OUT.h5: the batch file (threads), or the index of the ranks' shards (MPI)
  bool resume = false;  // finish OUT.h5 of the same study: run only the runs not in it yet
  std::optional<ShardSlice> shard;  // threads only: this slice into a shard file
};

// What an executor measured on the ranks of an MPI job (rank 0).
struct RankStatistics {
  int ranks = 1;
  int workers_per_rank = 1;
  std::size_t remote_handouts = 0;   // runs (and "no more") rank 0 handed to other ranks
  double service_seconds = 0.0;      // rank 0's time answering them, summed
  double service_max_seconds = 0.0;
  std::size_t runs = 0;              // runs in the index
  double index_seconds = 0.0;        // writing the index
};

// What the caller hears while a study runs (the CLI prints it). The executor calls it on the
// process that reports progress (rank 0 under MPI), one call at a time; all may be left as is.
class StudyObserver {
 public:
  virtual ~StudyObserver() = default;
  // The study `name` is loaded and every input and output checked, nothing written yet;
  // `warnings`: what its runs' scenarios warn about (a clamped command, ...), run by run.
  // Called by runBatchStudy and runComparisonStudy, on the process that reports (rank 0).
  virtual void accepted(const std::string& name, const std::vector<std::string>& warnings);
  // `file`, which HDF5 cannot read (a process killed inside a write), was moved to `aside`;
  // `shard`: a rank's shard, whose runs are run again (else the batch file: all start again).
  virtual void movedDamagedFile(const std::string& file, const std::string& aside, bool shard);
  // Resuming: `already` of `total` runs are done in `where` (a file or the shards' folder).
  virtual void resuming(std::size_t already, std::size_t total, const std::string& where);
  virtual void started(std::size_t runs_to_do);  // this call runs that many
  virtual void runFinished(bool failed);
  virtual void finished();  // every run of this call finished
  virtual void ranksFinished(const RankStatistics& statistics);  // MPI, once the index is written
  // A rank cannot go on (an I/O error): said before every rank is stopped (exit status 1).
  virtual void rankFailed(int rank, const std::string& what);
};

class StudyExecutor {
 public:
  virtual ~StudyExecutor() = default;
  // Runs the study's runs into `output` (the runs not yet there with `resume`). Returns true on
  // the process that holds the complete output: always with threads, rank 0 under MPI. Throws
  // datasets::InputError, nothing written, when `output` cannot be resumed (another study,
  // another slice); an error while running (I/O) stops the study and is rethrown.
  virtual bool run(const datasets::Study& study, const StudyOutput& output,
                   const StudyRunHandling& handling, StudyObserver& observer) = 0;
};

// `threads` workers in this process, each with its own robot models (from robots_directory);
// the runs are written in study order.
std::unique_ptr<StudyExecutor> makeThreadExecutor(int threads, std::string robots_directory);

}  // namespace wpg::engine
