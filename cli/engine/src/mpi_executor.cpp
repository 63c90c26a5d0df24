// A study on the ranks of an MPI job (mpi_executor.hpp).
#include "wpg/engine/mpi_executor.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <system_error>
#include <thread>
#include <utility>

#include "batch_run_record.hpp"
#include "mpi_world.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/storage/output_file.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {
namespace {

std::vector<std::string> shardFiles(const fs::path& folder) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
    if (entry.is_regular_file(ec) && entry.path().extension() == ".h5") {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Rank 0 before any rank opens its shard: the runs already done (resume), or a clean folder.
// The folder is claimed by the caller (held while the job runs); every shard file of it is
// claimed here before it is read, moved or removed: a shard another process holds (a
// `wpg batch --shard` or any HDF5 program) is refused, "in use by another wpg", and nothing
// is touched.
std::vector<bool> prepareShardFolder(const datasets::Study& study, const StudyOutput& output,
                                     StudyObserver& observer) {
  const fs::path folder = shardFolderOf(output.path);
  std::vector<bool> done(study.runs.size(), false);
  std::error_code ec;
  std::vector<std::unique_ptr<datasets::OutputClaim>> claims;
  for (const std::string& file : shardFiles(folder)) {
    claims.push_back(std::make_unique<datasets::OutputClaim>(file));
  }
  if (!output.resume) {
    fs::remove(output.path, ec);  // its links would point into shards rewritten now
    for (const std::string& file : shardFiles(folder)) {
      if (fs::path(file).filename().string().rfind("rank-", 0) == 0) fs::remove(file, ec);
    }
    fs::create_directories(folder, ec);
    if (ec) throw std::runtime_error("cannot create " + folder.string() + ": " + ec.message());
    return done;
  }
  fs::create_directories(folder, ec);
  std::vector<std::string> damaged;
  std::vector<datasets::ShardContents> shards;
  for (const std::string& file : shardFiles(folder)) {
    if (datasets::isDamagedHdf5File(file)) {
      damaged.push_back(file);
    } else {
      shards.push_back(datasets::readShardContents(file));
    }
  }
  for (const datasets::ShardContents& shard : shards) {  // all checked before anything moves
    if (shard.study_name != study.name || shard.study_fingerprint != study.fingerprint) {
      throw datasets::InputError(shard.path + ": cannot resume: it holds study '" +
                                 shard.study_name + "' (fingerprint " + shard.study_fingerprint +
                                 "), not '" + study.name + "' (fingerprint " + study.fingerprint +
                                 ") (files left as they are)");
    }
    if (shard.fields != study.fields.text()) {
      throw datasets::InputError(shard.path + ": cannot resume: its runs store the fields " +
                                 shard.fields + ", this batch asks for " + study.fields.text() +
                                 " (files left as they are)");
    }
  }
  for (const std::string& file : damaged) {
    observer.movedDamagedFile(file, datasets::moveDamagedFileAside(file), true);
  }
  for (const datasets::ShardContents& shard : shards) {
    for (std::size_t row = 0; row < shard.done.size(); ++row) {
      if (shard.done[row] && shard.runs[row] < done.size()) done[shard.runs[row]] = true;
    }
  }
  return done;
}

// The runs of this rank, pulled one at a time: `next(finished, report)` gets the index of the
// run the calling worker just finished (none at its first call) with its report, and returns
// the worker's next run's (none: no more), which the worker makes from it (study_runs.hpp). Each run is written into `writer` as it finishes: the order of the
// groups in the shard differs from run to run, not their contents. Exceptions stop the workers
// and the first is rethrown.
using RunSource = std::function<std::optional<std::size_t>(std::optional<std::size_t> finished,
                                                           std::vector<double>&& report)>;
void runPulled(const datasets::Study& study, const RunSource& next, int threads,
               const std::string& robots_directory,
               datasets::BatchDatasetWriter& writer, const RunNumbers& values,
               const RunNumbers& report) {
  std::mutex mutex;  // the writer and the first error
  std::exception_ptr error;
  const auto worker = [&]() {
    RobotModelCache models(robots_directory);
    const RunSettings settings{robots_directory, &models};
    std::optional<std::size_t> finished;
    std::vector<double> finished_report;
    try {
      while (const std::optional<std::size_t> index = next(finished, std::move(finished_report))) {
        {
          std::lock_guard<std::mutex> lock(mutex);
          if (error) return;
        }
        const datasets::StudyRun run = study.runs[*index];
        const RunResult result = runScenario(scenarioToWalk(study, run), settings);
        BatchRunRecordOf record(run, result, study.fields);
        const datasets::PreparedRun prepared = datasets::BatchDatasetWriter::prepare(record.record());
        record.record().values = values(run, result);
        {
          std::lock_guard<std::mutex> lock(mutex);
          writer.write(record.record(), &prepared);
        }
        finished = run.index;
        finished_report = report(run, result);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();
  if (error) std::rethrow_exception(error);
}

class MpiExecutor : public StudyExecutor {
 public:
  MpiExecutor(const MpiWorld& world, int workers_per_rank, std::string robots_directory)
      : world_(world),
        workers_(workers_per_rank < 1 ? 1 : workers_per_rank),
        robots_directory_(std::move(robots_directory)) {}

  bool run(const datasets::Study& study, const StudyOutput& output,
           const StudyRunHandling& handling, StudyObserver& observer) override;

 private:
  MpiWorld world_;
  int workers_;
  std::string robots_directory_;
};

bool MpiExecutor::run(const datasets::Study& study, const StudyOutput& output,
                      const StudyRunHandling& handling, StudyObserver& observer) {
  const bool root = world_.rank == 0;
  std::vector<bool> done;
  std::exception_ptr setup_error;
  bool bad_input = false;
  // Rank 0 holds the shard folder until the job ends: a second job on the same OUT.h5 (or
  // OUT.shards/) is refused before it touches the index or a shard, "in use by another wpg".
  // Each rank holds its own shard while it writes it.
  std::unique_ptr<datasets::FolderClaim> folder_claim;
  if (root) {
    try {
      folder_claim = std::make_unique<datasets::FolderClaim>(shardFolderOf(output.path), output.path);
      done = prepareShardFolder(study, output, observer);
    } catch (const datasets::InputError&) {
      setup_error = std::current_exception();
      bad_input = true;
    } catch (...) {
      setup_error = std::current_exception();
    }
  }
  // 0 go on, 1 rank 0 failed, 2 bad input
  const int status = mpi::broadcastStatus(setup_error ? (bad_input ? 2 : 1) : 0);
  if (status != 0) {
    mpi::finish();
    if (root) std::rethrow_exception(setup_error);
    throw RankStopped(status == 2);
  }

  const auto fail = [&](const std::exception& error) {
    observer.rankFailed(world_.rank, error.what());
    mpi::abortAll(1);
  };
  const std::string shard =
      (fs::path(shardFolderOf(output.path)) / ("rank-" + std::to_string(world_.rank) + ".h5")).string();
  std::unique_ptr<datasets::BatchDatasetWriter> writer;
  std::unique_ptr<datasets::OutputClaim> shard_claim;
  try {
    std::error_code ec;
    const bool existing = output.resume && fs::exists(shard, ec);
    shard_claim = std::make_unique<datasets::OutputClaim>(shard);
    writer = existing
                 ? datasets::BatchDatasetWriter::resume(shard, study, handling.columns)
                 : datasets::BatchDatasetWriter::create(
                       shard, study, handling.columns, datasets::mpiRankLabel(world_.rank, world_.size));
  } catch (const std::exception& error) {
    fail(error);
  }

  std::vector<std::size_t> todo;
  // Rank 0: each run's report as it comes, handed to `collect` in study order at the end.
  std::vector<std::optional<std::vector<double>>> reports;
  if (root) {
    for (std::size_t i = 0; i < study.runs.size(); ++i) {
      if (!done[i]) todo.push_back(i);
    }
    if (todo.size() < study.runs.size()) {
      observer.resuming(study.runs.size() - todo.size(), study.runs.size(),
                        shardFolderOf(output.path));
    }
    observer.started(todo.size());
    if (handling.collect) reports.resize(study.runs.size());  // a comparison's: small
  }
  mpi::RunDispenser dispenser(
      world_, todo, workers_,
      root ? std::function<void(std::size_t, std::vector<double>&&)>(
                 [&](std::size_t run, std::vector<double>&& message) {
                   // message = [exit status, the caller's report...]
                   observer.runFinished(!message.empty() && message[0] != 0.0);
                   if (!message.empty()) message.erase(message.begin());
                   if (run < reports.size()) reports[run] = std::move(message);
                 })
           : nullptr);
  try {
    runPulled(
        study,
        [&](std::optional<std::size_t> finished, std::vector<double>&& message) {
          return dispenser.next(finished, std::move(message));
        },
        workers_, robots_directory_, *writer, handling.summary_values,
        [&](const datasets::StudyRun& run, const RunResult& result) {
          std::vector<double> message = {static_cast<double>(result.exitStatus())};
          if (handling.report) {
            for (const double value : handling.report(run, result)) message.push_back(value);
          }
          return message;
        });
    writer->close();
  } catch (const std::exception& error) {
    fail(error);
  }
  dispenser.finishDispatch();
  mpi::barrier();  // every shard closed
  if (!root) return false;

  observer.finished();
  const mpi::DispenserStats stats = dispenser.stats();
  const auto begin = std::chrono::steady_clock::now();
  try {
    datasets::writeBatchIndex(output.path, shardFiles(shardFolderOf(output.path)),
                              datasets::IndexLayout::kLinks);
  } catch (const std::exception& error) {
    fail(error);
  }
  RankStatistics statistics;
  statistics.ranks = world_.size;
  statistics.workers_per_rank = workers_;
  statistics.remote_handouts = stats.remote_handouts;
  statistics.service_seconds = stats.service_seconds;
  statistics.service_max_seconds = stats.service_max_seconds;
  statistics.runs = study.runs.size();
  statistics.index_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  observer.ranksFinished(statistics);
  if (handling.collect) {
    for (std::size_t run = 0; run < reports.size(); ++run) {
      if (reports[run]) handling.collect(run, std::move(*reports[run]));
    }
  }
  return true;
}

}  // namespace

bool mpiLaunched() { return mpi::launched(); }

std::optional<MpiWorld> checkInputWhileMpiStarts(const std::function<void()>& check) {
  if (!mpi::launched() && mpi::launcherProcesses() > 1) {
    throw datasets::InputError(
        "this wpg was built without MPI (WPG_WITH_MPI) but runs as one of " +
        std::to_string(mpi::launcherProcesses()) +
        " processes of an MPI launcher: each would run the whole study into the same file "
        "(rebuild with scripts/setup.sh --with-mpi, or give each process its --shard K/N)");
  }
  if (!mpi::launched()) {
    check();
    return std::nullopt;
  }
  std::exception_ptr error;
  std::thread checking([&] {
    try {
      check();
    } catch (...) {
      error = std::current_exception();
    }
  });
  MpiWorld world;
  try {
    world = mpi::start();  // only this thread calls MPI
  } catch (...) {
    checking.join();
    throw;
  }
  checking.join();
  if (mpi::largestStatus(error ? 1 : 0) != 0) {
    mpi::finish();
    if (world.rank != 0) throw RankStopped(true);  // rank 0 says why
    if (error) std::rethrow_exception(error);
    throw std::runtime_error("another rank could not read the input (its message is above)");
  }
  return world;
}

void finishMpi() { mpi::finish(); }

std::string shardFolderOf(const std::string& index) {
  fs::path folder(index);
  folder.replace_extension(".shards");
  return folder.string();
}

std::unique_ptr<StudyExecutor> makeMpiExecutor(const MpiWorld& world, int workers_per_rank,
                                               std::string robots_directory) {
  return std::make_unique<MpiExecutor>(world, workers_per_rank, std::move(robots_directory));
}

}  // namespace wpg::engine
