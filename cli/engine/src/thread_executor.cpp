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

    // The slice's runs, by index arithmetic; resuming, the list of those not in the file yet.
    const datasets::BatchRows rows{static_cast<std::size_t>(slice.index),
                                   static_cast<std::size_t>(slice.count)};
    const datasets::BatchRows file_rows = study.slices_hold_every_row ? datasets::BatchRows{} : rows;
    const std::size_t slice_runs = rows.count(study.runs.size());
    std::vector<std::size_t> todo;
    const bool resuming = writer != nullptr;  // else the file is created once workers start
    if (resuming) {
      for (std::size_t row = 0; row < slice_runs; ++row) {
        if (!writer->done(rows.runOf(row))) todo.push_back(rows.runOf(row));
      }
      if (todo.size() < slice_runs) observer.resuming(slice_runs - todo.size(), slice_runs, output.path);
    }
    const std::size_t count = resuming ? todo.size() : slice_runs;
    const auto runAt = [&](std::size_t position) {
      return resuming ? todo[position] : rows.runOf(position);
    };
    observer.started(count);
    // A new file is created once every worker thread has started: a thread the system refuses
    // leaves no file (exit 3), and an old file in its place untouched.
    runInto(study, count, runAt, handling, writer, observer, [&] {
      if (!writer) {
        writer = datasets::BatchDatasetWriter::create(output.path, study, handling.columns,
                                                      shard_label, file_rows);
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
      const ShardSlice slice = output.shard.value_or(ShardSlice{});
      const datasets::BatchRows file_rows =
          study.slices_hold_every_row
              ? datasets::BatchRows{}
              : datasets::BatchRows{static_cast<std::size_t>(slice.index),
                                    static_cast<std::size_t>(slice.count)};
      return datasets::BatchDatasetWriter::resume(path, study, handling.columns, file_rows);
    }
    return nullptr;  // created by run() once its workers have started
  }

  // A run as its worker leaves it for the writer: everything that can be computed without the
  // file is, on the worker (the walk, its checks and metrics, the chunks compressed, the summary
  // row and the caller's report), so that the writer, one thread at a time, only writes.
  struct FinishedRun {
    datasets::StudyRun run;  // made on the worker from its index (study_runs.hpp)
    RunResult result;
    datasets::PreparedRun prepared;
    std::vector<double> values;  // the summary row (handling.summary_values)
    std::vector<double> report;  // handling.report, when collected
  };

  // The runs on the workers (run `run_at(position)` for each position < count), made from
  // their index and their datasets compressed there, written in study order.
  void runInto(const datasets::Study& study, std::size_t count,
               const std::function<std::size_t(std::size_t)>& run_at,
               const StudyRunHandling& handling,
               std::unique_ptr<datasets::BatchDatasetWriter>& writer, StudyObserver& observer,
               const std::function<void()>& ready) {
    // Never more workers than runs (runOrdered): one robot model cache each.
    const int workers = static_cast<int>(
        std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(threads_), count)));
    std::vector<RobotModelCache> models;
    for (int worker = 0; worker < workers; ++worker) models.emplace_back(robots_directory_);
    runOrdered<FinishedRun>(
        count, workers,
        [&](std::size_t position, int worker) {
          RunSettings settings{robots_directory_, &models[static_cast<std::size_t>(worker)]};
          FinishedRun finished;
          finished.run = study.runs[run_at(position)];
          const datasets::StudyRun& run = finished.run;
          finished.result = runScenario(scenarioToWalk(study, run), settings);
          BatchRunRecordOf record(run, finished.result, study.fields);
          finished.prepared = datasets::BatchDatasetWriter::prepare(record.record());
          finished.values = handling.summary_values(run, finished.result);
          if (handling.report && handling.collect) {
            finished.report = handling.report(run, finished.result);
          }
          return finished;
        },
        [&](std::size_t, FinishedRun&& finished) {
          const datasets::StudyRun& run = finished.run;
          BatchRunRecordOf record(run, finished.result, study.fields);
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
