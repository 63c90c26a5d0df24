// `wpg batch STUDY.yaml -o OUT.h5 [-j N] [--resume] [--shard K/N]`: a study
// (datasets/SCENARIOS.md, "Studies") expanded into runs, run on N worker threads, written run by
// run into one HDF5 file (datasets/SCHEMA.md, "Batch files"), then OUT.summary.csv,
// OUT.summary.md and the summary figure OUT.summary.png beside it. With --shard K/N only the
// runs of slice K (batch_index.hpp) into a shard file, joined later by `wpg merge`; under an MPI
// launcher the ranks share the study (distributed_study.hpp) and OUT.h5 is the index.
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>
#include <system_error>
#include <thread>

#include "batch_progress.hpp"
#include "cli_common.hpp"
#include "mpi_executor.hpp"
#include "mpi_world.hpp"
#include "scenario_run.hpp"
#include "study_execution.hpp"
#include "wpg/analysis/run_metrics.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/batch_index.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/datasets/study_design/study.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

void checkOutputFolder(const fs::path& output, const std::string& study) {
  // Never over the study, a device, a folder or a file that is not HDF5 (output_file.hpp).
  try {
    datasets::checkOutputPath(output.string(), datasets::OutputKind::kHdf5, {study});
  } catch (const datasets::InputError& e) {
    throw UsageError(e.what());
  }
  checkWritableParent(output);
}

// OUT.h5 -> OUT.summary.<extension>
std::string besideOutput(const fs::path& output, const std::string& extension) {
  fs::path path = output;
  path.replace_extension(".summary." + extension);
  return path.string();
}

int drawSummaryFigure(const std::string& batch_file, const std::string& figure) {
  const std::string script = (fs::path(dataDirectory()) / "analysis" / "plot_batch.py").string();
  return runAnalysisScript(script, {batch_file, "-o", figure});
}

// "K/N" -> {K, N} with 0 <= K < N.
std::pair<int, int> parseShard(const std::string& text) {
  const auto bad = [&]() {
    return UsageError("--shard: expected K/N, slice K of N with 0 <= K < N (e.g. 0/4), got '" +
                      text + "'");
  };
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == text.size()) throw bad();
  const std::string k = text.substr(0, slash), n = text.substr(slash + 1);
  if (k.find_first_not_of("0123456789") != std::string::npos ||
      n.find_first_not_of("0123456789") != std::string::npos || k.size() > 9 || n.size() > 9) {
    throw bad();
  }
  const int shard = std::stoi(k), count = std::stoi(n);
  if (count < 1 || shard >= count) throw bad();
  return {shard, count};
}

}  // namespace

int finishBatchFile(const std::string& batch_file, bool plot) {
  const fs::path output(batch_file);
  const datasets::BatchSummaryTable table = datasets::readBatchSummary(output.string());
  writeTableCsv(table, besideOutput(output, "csv"));
  writeTableMarkdown(table, besideOutput(output, "md"), "Study " + table.study,
                     std::to_string(table.rows) +
                         " runs; units in the header; definitions: datasets/METRICS.md.");
  std::size_t failed = 0;
  for (std::size_t c = 0; c < table.column_names.size(); ++c) {
    if (table.column_names[c] != "exit_status") continue;
    for (const std::string& cell : table.cells[c]) failed += cell != "0";
  }
  std::cout << "wrote " << output.string() << " (" << table.rows << " runs), "
            << besideOutput(output, "csv") << ", " << besideOutput(output, "md");
  if (plot) {
    const std::string figure = besideOutput(output, "png");
    if (drawSummaryFigure(output.string(), figure) == 0) {
      std::cout << ", " << figure;
    } else {
      std::cout.flush();
      printWarning("the summary figure could not be drawn (Python with h5py and matplotlib?)");
    }
  }
  std::cout << "\n";
  if (failed > 0) {
    std::cout.flush();
    printError(std::to_string(failed) + " of " + std::to_string(table.rows) +
               " runs failed (exit_status in /batch/summary says which; datasets written)");
    return kExitRunFailed;
  }
  return kExitSuccess;
}

int batchCommand(const BatchOptions& options) {
  if (options.threads < 1) throw UsageError("-j: expected a number of worker threads >= 1");
  const fs::path output(options.output);
  if (options.output.empty()) throw UsageError("-o: expected the batch file to write (OUT.h5)");
  const bool sharded = !options.shard.empty();
  const std::pair<int, int> slice = sharded ? parseShard(options.shard) : std::pair<int, int>{0, 1};
  if (sharded && mpi::launched()) {
    throw UsageError("--shard: a slice runs without MPI (one task of a job array); under an MPI "
                     "launcher the ranks share the study among themselves");
  }
  std::error_code ec;
  if (!fs::is_regular_file(options.study, ec)) {
    throw UsageError(options.study + ": cannot read the study file: no such file");
  }
  // Everything about the input is checked before anything is written.
  datasets::Study study;
  const auto check_input = [&] {
    study = datasets::loadStudy(
        options.study, [](const std::string& base) { return resolveScenarioPath(base); },
        robotsDirectory(), options.threads);
    checkOutputFolder(output, options.study);
    std::set<std::string> replayed_robots;
    for (const datasets::StudyRun& run : study.runs) {
      if (run.scenario.replay) replayed_robots.insert(run.scenario.robot);
    }
    for (const std::string& robot : replayed_robots) (void)loadRobotModel(robot);
  };
  std::optional<mpi::World> world;
  if (sharded) {
    check_input();  // a slice is one process, whatever launched it
  } else {
    world = checkInputWhileMpiStarts(check_input);
  }

  const std::vector<datasets::SummaryColumn> columns = runSummaryColumns();
  if (world) {
    // One worker per rank unless -j says otherwise: a rank per core is the usual launch.
    const bool root = runStudyOnRanks(
        *world, study, columns, {options.output, options.resume, options.threads_given ? options.threads : 1},
        [](const datasets::StudyRun&, const ScenarioOutcome& outcome) {
          return runSummaryValues(outcome);
        },
        nullptr, nullptr);
    const int status = root ? finishBatchFile(options.output, options.plot) : kExitSuccess;
    mpi::finish();
    return status;
  }
  const std::string shard_label = sharded ? datasets::shardSliceLabel(slice.first, slice.second) : "";
  if (options.resume && fs::exists(output, ec) && !datasets::isDamagedHdf5File(output.string())) {
    // A slice finishes its own shard only (and a whole batch is not finished as a slice).
    const std::string label = datasets::readShardContents(output.string()).label;
    if (label != shard_label) {
      throw datasets::InputError(
          output.string() + ": cannot resume: it is " +
          (label.empty() ? std::string("not a shard") : "shard " + label) + ", not " +
          (shard_label.empty() ? std::string("a whole batch") : "shard " + shard_label) +
          " (file left as it is)");
    }
  }
  std::unique_ptr<datasets::BatchDatasetWriter> writer;
  if (options.resume && fs::exists(output, ec) && datasets::isDamagedHdf5File(output.string())) {
    // Killed inside HDF5's write of a run: nothing of it can be trusted. Kept aside, not
    // removed, and the study starts again (the same runs give the same file).
    const std::string aside = datasets::moveDamagedFileAside(output.string());
    std::cerr << study.name << ": " << output.string()
              << " cannot be read by HDF5 (killed inside a write); moved to " << aside
              << ", starting again\n";
  }
  if (options.resume && fs::exists(output, ec)) {
    writer = datasets::BatchDatasetWriter::resume(output.string(), study, columns);
  } else {
    if (output.has_parent_path()) fs::create_directories(output.parent_path(), ec);
    writer = datasets::BatchDatasetWriter::create(output.string(), study, columns, shard_label);
  }

  std::vector<const datasets::StudyRun*> todo;
  for (const datasets::StudyRun& run : study.runs) {
    if (!datasets::inShardSlice(run.index, slice.first, slice.second)) continue;
    if (!writer->done()[run.index]) todo.push_back(&run);
  }
  std::size_t slice_runs = 0;
  for (const datasets::StudyRun& run : study.runs) {
    slice_runs += datasets::inShardSlice(run.index, slice.first, slice.second);
  }
  const std::size_t already = slice_runs - todo.size();
  if (already > 0) {
    std::cerr << study.name << ": resuming, " << already << " of " << slice_runs
              << " runs already in " << output.string() << "\n";
  }
  BatchProgress progress(study.name, todo.size(), stderr);
  runStudyInto(
      todo, options.threads, &progress, writer.get(),
      [](const datasets::StudyRun&, const ScenarioOutcome& outcome) {
        return runSummaryValues(outcome);
      },
      nullptr);
  progress.finish();
  writer->close();
  if (sharded) {
    std::cout << "wrote " << output.string() << " (shard " << shard_label << ": " << slice_runs
              << " of " << study.runs.size() << " runs; join the shards with `wpg merge`)\n";
    if (progress.failures() > 0) {
      std::cout.flush();
      printError(std::to_string(progress.failures()) + " of these runs failed (exit_status in "
                 "/batch/summary says which; datasets written)");
      return kExitRunFailed;
    }
    return kExitSuccess;
  }
  return finishBatchFile(output.string(), options.plot);
}

}  // namespace wpg::cli
