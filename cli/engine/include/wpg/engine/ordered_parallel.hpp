#pragma once
// Jobs 0..count-1 on `threads` worker threads, their outcomes delivered in job order: the
// thread executor of studies and comparisons (study_executor.hpp) and the push sweep's
// bisections (push_sweep.hpp) run on it. Each worker owns what its jobs build (one problem
// copy per thread, nothing shared that a job writes); `deliver` is called by one thread at a
// time, in order 0, 1, 2, ..., as soon as the outcome of every earlier job is there, so a writer
// behind it sees the same sequence for any number of threads.
//
// An exception thrown by `work` or `deliver` stops the hand-out of new jobs; the running jobs
// finish, and the first exception is rethrown to the caller.
//
// Workers are never more than the jobs. Every worker thread is started before the first job is
// handed out and before `all_started` (may be empty; e.g. creating the output file) is called: a
// thread the system refuses (a thread or memory limit) is a std::runtime_error ("cannot start
// worker thread k of n") with no job run and `all_started` not called, never std::terminate.
// `all_started` runs on the calling thread while the other workers start their first jobs (the
// batch file's creation no longer holds the second core idle); nothing is delivered before it
// returns, and if it throws, no job is delivered and no new one is handed out.
//
// Who delivers, and who frees: the calling thread delivers (between its own jobs, then until
// the last outcome); another worker delivers only when kDeliveryBacklog outcomes wait in turn
// (the caller busy with a long job), so that what waits stays bounded. An outcome is destroyed
// by the worker that made it, at its next hand-out. Both keep a writer's memory on one thread:
// glibc gives each thread its own heap (arena), and a block freed by a thread other than the
// one that allocated it takes the owner's arena lock; at -j 2 a batch's HDF5 cache entries and
// run records, written and freed by whichever worker delivered, made ~120 lock waits.
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>
#include <system_error>
#include <functional>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

namespace wpg::engine {

// Outcomes in turn past which a worker other than the caller delivers them itself.
inline constexpr std::size_t kDeliveryBacklog = 4;

// `work(job, worker)`: worker in [0, threads), for per-thread state (a robot model, ...).
template <typename Outcome>
void runOrdered(std::size_t count, int threads,
                const std::function<Outcome(std::size_t job, int worker)>& work,
                const std::function<void(std::size_t job, Outcome&& outcome)>& deliver,
                const std::function<void()>& all_started = {}) {
  struct Finished {
    int worker = 0;  // who made it, and destroys it
    Outcome outcome;
  };
  std::mutex mutex;
  std::condition_variable go_signal, progress_signal;
  bool go = false;
  std::map<std::size_t, Finished> ready;       // finished, waiting for their turn
  std::vector<std::vector<Outcome>> spent;     // delivered, by the worker that made them
  std::size_t next_job = 0, next_delivery = 0;
  bool delivering = false;
  std::exception_ptr error;

  // Outcomes whose turn has come (consecutive from next_delivery), counted up to `enough`.
  const auto inTurn = [&](std::size_t enough) {
    std::size_t n = 0;
    for (auto it = ready.find(next_delivery); it != ready.end() && it->first == next_delivery + n &&
                                              n < enough;
         ++it)
      ++n;
    return n;
  };
  // With the lock held and `delivering` set by the caller: every outcome whose turn has come,
  // delivered without the lock; then `delivering` cleared.
  const auto deliverReady = [&](std::unique_lock<std::mutex>& lock, int self) {
    while (!error) {
      const auto next = ready.find(next_delivery);
      if (next == ready.end()) break;
      Finished item = std::move(next->second);
      ready.erase(next);
      const std::size_t index = next_delivery++;
      lock.unlock();
      try {
        deliver(index, std::move(item.outcome));
      } catch (...) {
        lock.lock();
        if (!error) error = std::current_exception();
        break;
      }
      if (item.worker == self) {
        item = Finished{};  // made here: freed here, without the lock
        lock.lock();
      } else {
        lock.lock();
        spent[static_cast<std::size_t>(item.worker)].push_back(std::move(item.outcome));
      }
    }
    delivering = false;
    progress_signal.notify_all();
  };

  // Runs jobs until none is left to hand out (or an error).
  const auto runJobs = [&](int worker_index) {
    while (true) {
      std::vector<Outcome> garbage;
      std::size_t job = 0;
      {
        std::unique_lock<std::mutex> lock(mutex);
        garbage.swap(spent[static_cast<std::size_t>(worker_index)]);
        const bool caller = worker_index == 0;
        if (!delivering && !error && (caller || inTurn(kDeliveryBacklog) >= kDeliveryBacklog)) {
          delivering = true;
          deliverReady(lock, worker_index);
        }
        if (error || next_job >= count) return;
        job = next_job++;
      }
      garbage.clear();  // freed by the thread that allocated it
      Outcome outcome;
      try {
        outcome = work(job, worker_index);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        progress_signal.notify_all();
        return;
      }
      std::lock_guard<std::mutex> lock(mutex);
      ready.emplace(job, Finished{worker_index, std::move(outcome)});
      progress_signal.notify_all();
    }
  };

  const auto worker = [&](int worker_index) {
    {
      std::unique_lock<std::mutex> lock(mutex);
      go_signal.wait(lock, [&] { return go; });
    }
    runJobs(worker_index);
  };

  const std::size_t wanted = threads < 1 ? 1 : static_cast<std::size_t>(threads);
  const int count_threads = static_cast<int>(count < wanted ? (count < 1 ? 1 : count) : wanted);
  spent.resize(static_cast<std::size_t>(count_threads));
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(count_threads));
  for (int t = 1; t < count_threads && !error; ++t) {
    try {
      pool.emplace_back(worker, t);
    } catch (const std::system_error& e) {
      error = std::make_exception_ptr(std::runtime_error(
          "cannot start worker thread " + std::to_string(t + 1) + " of " +
          std::to_string(count_threads) + " (-j): " + e.what()));
    }
  }
  const bool prepare = !error && all_started;
  {
    std::lock_guard<std::mutex> lock(mutex);
    go = true;  // with an error, the workers stop before their first job
    delivering = prepare;  // outcomes wait in `ready` until all_started has returned
  }
  go_signal.notify_all();
  if (prepare) {
    std::exception_ptr failed;
    try {
      all_started();
    } catch (...) {
      failed = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mutex);
    if (failed && !error) error = failed;
    delivering = false;
  }
  runJobs(0);  // the calling thread is worker 0
  {
    // Every job is handed out (or an error stopped the hand-out): the others' last outcomes,
    // delivered here as they come.
    std::unique_lock<std::mutex> lock(mutex);
    while (true) {
      if (!delivering && !error) {
        delivering = true;
        deliverReady(lock, 0);
      }
      if (error || (!delivering && next_delivery == count)) break;
      progress_signal.wait(lock);
    }
  }
  for (std::thread& thread : pool) thread.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace wpg::engine
