// The thread pool of the engine (wpg/engine/ordered_parallel.hpp): outcomes are delivered in job
// order whatever order the jobs finish in, one delivery at a time, each job once; the worker
// index names the worker; an exception of a job or of a delivery stops the hand-out and reaches
// the caller.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "wpg/engine/ordered_parallel.hpp"

using wpg::engine::runOrdered;

namespace {

// A job's duration that makes later jobs finish first: job j sleeps longer the smaller j is
// within each group of four, so every worker count sees completions out of order.
std::chrono::microseconds jobDuration(std::size_t job) {
  return std::chrono::microseconds(200 * (4 - job % 4));
}

// A job's duration in the tests that stop the hand-out: 0.1 ms for the first 20 jobs, 1 ms
// after. The thread that stops the hand-out (a job's or a delivery's exception, caught and
// recorded under the lock) may be preempted in between on a loaded machine; the other two
// workers meanwhile start jobs, and with 0.1 ms jobs they reached 100 once in a full suite
// (load 8 on 2 cores). At 1 ms a hundred starts take them ~40 ms of such a delay, not ~5.
std::chrono::microseconds stoppingJobDuration(std::size_t job) {
  return std::chrono::microseconds(job < 20 ? 100 : 1000);
}

}  // namespace

TEST(OrderedParallel, DeliversInJobOrderWhateverTheCompletionOrder) {
  constexpr std::size_t kJobs = 40;
  for (const int threads : {1, 2, 3, 8}) {
    SCOPED_TRACE(threads);
    std::mutex mutex;
    std::vector<std::size_t> completed, delivered;
    std::set<int> workers;
    std::atomic<int> delivering{0};
    bool overlapped = false;
    // No job runs before two workers have started one: on a loaded machine one worker could
    // otherwise run all 40 before the other is scheduled (it did once in a full suite), and
    // the jobs would finish in order.
    std::mutex start_mutex;
    std::condition_variable start_signal;
    std::set<int> starters;
    const std::size_t together = threads > 1 ? 2 : 1;
    runOrdered<std::size_t>(
        kJobs, threads,
        [&](std::size_t job, int worker) {
          {
            std::unique_lock<std::mutex> lock(start_mutex);
            starters.insert(worker);
            start_signal.notify_all();
            start_signal.wait(lock, [&] { return starters.size() >= together; });
          }
          std::this_thread::sleep_for(jobDuration(job));
          std::lock_guard<std::mutex> lock(mutex);
          completed.push_back(job);
          workers.insert(worker);
          return job * job;  // the outcome travels with its job
        },
        [&](std::size_t job, std::size_t&& outcome) {
          if (delivering.fetch_add(1) != 0) overlapped = true;
          EXPECT_EQ(outcome, job * job);
          delivered.push_back(job);
          delivering.fetch_sub(1);
        });
    std::vector<std::size_t> in_order(kJobs);
    for (std::size_t j = 0; j < kJobs; ++j) in_order[j] = j;
    EXPECT_EQ(delivered, in_order);
    EXPECT_FALSE(overlapped) << "two deliveries at once";
    EXPECT_EQ(completed.size(), kJobs);
    for (const int worker : workers) {
      EXPECT_GE(worker, 0);
      EXPECT_LT(worker, threads);
    }
    if (threads > 1) {
      // The property is only tested when the jobs did finish out of order.
      EXPECT_NE(completed, in_order) << "the jobs finished in order: the test proves nothing";
      EXPECT_GT(workers.size(), 1u);
    }
  }
}

TEST(OrderedParallel, NoJobsCallsNothing) {
  bool called = false;
  runOrdered<int>(
      0, 4, [&](std::size_t, int) { called = true; return 0; },
      [&](std::size_t, int&&) { called = true; });
  EXPECT_FALSE(called);
}

TEST(OrderedParallel, AJobsExceptionStopsTheHandOutAndReachesTheCaller) {
  constexpr std::size_t kJobs = 200, kFailing = 5;
  for (const int threads : {1, 3}) {
    SCOPED_TRACE(threads);
    std::atomic<std::size_t> started{0};
    std::vector<std::size_t> delivered;
    EXPECT_THROW(runOrdered<int>(
                     kJobs, threads,
                     [&](std::size_t job, int) {
                       ++started;
                       if (job == kFailing) throw std::runtime_error("job 5 failed");
                       std::this_thread::sleep_for(stoppingJobDuration(job));
                       return 0;
                     },
                     [&](std::size_t job, int&&) { delivered.push_back(job); }),
                 std::runtime_error);
    // Nothing at or after the failed job is delivered in order past it, and the hand-out
    // stopped: far fewer jobs started than there are.
    for (const std::size_t job : delivered) EXPECT_LT(job, kFailing);
    EXPECT_LT(started.load(), kJobs / 2);
  }
}

TEST(OrderedParallel, ADeliverysExceptionStopsEverythingAndReachesTheCaller) {
  constexpr std::size_t kJobs = 200;
  std::atomic<std::size_t> started{0};
  std::vector<std::size_t> delivered;
  try {
    runOrdered<int>(
        kJobs, 3,
        [&](std::size_t job, int) {
          ++started;
          std::this_thread::sleep_for(stoppingJobDuration(job));
          return 0;
        },
        [&](std::size_t job, int&&) {
          if (job == 3) throw std::logic_error("the writer failed at 3");
          delivered.push_back(job);
        });
    ADD_FAILURE() << "no exception";
  } catch (const std::logic_error& error) {
    EXPECT_STREQ(error.what(), "the writer failed at 3");
  }
  EXPECT_EQ(delivered, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_LT(started.load(), kJobs / 2);
}

// `all_started` (the batch file's creation) runs while the other workers start their jobs, and
// nothing is delivered before it has returned: it waits here until a job has finished, which
// only a worker running beside it can do.
TEST(OrderedParallel, AllStartedRunsBesideTheWorkersAndPrecedesEveryDelivery) {
  constexpr std::size_t kJobs = 20;
  std::mutex mutex;
  std::condition_variable finished_signal;
  std::size_t finished = 0;
  bool prepared = false, saw_a_finished_job = false;
  std::vector<std::size_t> delivered;
  runOrdered<int>(
      kJobs, 2,
      [&](std::size_t job, int) {
        std::lock_guard<std::mutex> lock(mutex);
        ++finished;
        finished_signal.notify_all();
        return static_cast<int>(job);
      },
      [&](std::size_t job, int&& outcome) {
        EXPECT_TRUE(prepared) << "job " << job << " delivered before all_started returned";
        EXPECT_EQ(outcome, static_cast<int>(job));
        delivered.push_back(job);
      },
      [&] {
        std::unique_lock<std::mutex> lock(mutex);
        saw_a_finished_job = finished_signal.wait_for(lock, std::chrono::seconds(10),
                                                      [&] { return finished > 0; });
        prepared = true;
      });
  EXPECT_TRUE(saw_a_finished_job) << "no job ran while all_started did";
  ASSERT_EQ(delivered.size(), kJobs);
  for (std::size_t job = 0; job < kJobs; ++job) EXPECT_EQ(delivered[job], job);
}

// A failing `all_started` (the file cannot be created): no outcome delivered, its exception
// reaches the caller, and the hand-out stops.
TEST(OrderedParallel, AFailingAllStartedDeliversNothing) {
  constexpr std::size_t kJobs = 200;
  std::atomic<std::size_t> started{0};
  std::size_t delivered = 0;
  try {
    runOrdered<int>(
        kJobs, 2,
        [&](std::size_t, int) {
          ++started;
          std::this_thread::sleep_for(std::chrono::microseconds(100));
          return 0;
        },
        [&](std::size_t, int&&) { ++delivered; },
        [] {
          std::this_thread::sleep_for(std::chrono::milliseconds(2));
          throw std::runtime_error("cannot create the file");
        });
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "cannot create the file");
  }
  EXPECT_EQ(delivered, 0u);
  EXPECT_LT(started.load(), kJobs / 2);
}
