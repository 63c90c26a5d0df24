#pragma once
// The only MPI wpg uses (mpi_world.cpp is the one file that includes <mpi.h>; built with
// WPG_WITH_MPI, otherwise launched() is false and the rest is never called): start and stop,
// a status broadcast, a barrier, and the hand-out of a study's runs by rank 0 (RunDispenser).
// The MPI executor (mpi_executor.cpp) is its one user.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "wpg/engine/mpi_executor.hpp"

namespace wpg::engine::mpi {

// Built with MPI and started by an MPI launcher (mpirun, srun, ...: its environment says so).
bool launched();
// How many processes the launcher started, from its environment (1 without a launcher), built
// with MPI or not: a build without MPI under `mpirun -np 4` would run the whole study 4 times
// into one file, and refuses to.
int launcherProcesses();

using World = MpiWorld;
// MPI_Init_thread (MPI_THREAD_SERIALIZED: one thread at a time calls MPI, see RunDispenser).
World start();
void finish();                         // MPI_Finalize
[[noreturn]] void abortAll(int code);  // MPI_Abort: every rank exits with `code`
// Rank 0's `status` on every rank (0: go on).
int broadcastStatus(int status);
// The largest `status` of all ranks, on every rank.
int largestStatus(int status);
void barrier();

// What rank 0 measures while it hands out runs.
struct DispenserStats {
  std::size_t remote_handouts = 0;  // replies sent to other ranks (runs and "no more")
  double service_seconds = 0.0;     // receive + bookkeeping + send, summed over them
  double service_max_seconds = 0.0;
};

// The runs of a study handed out one at a time, on request: rank 0 holds the list of run
// indices to do; a worker asks for its next run when it has finished one, so a slow run keeps
// one worker, not a rank's share of the study (dynamic scheduling, no static split). Rank 0
// runs workers too: its workers take from the list directly, and a dispatcher thread answers
// the other ranks' requests (polling MPI_Iprobe every 1 ms, mpi_world.cpp says why: a blocking
// receive would keep a core busy, which the workers of rank 0 need; for the same reason every
// wait of this file sleeps between MPI_Test calls instead of spinning). Only the dispatcher calls MPI on rank 0 while
// runs are handed out; on the other ranks a mutex makes each request and its reply one round
// trip: MPI_THREAD_SERIALIZED is enough.
class RunDispenser {
 public:
  // Collective. On rank 0, `todo` (run indices, in the order they are handed out) and
  // `collect(run, report)`, called one at a time for every finished run of every rank; the other
  // ranks pass {} and an empty function. `workers_per_rank`: how many workers ask on each rank.
  RunDispenser(const World& world, std::vector<std::size_t> todo, int workers_per_rank,
               std::function<void(std::size_t run, std::vector<double>&& report)> collect);
  ~RunDispenser();  // rank 0: waits for the dispatcher (every worker told "no more")
  RunDispenser(const RunDispenser&) = delete;
  RunDispenser& operator=(const RunDispenser&) = delete;

  // Any worker thread: reports `finished` (with `report`) when it has a value, returns the next
  // run to do, or nothing when there is none left.
  std::optional<std::size_t> next(std::optional<std::size_t> finished, std::vector<double>&& report);

  // Rank 0: waits until every worker of the other ranks has been told "no more" (the
  // destructor does it too); stats() is complete after it.
  void finishDispatch();
  DispenserStats stats() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace wpg::engine::mpi
