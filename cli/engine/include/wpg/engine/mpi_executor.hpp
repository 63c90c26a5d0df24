#pragma once
// `wpg batch` and `wpg compare` under an MPI launcher (`mpirun -np R wpg batch STUDY -o OUT.h5`):
// every rank runs runs handed out one at a time by rank 0 (mpi_world.hpp, RunDispenser) with
// the thread runner's pipeline (study_execution.hpp, runStudyPulled) and writes them into its own
// shard, OUT.shards/rank-<r>.h5 (a batch file of the whole study holding that rank's runs);
// rank 0 then writes OUT.h5, the index that links them (batch_index.hpp, as `wpg merge`).
//
// --resume: rank 0 reads the done flags of every shard in OUT.shards/ (of any earlier number of
// ranks); a shard HDF5 cannot open (a rank killed inside a write) is moved to
// <shard>.damaged and its runs are run again; each rank finishes its own shard; only the runs
// done in no shard are handed out. Without --resume, OUT.h5 and OUT.shards/rank-*.h5 are
// removed first.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mpi_world.hpp"
#include "scenario_run.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/study_design/study.hpp"

namespace wpg::cli {

// Runs `check` (loading and checking the input, before anything is written) on another thread
// while MPI starts on this one, when launched (mpi::launched()); otherwise runs it here and
// returns nothing. Open MPI's start is mostly waiting (0.3-0.6 s measured on this machine, a
// fixed cost a 2-rank batch of 200 short runs feels), the study's load is CPU: overlapped, they
// cost the longer of the two. When `check` throws on any rank, every rank stops: rank 0 throws
// its error (one line on stderr), the others finish MPI and exit with status 2 quietly.
std::optional<mpi::World> checkInputWhileMpiStarts(const std::function<void()>& check);

// OUT.h5 -> OUT.shards (the folder of the ranks' shards, beside the index).
std::string shardFolderOf(const std::string& index);

struct DistributedStudyOptions {
  std::string index;    // OUT.h5
  bool resume = false;
  int threads = 1;      // workers per rank
};

using RunValues =
    std::function<std::vector<double>(const datasets::StudyRun&, const ScenarioOutcome&)>;

// Runs the study on every rank of `world` (collective). `values`: a run's summary row (as
// runStudyInto); `report(run, outcome)`: what rank 0 gets of each run, on the rank that ran it
// (empty function: nothing); `collect(run index, report)`: rank 0, one call at a time. Returns
// true on rank 0 once OUT.h5 is written, false on the other ranks. Bad input found by rank 0
// (a shard of another study in OUT.shards/): every rank stops, rank 0 throws InputError and the
// others exit with status 2 quietly. An error while running aborts every rank (MPI_Abort).
bool runStudyOnRanks(const mpi::World& world, const datasets::Study& study,
                     const std::vector<datasets::SummaryColumn>& columns,
                     const DistributedStudyOptions& options, const RunValues& values,
                     const RunValues& report,
                     const std::function<void(std::size_t, std::vector<double>&&)>& collect);

}  // namespace wpg::cli
