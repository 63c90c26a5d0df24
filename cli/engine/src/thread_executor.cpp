// A study on this process's worker threads (study_executor.hpp, makeThreadExecutor).
#include <algorithm>
#include <filesystem>
#include <functional>
#include <system_error>
#include <utility>

#include "batch_run_record.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/ordered_parallel.hpp"
#include "wpg/engine/study_executor.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {

namespace {

class ThreadExecutor : public StudyExecutor {
 public:
  ThreadExecutor(int threads, std::string robots_directory)
      : threads_(threads < 1 ? 1 : threads), robots_directory_(std::move(robots_directory)) {}

  bool run(const datasets::Study& study, const StudyOutput& output,
           const StudyRunHandling& handling, StudyObserver& observer) override {
    const ShardSlice slice = output.shard.value_or(ShardSlice{});
    const std::string shard_label =
        output.shard ? datasets::shardSliceLabel(slice.index, slice.count) : "";
    // Claimed before the file is examined or truncated, held until the file is closed: a second
    // writer is refused, the first one's file untouched (output_file.hpp, OutputClaim).
    std::unique_ptr<datasets::OutputClaim> claim;
    std::unique_ptr<datasets::BatchDatasetWriter> writer =
        openWriter(study, output, handling, shard_label, observer, claim);

    std::vector<const datasets::StudyRun*> todo;
    std::size_t slice_runs = 0;
    for (const datasets::StudyRun& run : study.runs) {
      if (!datasets::inShardSlice(run.index, slice.index, slice.count)) continue;
      ++slice_runs;
      if (!writer || !writer->done()[run.index]) todo.push_back(&run);
    }
    if (todo.size() < slice_runs) observer.resuming(slice_runs - todo.size(), slice_runs, output.path);
    observer.started(todo.size());
    // A new file is created once every worker thread has started: a thread the system refuses
    // leaves no file (exit 3), and an old file in its place untouched.
    runInto(todo, handling, writer, observer, [&] {
      if (!writer) {
        writer = datasets::BatchDatasetWriter::create(output.path, study, handling.columns,
                                                      shard_label);
      }
    });
    observer.finished();
    writer->close();
    return true;
  }

 private:
  // The batch file to resume (none: a new one, created by run()), with `resume` the one there (moved aside first when
  // HDF5 cannot read it: killed inside a write).
  std::unique_ptr<datasets::BatchDatasetWriter> openWriter(const datasets::Study& study,
                                                           const StudyOutput& output,
                                                           const StudyRunHandling& handling,
                                                           const std::string& shard_label,
                                                           StudyObserver& observer,
                                                           std::unique_ptr<datasets::OutputClaim>& claim) {
    std::error_code ec;
    const std::string& path = output.path;
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty()) fs::create_directories(parent, ec);
    claim = std::make_unique<datasets::OutputClaim>(path);
    // A file held by another process was refused above: what is left to judge is damage.
    const bool existing = output.resume && !claim->created();
    // Opens the file and visits every object header: once.
    const bool damaged = existing && datasets::isDamagedHdf5File(path);
    if (existing && !damaged) {
      // A slice finishes its own shard only (and a whole batch is not finished as a slice).
      const std::string label = datasets::readShardContents(path).label;
      if (label != shard_label) {
        throw datasets::InputError(
            path + ": cannot resume: it is " +
            (label.empty() ? std::string("not a shard") : "shard " + label) + ", not " +
            (shard_label.empty() ? std::string("a whole batch") : "shard " + shard_label) +
            " (file left as it is)");
      }
    }
    if (damaged) {
      // Nothing of it can be trusted. Kept aside, not removed, and the study starts again (the
      // same runs give the same file), under a new claim on the new file.
      observer.movedDamagedFile(path, datasets::moveDamagedFileAside(path), false);
      claim.reset();
      claim = std::make_unique<datasets::OutputClaim>(path);
    } else if (existing) {
      return datasets::BatchDatasetWriter::resume(path, study, handling.columns);
    }
    return nullptr;  // created by run() once its workers have started
  }

  // A run as its worker leaves it for the writer: everything that can be computed without the
  // file is, on the worker (the walk, its checks and metrics, the chunks compressed, the summary
  // row and the caller's report), so that the writer, one thread at a time, only writes.
  struct FinishedRun {
    RunResult result;
    datasets::PreparedRun prepared;
    std::vector<double> values;  // the summary row (handling.summary_values)
    std::vector<double> report;  // handling.report, when collected
  };

  // The runs on the workers, their datasets compressed there, written in study order.
  void runInto(const std::vector<const datasets::StudyRun*>& runs,
               const StudyRunHandling& handling,
               std::unique_ptr<datasets::BatchDatasetWriter>& writer, StudyObserver& observer,
               const std::function<void()>& ready) {
    // Never more workers than runs (runOrdered): one robot model cache each.
    const int workers = static_cast<int>(
        std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(threads_), runs.size())));
    std::vector<RobotModelCache> models;
    for (int worker = 0; worker < workers; ++worker) models.emplace_back(robots_directory_);
    runOrdered<FinishedRun>(
        runs.size(), workers,
        [&](std::size_t position, int worker) {
          const datasets::StudyRun& run = *runs[position];
          RunSettings settings{robots_directory_, &models[static_cast<std::size_t>(worker)]};
          FinishedRun finished;
          finished.result = runScenario(run.scenario, settings);
          BatchRunRecordOf record(run, finished.result);
          finished.prepared = datasets::BatchDatasetWriter::prepare(record.record());
          finished.values = handling.summary_values(run, finished.result);
          if (handling.report && handling.collect) {
            finished.report = handling.report(run, finished.result);
          }
          return finished;
        },
        [&](std::size_t position, FinishedRun&& finished) {
          const datasets::StudyRun& run = *runs[position];
          BatchRunRecordOf record(run, finished.result);
          record.record().values = std::move(finished.values);
          writer->write(record.record(), &finished.prepared);
          if (handling.report && handling.collect) {
            handling.collect(run.index, std::move(finished.report));
          }
          observer.runFinished(finished.result.exitStatus() != 0);
        },
        ready);
  }

  int threads_;
  std::string robots_directory_;
};

}  // namespace

std::unique_ptr<StudyExecutor> makeThreadExecutor(int threads, std::string robots_directory) {
  return std::make_unique<ThreadExecutor>(threads, std::move(robots_directory));
}

}  // namespace wpg::engine
