#pragma once
// A study on the ranks of an MPI job (`mpirun -np R wpg batch STUDY -o OUT.h5`): every rank
// runs runs handed out one at a time by rank 0 (dynamic scheduling: a slow run keeps one
// worker, not a rank's share) on its worker threads, and writes them into its own shard,
// OUT.shards/rank-<r>.h5 (a batch file of the whole study holding that rank's runs); rank 0
// then writes OUT.h5, the index that links them (batch_index.hpp, as `wpg merge`).
//
// Resume: rank 0 reads the done flags of every shard in OUT.shards/ (of any earlier number of
// ranks); a shard HDF5 cannot open (a rank killed inside a write) is moved to <shard>.damaged
// and its runs are run again; each rank finishes its own shard; only the runs done in no shard
// are handed out. Without resume, OUT.h5 and OUT.shards/rank-*.h5 are removed first.
//
// Built without MPI (WPG_WITH_MPI off) mpiLaunched() is false and nothing else is called.
// Only src/mpi_world.cpp includes <mpi.h>.
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "wpg/engine/study_executor.hpp"

namespace wpg::engine {

struct MpiWorld {
  int rank = 0;
  int size = 1;
};

// Built with MPI and started by an MPI launcher (mpirun, srun, ...: its environment says so).
bool mpiLaunched();

// Runs `check` (loading and checking the input, before anything is written) on another thread
// while MPI starts on this one, when launched; otherwise runs it here and returns nothing.
// Open MPI's start is mostly waiting (0.3-0.6 s measured on a 2-core machine, a fixed cost a
// 2-rank batch of 200 short runs feels), the study's load is CPU: overlapped, they cost the
// longer of the two. When `check` throws on any rank, every rank stops: rank 0 rethrows its
// error, the others throw RankStopped. Throws datasets::InputError when this build has no MPI
// but runs as one of several processes of a launcher (each would run the whole study into the
// same file).
std::optional<MpiWorld> checkInputWhileMpiStarts(const std::function<void()>& check);

// MPI_Finalize, once every rank is there (after the last collective call of the command).
void finishMpi();

// Thrown on the ranks other than 0 when the study cannot go on for a reason rank 0 reports
// (bad input it found, or its error before the runs): MPI is finished, and this process should
// exit quietly with 0, leaving the exit code to rank 0 (a non-zero exit lets mpiexec abort
// rank 0 before it has reported); `badInput()` says which of the two it was.
class RankStopped : public std::exception {
 public:
  explicit RankStopped(bool bad_input) : bad_input_(bad_input) {}
  bool badInput() const { return bad_input_; }
  const char* what() const noexcept override { return "stopped: rank 0 reports why"; }

 private:
  bool bad_input_;
};

// OUT.h5 -> OUT.shards (the folder of the ranks' shards, beside the index).
std::string shardFolderOf(const std::string& index);

// The executor over `world` (collective: every rank calls run() with the same study), with
// `workers_per_rank` worker threads on each rank. run() returns true on rank 0 once OUT.h5 is
// written, false on the others. Bad input found by rank 0 (a shard of another study in
// OUT.shards/): rank 0 throws datasets::InputError, the others RankStopped. An error while
// running is reported (StudyObserver::rankFailed) and aborts every rank (MPI_Abort, exit 1).
// StudyOutput::shard is not used (the ranks share the whole study).
std::unique_ptr<StudyExecutor> makeMpiExecutor(const MpiWorld& world, int workers_per_rank,
                                               std::string robots_directory);

}  // namespace wpg::engine
