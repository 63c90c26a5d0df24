// A study on the ranks of an MPI job (distributed_study.hpp).
#include "mpi_executor.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "batch_progress.hpp"
#include "cli_common.hpp"
#include "study_execution.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/input/input_error.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
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
std::vector<bool> prepareShardFolder(const datasets::Study& study,
                                     const DistributedStudyOptions& options) {
  const fs::path folder = shardFolderOf(options.index);
  std::vector<bool> done(study.runs.size(), false);
  std::error_code ec;
  if (!options.resume) {
    fs::remove(options.index, ec);  // its links would point into shards rewritten now
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
  }
  for (const std::string& file : damaged) {
    const std::string aside = datasets::moveDamagedFileAside(file);
    std::cerr << study.name << ": " << file << " cannot be read by HDF5 (a rank killed inside a "
              << "write); moved to " << aside << ", its runs are run again\n";
  }
  for (const datasets::ShardContents& shard : shards) {
    for (std::size_t i = 0; i < done.size() && i < shard.done.size(); ++i) {
      done[i] = done[i] || shard.done[i];
    }
  }
  return done;
}

}  // namespace

std::optional<mpi::World> checkInputWhileMpiStarts(const std::function<void()>& check) {
  if (!mpi::launched() && mpi::launcherProcesses() > 1) {
    throw UsageError("this wpg was built without MPI (WPG_WITH_MPI) but runs as one of " +
                     std::to_string(mpi::launcherProcesses()) +
                     " processes of an MPI launcher: each would run the whole study into the "
                     "same file (rebuild with scripts/setup.sh --with-mpi, or give each process "
                     "its --shard K/N)");
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
  mpi::World world;
  try {
    world = mpi::start();  // only this thread calls MPI
  } catch (...) {
    checking.join();
    throw;
  }
  checking.join();
  if (mpi::largestStatus(error ? kExitBadInput : 0) != 0) {
    mpi::finish();
    if (world.rank != 0) std::exit(kExitBadInput);  // rank 0 says why
    if (error) std::rethrow_exception(error);
    throw std::runtime_error("another rank could not read the input (its message is above)");
  }
  return world;
}

std::string shardFolderOf(const std::string& index) {
  fs::path folder(index);
  folder.replace_extension(".shards");
  return folder.string();
}

bool runStudyOnRanks(const mpi::World& world, const datasets::Study& study,
                     const std::vector<datasets::SummaryColumn>& columns,
                     const DistributedStudyOptions& options, const RunValues& values,
                     const RunValues& report,
                     const std::function<void(std::size_t, std::vector<double>&&)>& collect) {
  const bool root = world.rank == 0;
  std::vector<bool> done;
  std::exception_ptr setup_error;
  int status = 0;
  if (root) {
    try {
      done = prepareShardFolder(study, options);
    } catch (const datasets::InputError&) {
      setup_error = std::current_exception();
      status = kExitBadInput;
    } catch (...) {
      setup_error = std::current_exception();
      status = kExitRunFailed;
    }
  }
  status = mpi::broadcastStatus(status);
  if (status != 0) {
    mpi::finish();
    if (root) std::rethrow_exception(setup_error);
    std::exit(status);  // rank 0 says why
  }

  const auto fail = [&](const std::exception& error) {
    printError("rank " + std::to_string(world.rank) + ": " + error.what());
    mpi::abortAll(kExitRunFailed);
  };
  const std::string shard =
      (fs::path(shardFolderOf(options.index)) / ("rank-" + std::to_string(world.rank) + ".h5")).string();
  std::unique_ptr<datasets::BatchDatasetWriter> writer;
  try {
    std::error_code ec;
    writer = options.resume && fs::exists(shard, ec)
                 ? datasets::BatchDatasetWriter::resume(shard, study, columns)
                 : datasets::BatchDatasetWriter::create(shard, study, columns,
                                                        datasets::mpiRankLabel(world.rank, world.size));
  } catch (const std::exception& error) {
    fail(error);
  }

  std::vector<std::size_t> todo;
  std::unique_ptr<BatchProgress> progress;
  if (root) {
    for (std::size_t i = 0; i < study.runs.size(); ++i) {
      if (!done[i]) todo.push_back(i);
    }
    if (todo.size() < study.runs.size()) {
      std::cerr << study.name << ": resuming, " << study.runs.size() - todo.size() << " of "
                << study.runs.size() << " runs already in " << shardFolderOf(options.index) << "\n";
    }
    progress = std::make_unique<BatchProgress>(study.name, todo.size(), stderr);
  }
  mpi::RunDispenser dispenser(
      world, todo, options.threads,
      root ? std::function<void(std::size_t, std::vector<double>&&)>(
                 [&](std::size_t run, std::vector<double>&& message) {
                   // message = [exit status, the caller's report...]
                   progress->runFinished(!message.empty() && message[0] != 0.0);
                   if (collect) collect(run, std::vector<double>(message.begin() + 1, message.end()));
                 })
           : nullptr);
  try {
    runStudyPulled(
        [&](const datasets::StudyRun* finished, std::vector<double>&& message) {
          const std::optional<std::size_t> next = dispenser.next(
              finished ? std::optional<std::size_t>(finished->index) : std::nullopt,
              std::move(message));
          return next ? &study.runs[*next] : nullptr;
        },
        options.threads, writer.get(), values,
        [&](const datasets::StudyRun& run, const ScenarioOutcome& outcome) {
          std::vector<double> message = {static_cast<double>(outcome.exit_status)};
          if (report) {
            for (const double value : report(run, outcome)) message.push_back(value);
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

  progress->finish();
  const mpi::DispenserStats stats = dispenser.stats();
  const auto begin = std::chrono::steady_clock::now();
  try {
    datasets::writeBatchIndex(options.index, shardFiles(shardFolderOf(options.index)),
                              datasets::IndexLayout::kLinks);
  } catch (const std::exception& error) {
    fail(error);
  }
  const double index_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  char line[256];
  std::snprintf(line, sizeof line,
                "%s: %d ranks x %d workers; rank 0 answered %zu requests of other ranks, %.1f us "
                "each (max %.1f us); index of %zu runs written in %.3f s\n",
                study.name.c_str(), world.size, options.threads, stats.remote_handouts,
                stats.remote_handouts ? 1e6 * stats.service_seconds / static_cast<double>(stats.remote_handouts) : 0.0,
                1e6 * stats.service_max_seconds, study.runs.size(), index_seconds);
  std::cerr << line;
  return true;
}

}  // namespace wpg::cli
