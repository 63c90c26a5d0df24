#pragma once
// One HDF5 file for a whole study (`wpg batch`; layout: datasets/SCHEMA.md, "Batch files"):
// a group /runs/<study>_<index> per finished run in the run schema, with the run's resolved
// scenario and swept values as attributes, and the table /batch/summary, one row per run of
// the study (row = index), its columns allocated when the file is created and filled as runs
// finish. Each finished run is flushed (H5Fflush) before the next is written, so a killed
// batch leaves a file that h5py opens, holding every run it had finished; `done` marks them.
//
// The writer is used from one thread at a time and holds hdf5Mutex() in each call.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/study_design/study.hpp"

namespace wpg::datasets {

struct DatasetChecks;  // dataset_checks.hpp

// The schema version of the batch layout (root attribute `batch_schema_version`).
constexpr int kBatchDatasetSchemaVersion = 1;

// A column of /batch/summary filled from each run's results (the caller's metrics).
struct SummaryColumn {
  std::string name;         // dataset name under /batch/summary, e.g. "cop_margin_min"
  std::string units;        // "m", "s", "1", ...
  std::string description;  // one sentence
  bool integer = false;     // int32 (fill -1) instead of float64 (fill NaN)
};

// The runs a batch file's summary table holds, a row each: first, first + stride, ... up to the
// study's last (a whole batch and an MPI rank's shard: every run; slice K/N: K, K + N, ...).
// A slice's table is its runs' only, so that a slice of 10^7 runs starts as quickly as one of 10.
struct BatchRows {
  std::size_t first = 0;
  std::size_t stride = 1;
  std::size_t count(std::size_t runs) const {
    return runs > first ? (runs - first - 1) / stride + 1 : 0;
  }
  bool holds(std::size_t run) const { return run >= first && (run - first) % stride == 0; }
  std::size_t rowOf(std::size_t run) const { return (run - first) / stride; }
  std::size_t runOf(std::size_t row) const { return first + row * stride; }
};

// The attribute `description` of /batch/summary: a table of every run, a slice's table.
inline constexpr const char* kSummaryDescription =
    "one row per run of the study (row = index); result columns hold their fill value (-1, NaN) "
    "until the run is done";
inline constexpr const char* kSliceSummaryDescription =
    "one row per run of this slice of the study (its run in `index`); result columns hold their "
    "fill value (-1, NaN) until the run is done";

// A finished run as the batch file stores it.
struct BatchRunRecord {
  const StudyRun* run = nullptr;
  const wpg::WalkResult* result = nullptr;
  const FootstepClearances* clearances = nullptr;       // may be null
  const MultibodyRecord* multibody = nullptr;  // may be null (not replayed)
  const GoalOutcome* goal = nullptr;                     // a walk to a goal, else null
  // computeDatasetChecks of this run (the engine's run result holds them), or null: the writer
  // computes them (prepare(), on the worker)
  const DatasetChecks* checks = nullptr;
  // What the run stores (the study's fields: the file's, BatchDatasetWriter::write checks it)
  RunFields fields = RunFields::all();
  int exit_status = 0;                 // 0 the walk succeeded, 1 it failed (as `wpg run`)
  std::vector<double> values;          // one per SummaryColumn, in the writer's order
};


class BatchDatasetWriter {
 public:
  // Compresses the run's datasets for write(); makes no HDF5 call and touches no writer, so any
  // thread may call it at any time. Throws std::invalid_argument as writeRunDataset.
  static PreparedRun prepare(const BatchRunRecord& record);

  // Creates `path` (replacing a file there) with the study's layout: root attributes, /batch,
  // the summary table of the runs `rows` with its index, name and swept columns filled (block
  // by block: the memory does not grow with the rows) and its result columns at their fill
  // values, and an empty /runs. A non-empty `shard_label` makes it a shard file
  // (batch_index.hpp): root attribute `shard`. A study of lean runs (study.fields not all)
  // has the root attribute `fields`, the names of its runs' fields. Throws std::runtime_error
  // on I/O errors.
  static std::unique_ptr<BatchDatasetWriter> create(const std::string& path, const Study& study,
                                                    const std::vector<SummaryColumn>& columns,
                                                    const std::string& shard_label = "",
                                                    BatchRows rows = {});
  // Opens an existing batch file of the same study to finish it. Throws InputError, leaving the
  // file untouched, when it is not a batch file, holds another study (name or fingerprint
  // differ), other summary columns or runs of other fields (root attribute `fields`, absent:
  // all). Runs found half-written (a group without its `done`
  // row: the batch was killed while writing it) are removed, to be run again.
  static std::unique_ptr<BatchDatasetWriter> resume(const std::string& path, const Study& study,
                                                    const std::vector<SummaryColumn>& columns,
                                                    BatchRows rows = {});
  ~BatchDatasetWriter();
  BatchDatasetWriter(const BatchDatasetWriter&) = delete;
  BatchDatasetWriter& operator=(const BatchDatasetWriter&) = delete;

  // Run `run` (of the study, one of the file's rows) is in the file.
  bool done(std::size_t run) const { return done_[rows_.rowOf(run)]; }

  // Writes the run's group and its summary row, marks it done and flushes the file; with
  // `prepared` (from prepare(record)), its chunks as they are.
  void write(const BatchRunRecord& record, const PreparedRun* prepared = nullptr);

  // Closes the file (also done by the destructor); throws on I/O errors.
  void close();

 private:
  struct Handles;
  BatchDatasetWriter(std::string path, std::vector<SummaryColumn> columns, BatchRows rows);
  std::string path_;
  std::vector<SummaryColumn> columns_;
  BatchRows rows_;
  RunFields fields_ = RunFields::all();
  std::vector<bool> done_;  // per row
  std::unique_ptr<Handles> handles_;
};

// The table /batch/summary of a batch file, read back (for summary.csv/.md and `wpg analyze`).
struct BatchSummaryTable {
  std::string study;
  std::vector<std::string> column_names;  // in the table's order (its `columns` attribute)
  std::vector<std::string> column_units;
  // cells[c][row] as text: numbers in shortest round-trip form, "nan" for missing values
  std::vector<std::vector<std::string>> cells;
  std::size_t rows = 0;
};

// Whether `path` is a batch file (has the root attribute `study`). Throws InputError when it
// cannot be read as HDF5.
bool isBatchFile(const std::string& path);

// A file that starts like HDF5 (its signature) but whose objects HDF5 cannot all open: what a
// SIGKILL inside HDF5's write or flush of a run leaves (HDF5 1.10 has no atomic commit; measured
// on `tests/cli/studies/batch_small.yaml`: 4 of 75 kills at random times with the cores loaded,
// 0 of 30 on idle cores). `wpg batch --resume` moves such a file aside and starts the study
// again. Also true for a batch file killed before its summary table was complete. False for a
// readable file and for a file that is not HDF5 at all.
bool isDamagedHdf5File(const std::string& path);
// Renames such a file to PATH.damaged (PATH.damaged-2, -3, ... when taken) and returns the new
// name: kept for a post-mortem, never removed. Throws std::runtime_error when the rename fails.
std::string moveDamagedFileAside(const std::string& path);
BatchSummaryTable readBatchSummary(const std::string& path);

}  // namespace wpg::datasets
