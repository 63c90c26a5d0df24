// The MPI of the engine's MPI executor, under a launcher (mpi_world.hpp). The only file that
// includes <mpi.h>; without WPG_WITH_MPI it compiles to launched() == false.
#include "mpi_world.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>

#if WPG_WITH_MPI
#include <mpi.h>
#endif

namespace wpg::engine::mpi {

int launcherProcesses() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* value = std::getenv(name)) return std::max(1, std::atoi(value));
  }
  return 1;
}

#if WPG_WITH_MPI

namespace {
constexpr int kRequestTag = 1;  // worker -> rank 0: [finished run or -1, its report...] (doubles)
constexpr int kReplyTag = 2;    // rank 0 -> worker: the next run, or -1 (long long)
// Rank 0's dispatcher looks for requests every 1 ms: at 200 us its wake-ups took enough of the
// core its own worker runs on that rank 0 ran 88-95 of 200 runs (2 free cores, 2 ranks) and the
// 1 vs 2 rank speed-up was 1.63-1.85x (median 1.66, 4 pairs); at 1 ms, 97-101 runs and 1.76-1.94x
// (median 1.83, 5 pairs). A request then waits <= 1 ms, against runs of 15 ms and more.
constexpr auto kPollInterval = std::chrono::microseconds(1000);
constexpr auto kWaitInterval = std::chrono::microseconds(50);

// MPI_Wait without the busy loop: Open MPI's blocking calls spin on a core while they wait,
// which the workers of the other ranks on a shared node need (measured on 2 loaded cores: +25 %
// CPU for 2 ranks with blocking receives, the waits for replies stretched by the scheduler).
void sleepUntilDone(MPI_Request* request) {
  int done = 0;
  while (MPI_Test(request, &done, MPI_STATUS_IGNORE), !done) std::this_thread::sleep_for(kWaitInterval);
}
}  // namespace

bool launched() {
  // Open MPI's mpirun, MPICH's Hydra and Slurm's srun (PMI-2 or PMIx) set one of these.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(name)) return true;
  }
  return false;
}

World start() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
  if (provided < MPI_THREAD_SERIALIZED) {
    throw std::runtime_error("MPI: this MPI library does not allow calls from several threads "
                             "(MPI_THREAD_SERIALIZED), which rank 0's dispatcher needs");
  }
  World world;
  MPI_Comm_rank(MPI_COMM_WORLD, &world.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world.size);
  return world;
}

void finish() {
  barrier();  // every rank here before MPI_Finalize, which spins while it waits for the others
  MPI_Finalize();
}

void abortAll(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);  // MPI_Abort does not return; this is for the compiler
}

int broadcastStatus(int status) {
  MPI_Request request;
  MPI_Ibcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
  sleepUntilDone(&request);
  return status;
}

int largestStatus(int status) {
  int largest = status;
  MPI_Request request;
  MPI_Iallreduce(&status, &largest, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD, &request);
  sleepUntilDone(&request);
  return largest;
}

void barrier() {
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  sleepUntilDone(&request);
}

struct RunDispenser::State {
  World world;
  int workers_per_rank = 1;
  std::mutex mutex;  // rank 0: the list, `collect` and the stats; others: one round trip
  std::vector<std::size_t> todo;
  std::size_t position = 0;
  std::function<void(std::size_t, std::vector<double>&&)> collect;
  std::thread dispatcher;
  DispenserStats stats;

  // Rank 0, under `mutex`.
  long long handOut(double finished, std::vector<double>&& report) {
    if (finished >= 0.0 && collect) collect(static_cast<std::size_t>(finished), std::move(report));
    return position < todo.size() ? static_cast<long long>(todo[position++]) : -1;
  }

  void dispatch() {
    const std::size_t expected_stops =
        static_cast<std::size_t>(world.size - 1) * static_cast<std::size_t>(workers_per_rank);
    std::size_t stops = 0;
    std::vector<double> message;
    while (stops < expected_stops) {
      int found = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &found, &status);
      if (!found) {
        std::this_thread::sleep_for(kPollInterval);
        continue;
      }
      const auto begin = std::chrono::steady_clock::now();
      int count = 0;
      MPI_Get_count(&status, MPI_DOUBLE, &count);
      message.resize(static_cast<std::size_t>(count));
      MPI_Recv(message.data(), count, MPI_DOUBLE, status.MPI_SOURCE, kRequestTag, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
      long long reply = -1;
      {
        std::lock_guard<std::mutex> lock(mutex);
        reply = handOut(message.empty() ? -1.0 : message[0],
                        std::vector<double>(message.begin() + (message.empty() ? 0 : 1), message.end()));
      }
      MPI_Send(&reply, 1, MPI_LONG_LONG, status.MPI_SOURCE, kReplyTag, MPI_COMM_WORLD);
      if (reply < 0) ++stops;
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
      std::lock_guard<std::mutex> lock(mutex);
      ++stats.remote_handouts;
      stats.service_seconds += seconds;
      if (seconds > stats.service_max_seconds) stats.service_max_seconds = seconds;
    }
  }
};

RunDispenser::RunDispenser(const World& world, std::vector<std::size_t> todo, int workers_per_rank,
                           std::function<void(std::size_t, std::vector<double>&&)> collect)
    : state_(new State) {
  state_->world = world;
  state_->workers_per_rank = workers_per_rank;
  state_->todo = std::move(todo);
  state_->collect = std::move(collect);
  if (world.rank == 0 && world.size > 1) {
    state_->dispatcher = std::thread([state = state_.get()] { state->dispatch(); });
  }
}

RunDispenser::~RunDispenser() { finishDispatch(); }

void RunDispenser::finishDispatch() {
  if (state_->dispatcher.joinable()) state_->dispatcher.join();
}

DispenserStats RunDispenser::stats() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->stats;
}

std::optional<std::size_t> RunDispenser::next(std::optional<std::size_t> finished,
                                              std::vector<double>&& report) {
  std::lock_guard<std::mutex> lock(state_->mutex);
  const double done = finished ? static_cast<double>(*finished) : -1.0;
  long long reply = -1;
  if (state_->world.rank == 0) {
    reply = state_->handOut(done, std::move(report));
  } else {
    std::vector<double> message;
    message.reserve(report.size() + 1);
    message.push_back(done);
    message.insert(message.end(), report.begin(), report.end());
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_DOUBLE, 0, kRequestTag,
             MPI_COMM_WORLD);
    MPI_Request request;
    MPI_Irecv(&reply, 1, MPI_LONG_LONG, 0, kReplyTag, MPI_COMM_WORLD, &request);
    sleepUntilDone(&request);
  }
  if (reply < 0) return std::nullopt;
  return static_cast<std::size_t>(reply);
}

#else  // built without MPI: launched() is false, so nothing below is ever reached

bool launched() { return false; }
World start() { throw std::logic_error("wpg was built without MPI (WPG_WITH_MPI)"); }
void finish() {}
void abortAll(int code) { std::_Exit(code); }
int broadcastStatus(int status) { return status; }
int largestStatus(int status) { return status; }
void barrier() {}
struct RunDispenser::State {};
RunDispenser::RunDispenser(const World&, std::vector<std::size_t>, int,
                           std::function<void(std::size_t, std::vector<double>&&)>) {
  throw std::logic_error("wpg was built without MPI (WPG_WITH_MPI)");
}
RunDispenser::~RunDispenser() = default;
void RunDispenser::finishDispatch() {}
DispenserStats RunDispenser::stats() const { return {}; }
std::optional<std::size_t> RunDispenser::next(std::optional<std::size_t>, std::vector<double>&&) {
  return std::nullopt;
}

#endif

}  // namespace wpg::engine::mpi
