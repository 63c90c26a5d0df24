// The batch file of a study (wpg/datasets/storage/batch_dataset.hpp; layout: datasets/SCHEMA.md).
//
// Why the summary table is fixed-size, contiguous and allocated early: a row is then written
// in place, never moving data that the last flushed state of the file points to, so that a
// batch killed between two flushes leaves the table as it was at the last flush.
#include "wpg/datasets/storage/batch_dataset.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include <H5Cpp.h>

#include "batch_fields.hpp"
#include "external_link_guard.hpp"
#include "hdf5_bounded_reading.hpp"
#include "string_heap_check.hpp"
#include "hdf5_writing.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "provenance_attributes.hpp"
#include "run_group_writing.hpp"
#include "wpg/datasets/storage/read_limits.hpp"
#include "wpg/datasets/input/yaml_input.hpp"
#include "wpg/version.hpp"


namespace wpg::datasets {
namespace {

using namespace detail;  // NOLINT: the HDF5 helpers

constexpr const char* kSummaryPath = "/batch/summary";

std::string sweepColumn(const std::string& key) { return "sweep." + key; }

// A small metadata cache: every flush walks the whole cache, which otherwise keeps the
// (clean) metadata of every run written so far, making a flush cost grow with the runs.
H5::FileAccPropList smallMetadataCache() {
  H5::FileAccPropList access;
  H5AC_cache_config_t config;
  config.version = H5AC__CURR_CACHE_CONFIG_VERSION;
  if (H5Pget_mdc_config(access.getId(), &config) < 0) return access;
  config.set_initial_size = true;
  config.initial_size = 1 << 20;
  config.min_size = 1 << 19;
  config.max_size = 1 << 20;
  H5Pset_mdc_config(access.getId(), &config);
  return access;
}

// The table's column names, in order: index, name, the swept keys, done, exit_status, the
// caller's columns.
std::vector<std::string> columnNames(const Study& study, const std::vector<SummaryColumn>& columns) {
  std::vector<std::string> names = {"index", "name"};
  for (const std::string& key : study.keys) names.push_back(sweepColumn(key));
  names.push_back("done");
  names.push_back("exit_status");
  for (const SummaryColumn& column : columns) names.push_back(column.name);
  return names;
}

// A column of the summary table and its dataspace, kept: the table never changes size, and
// asking HDF5 for the dataspace and making the one-cell memory space for each of a run's ~16
// cells was ~5 % of the batch writer's serial work.
// Its last reference is closed quietly after a failure (QuietLastReference).
struct Column {
  QuietLastReference last_reference;
  H5::DataSet dataset;
  H5::DataSpace space;
  explicit Column(H5::DataSet set = {})
      : last_reference(set.getId() > 0 ? set.getId() : -1), dataset(std::move(set)) {
    if (dataset.getId() > 0) space = dataset.getSpace();
  }
};

// A fixed-size 1-D column of `rows`, contiguous, allocated and filled with `fill` at creation.
Column createColumn(H5::Group& table, const std::string& name, hsize_t rows,
                         const H5::DataType& file_type, const H5::DataType& memory_type,
                         const void* fill, const char* units, const std::string& description) {
  H5::DSetCreatPropList properties;
  properties.setLayout(H5D_CONTIGUOUS);
  properties.setAllocTime(H5D_ALLOC_TIME_EARLY);
  if (fill) {
    properties.setFillValue(memory_type, fill);
    properties.setFillTime(H5D_FILL_TIME_ALLOC);
  }
  const H5::DataSpace space(1, &rows);
  Column column(table.createDataSet(name, file_type, space, properties));
  writeStringAttribute(column.dataset, "units", units);
  writeStringAttribute(column.dataset, "description", description);
  return column;
}

void writeCell(Column& column, hsize_t row, const H5::DataType& memory_type, const void* value) {
  static const hsize_t count = 1;
  static const H5::DataSpace* const one = new H5::DataSpace(1, &count);  // never destroyed
  column.space.selectHyperslab(H5S_SELECT_SET, &count, &row);
  column.dataset.write(value, memory_type, *one, column.space);
}

H5::StrType stringType() {
  H5::StrType type(H5::PredType::C_S1, H5T_VARIABLE);
  type.setCset(H5T_CSET_UTF8);
  return type;
}

// The study's columns of the table (index, name, each swept key), `kBlockRows` rows at a time
// from the runs' descriptions (study_runs.hpp): the memory does not grow with the rows.
constexpr std::size_t kBlockRows = 4096;

void writeStudyColumns(H5::Group& table, const Study& study, BatchRows rows, hsize_t count) {
  Column index = createColumn(table, "index", count, H5::PredType::STD_I32LE,
                              H5::PredType::NATIVE_INT, nullptr, "1",
                              "index of the run in the study's expansion");
  Column name = createColumn(table, "name", count, stringType(), stringType(), nullptr, "1",
                             "group of the run under /runs");
  std::vector<Column> swept;
  for (std::size_t k = 0; k < study.keys.size(); ++k) {
    const std::string description = "swept value of '" + study.keys[k] + "'";
    if (study.key_numeric[k]) {
      swept.push_back(createColumn(table, sweepColumn(study.keys[k]), count,
                                   H5::PredType::IEEE_F64LE, H5::PredType::NATIVE_DOUBLE, nullptr,
                                   "as the scenario key", description));
    } else {
      swept.push_back(createColumn(table, sweepColumn(study.keys[k]), count, stringType(),
                                   stringType(), nullptr, "as the scenario key",
                                   description + " (YAML flow text)"));
    }
  }
  std::vector<int> indices;
  std::vector<std::string> names;
  std::vector<std::vector<double>> numbers(study.keys.size());
  std::vector<std::vector<std::string>> texts(study.keys.size());
  std::vector<const char*> pointers;
  for (hsize_t start = 0; start < count; start += kBlockRows) {
    const hsize_t block = std::min<hsize_t>(kBlockRows, count - start);
    indices.clear();
    names.clear();
    for (auto& column : numbers) column.clear();
    for (auto& column : texts) column.clear();
    for (hsize_t row = start; row < start + block; ++row) {
      const StudyRun run = study.runs.describe(rows.runOf(row));
      indices.push_back(static_cast<int>(run.index));
      names.push_back(run.name);
      for (std::size_t k = 0; k < study.keys.size(); ++k) {
        if (study.key_numeric[k]) {
          numbers[k].push_back(run.swept[k].number);
        } else {
          texts[k].push_back(run.swept[k].value);
        }
      }
    }
    const H5::DataSpace memory(1, &block);
    const auto write = [&](Column& column, const void* data, const H5::DataType& type) {
      column.space.selectHyperslab(H5S_SELECT_SET, &block, &start);
      column.dataset.write(data, type, memory, column.space);
    };
    const auto writeTexts = [&](Column& column, const std::vector<std::string>& values) {
      pointers.clear();
      for (const std::string& value : values) pointers.push_back(value.c_str());
      write(column, pointers.data(), stringType());
    };
    write(index, indices.data(), H5::PredType::NATIVE_INT);
    writeTexts(name, names);
    for (std::size_t k = 0; k < study.keys.size(); ++k) {
      if (study.key_numeric[k]) {
        write(swept[k], numbers[k].data(), H5::PredType::NATIVE_DOUBLE);
      } else {
        writeTexts(swept[k], texts[k]);
      }
    }
  }
}

}  // namespace

// The fields of a batch file's runs as text ("all" without the root attribute `fields`).
std::string storedFieldsText(const H5::H5File& file, const std::string& path) {
  if (!file.attrExists("fields")) return RunFields::all().text();
  const std::vector<std::string> names =
      detail::readStringListAttribute(file, "fields", path, "/:");
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

namespace {

[[noreturn]] void rethrowHdf5(const std::string& path, const std::string& what,
                              const H5::Exception& error) {
  throw std::runtime_error(path + ": cannot " + what + " (" + error.getFuncName() + ": " +
                           error.getDetailMsg() + ")");
}

}  // namespace

struct BatchDatasetWriter::Handles {
  H5::H5File file;
  H5::Group runs;
  Column done, exit_status;
  std::vector<Column> columns;  // the caller's, in order
};

BatchDatasetWriter::BatchDatasetWriter(std::string path, std::vector<SummaryColumn> columns,
                                       BatchRows rows)
    : path_(std::move(path)), columns_(std::move(columns)), rows_(rows), handles_(new Handles) {}

BatchDatasetWriter::~BatchDatasetWriter() {
  try {
    close();
  } catch (...) {  // a destructor does not throw; close() reports errors to callers that ask
  }
}

void BatchDatasetWriter::close() {
  if (!handles_) return;
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  std::unique_ptr<Handles> handles = std::move(handles_);
  try {
    handles->columns.clear();
    for (Column* column : {&handles->done, &handles->exit_status}) {
      column->space.close();
      column->dataset.close();
    }
    handles->runs.close();
    handles->file.close();
  } catch (const H5::Exception& error) {
    // HDF5 1.10 frees part of a file whose close failed (a full disk, a file size limit):
    // closing it again, as the handles' destructors would, crashes. They are left (the process
    // is about to stop on this error).
    (void)handles.release();
    rethrowHdf5(path_, "close the batch file", error);
  }
}

std::unique_ptr<BatchDatasetWriter> BatchDatasetWriter::create(
    const std::string& path, const Study& study, const std::vector<SummaryColumn>& columns,
    const std::string& shard_label, BatchRows rows) {
  std::unique_ptr<BatchDatasetWriter> writer(new BatchDatasetWriter(path, columns, rows));
  writer->fields_ = study.fields;
  const hsize_t count = rows.count(study.runs.size());
  writer->done_.assign(count, false);
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  try {
    Handles& h = *writer->handles_;
    h.file = H5::H5File(path, H5F_ACC_TRUNC, H5::FileCreatPropList::DEFAULT, smallMetadataCache());
    forgoWriteOutOnClose(path);
    GroupImage root;  // the file's attributes
    writeIntAttribute(root, "schema_version", kRunDatasetSchemaVersion);
    writeIntAttribute(root, "batch_schema_version", kBatchDatasetSchemaVersion);
    writeStringAttribute(root, "wpg_version", WPG_VERSION_STRING);
    writeProvenanceAttributes(root);
    writeStringAttribute(root, "created_by", study.created_by);
    writeStringAttribute(root, "study", study.text);
    writeStringAttribute(root, "study_name", study.name);
    writeStringAttribute(root, "study_fingerprint", study.fingerprint);
    writeIntAttribute(root, "run_count", static_cast<int>(study.runs.size()));
    writeStringListAttribute(root, "swept_keys", study.keys);
    if (!shard_label.empty()) writeStringAttribute(root, "shard", shard_label);
    // Lean runs (run_fields.hpp): absent, every field, as in every file written before.
    if (!study.fields.isAll()) writeStringListAttribute(root, "fields", study.fields.names());
    commit(root, h.file.getId());
    h.runs = h.file.createGroup("runs");
    H5::Group batch = h.file.createGroup("batch");
    H5::Group table = batch.createGroup("summary");
    writeStringAttribute(table, "description",
                         rows.stride == 1 && rows.first == 0 ? kSummaryDescription
                                                             : kSliceSummaryDescription);
    writeStringListAttribute(table, "columns", columnNames(study, columns));

    writeStudyColumns(table, study, rows, count);
    const unsigned char not_done = 0;
    h.done = createColumn(table, "done", count, H5::PredType::STD_U8LE, H5::PredType::NATIVE_UCHAR,
                          &not_done, "1", "1 when the run is in the file");
    const int no_status = -1;
    h.exit_status = createColumn(table, "exit_status", count, H5::PredType::STD_I32LE,
                                 H5::PredType::NATIVE_INT, &no_status, "1",
                                 "as `wpg run`: 0 the walk succeeded, 1 it failed; -1 not run");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const SummaryColumn& column : columns) {
      if (column.integer) {
        h.columns.emplace_back(createColumn(table, column.name, count, H5::PredType::STD_I32LE,
                                            H5::PredType::NATIVE_INT, &no_status,
                                            column.units.c_str(), column.description));
      } else {
        h.columns.emplace_back(createColumn(table, column.name, count, H5::PredType::IEEE_F64LE,
                                            H5::PredType::NATIVE_DOUBLE, &nan,
                                            column.units.c_str(), column.description));
      }
    }
    h.file.flush(H5F_SCOPE_GLOBAL);
  } catch (const H5::Exception& error) {
    rethrowHdf5(path, "create the batch file", error);
  }
  return writer;
}

std::unique_ptr<BatchDatasetWriter> BatchDatasetWriter::resume(
    const std::string& path, const Study& study, const std::vector<SummaryColumn>& columns,
    BatchRows batch_rows) {
  std::unique_ptr<BatchDatasetWriter> writer(new BatchDatasetWriter(path, columns, batch_rows));
  writer->fields_ = study.fields;
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  const auto refuse = [&](const std::string& why) {
    throw InputError(path + ": cannot resume: " + why + " (file left as it is)");
  };
  try {
    if (!H5::H5File::isHdf5(path)) refuse("not an HDF5 file");
    // Checked read-only first: a file of another study is not even opened for writing.
    {
      H5::H5File file(path, H5F_ACC_RDONLY);
      if (!file.attrExists("study_name") || !file.attrExists("study_fingerprint")) {
        refuse("not a batch file (no root attribute study_name)");
      }
      // Read bounded (hdf5_bounded_reading.hpp): the file may be anyone's.
      const std::string name = detail::readStringAttribute(file, "study_name", path, "/:");
      const std::string fingerprint =
          detail::readStringAttribute(file, "study_fingerprint", path, "/:");
      if (name != study.name || fingerprint != study.fingerprint) {
        refuse("it holds study '" + name + "' (fingerprint " + fingerprint + "), not '" +
               study.name + "' (fingerprint " + study.fingerprint + ")");
      }
      // A layout this wpg does not know (a later version's) is not written into.
      if (!file.attrExists("batch_schema_version")) refuse("no root attribute batch_schema_version");
      const double version =
          detail::readNumberAttribute(file, "batch_schema_version", path, "/:");
      if (version != kBatchDatasetSchemaVersion) {
        std::ostringstream text;
        text << version;
        refuse("its batch_schema_version is " + text.str() + ", this wpg writes " +
               std::to_string(kBatchDatasetSchemaVersion));
      }
      if (!file.nameExists("batch") || !file.nameExists(kSummaryPath)) refuse("no /batch/summary");
      const H5::Group table = file.openGroup(kSummaryPath);
      if (detail::readStringListAttribute(table, "columns", path, kSummaryPath + std::string(":")) !=
          columnNames(study, columns)) {
        refuse("its summary columns differ from this wpg's (written by another version?)");
      }
      const std::string stored = storedFieldsText(file, path);
      if (stored != study.fields.text()) {
        refuse("its runs store the fields " + stored + ", this batch asks for " +
               study.fields.text() + " (fields: in the study, or --fields)");
      }
    }
    Handles& h = *writer->handles_;
    h.file = H5::H5File(path, H5F_ACC_RDWR, H5::FileCreatPropList::DEFAULT, smallMetadataCache());
    h.runs = h.file.openGroup("runs");
    H5::Group table = h.file.openGroup(kSummaryPath);
    h.done = Column(table.openDataSet("done"));
    h.exit_status = Column(table.openDataSet("exit_status"));
    for (const SummaryColumn& column : columns) h.columns.emplace_back(table.openDataSet(column.name));
    const std::size_t rows = batch_rows.count(study.runs.size());
    if (h.done.space.getSimpleExtentNpoints() != static_cast<hssize_t>(rows)) {
      refuse("its summary has another number of rows");
    }
    std::vector<unsigned char> done(rows);
    h.done.dataset.read(done.data(), H5::PredType::NATIVE_UCHAR);
    writer->done_.assign(rows, false);
    for (std::size_t i = 0; i < rows; ++i) {
      const std::string name = study.runs.describe(batch_rows.runOf(i)).name;
      const bool group = h.runs.nameExists(name);
      if (done[i] && group) {
        writer->done_[i] = true;
      } else if (group) {
        h.runs.unlink(name);  // half-written when the batch was killed: run again
      }
    }
    h.file.flush(H5F_SCOPE_GLOBAL);
  } catch (const H5::Exception& error) {
    throw InputError(path + ": cannot resume: not a readable batch file (" +
                     error.getFuncName() + ": " + error.getDetailMsg() + ")");
  }
  return writer;
}

PreparedRun BatchDatasetWriter::prepare(const BatchRunRecord& record) {
  const StudyRun& run = *record.run;
  auto runs = std::make_shared<GroupImage>();  // the image of /runs, this run's group in it
  RunGroupParts parts;
  parts.checks = record.checks;
  GroupImage& group = buildRunGroup(*runs, run.name, run.scenario, *record.result,
                                    record.clearances, record.multibody, record.goal, parts,
                                    record.fields);
  writeStringAttribute(group, "scenario", resolvedScenarioText(run.scenario));
  writeIntAttribute(group, "batch_index", static_cast<int>(run.index));
  std::vector<std::string> keys;
  for (const SweptValue& value : run.swept) {
    keys.push_back(value.key);
    if (value.numeric) {
      writeDoubleAttribute(group, sweepColumn(value.key), value.number);
    } else {
      writeStringAttribute(group, sweepColumn(value.key), value.value);
    }
  }
  writeStringListAttribute(group, "swept_keys", keys);
  return PreparedRun{std::move(runs)};
}

void BatchDatasetWriter::write(const BatchRunRecord& record, const PreparedRun* prepared) {
  const StudyRun& run = *record.run;
  if (record.values.size() != columns_.size()) {
    throw std::invalid_argument("BatchDatasetWriter::write: " + std::to_string(record.values.size()) +
                                " values for " + std::to_string(columns_.size()) + " columns");
  }
  if (record.fields != fields_) {
    throw std::invalid_argument("BatchDatasetWriter::write: a run of the fields " +
                                record.fields.text() + " into a file of " + fields_.text());
  }
  // Built here, off the lock, when the caller has not built it.
  const PreparedRun built = prepared && prepared->image ? PreparedRun{} : prepare(record);
  const GroupImage& image = prepared && prepared->image ? *prepared->image : *built.image;
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  try {
    Handles& h = *handles_;
    try {
      commit(image, h.runs.getId());
    } catch (const std::runtime_error& error) {
      throw std::runtime_error(path_ + ": cannot write run " + run.name + " (" + error.what() +
                               ")");
    }
    // One flush per run, after the group, its row and `done`: until it, the file on disk is the
    // one of the last flush (the metadata lives in HDF5's cache; the summary is written in
    // place). Should the cache spill a new group's metadata earlier, the group has no `done`
    // and --resume removes it and runs it again.
    const hsize_t row = rows_.rowOf(run.index);
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      if (columns_[c].integer) {
        const double value = record.values[c];
        const int cell = std::isfinite(value) ? static_cast<int>(std::lround(value)) : -1;
        writeCell(h.columns[c], row, H5::PredType::NATIVE_INT, &cell);
      } else {
        writeCell(h.columns[c], row, H5::PredType::NATIVE_DOUBLE, &record.values[c]);
      }
    }
    writeCell(h.exit_status, row, H5::PredType::NATIVE_INT, &record.exit_status);
    // The run's group and row first, then its `done` flag: a flag on disk always follows the
    // group it marks (written together, a kill between the raw-data write of the flag and the
    // flush of the group's metadata left `done = 1` for a group that was not in the file).
    h.file.flush(H5F_SCOPE_GLOBAL);
    const unsigned char done = 1;
    writeCell(h.done, row, H5::PredType::NATIVE_UCHAR, &done);
    h.file.flush(H5F_SCOPE_GLOBAL);
  } catch (const H5::Exception& error) {
    rethrowHdf5(path_, "write run " + run.name, error);
  }
  done_[rows_.rowOf(run.index)] = true;
}

bool isBatchFile(const std::string& path) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  try {
    const H5::H5File file = detail::openFileForReading(path);
    return file.attrExists("study_name");
  } catch (const H5::Exception& error) {
    throw InputError(path + ": cannot read the file (" + error.getDetailMsg() + ")");
  }
}

namespace {
herr_t visitNothing(hid_t, const char*, const H5O_info_t*, void*) { return 0; }
}  // namespace

std::string moveDamagedFileAside(const std::string& path) {
  std::error_code ec;
  std::string aside = path + ".damaged";
  for (int n = 2; std::filesystem::exists(aside, ec); ++n) {
    aside = path + ".damaged-" + std::to_string(n);
  }
  std::filesystem::rename(path, aside, ec);
  if (ec) throw std::runtime_error("cannot move the damaged " + path + " aside: " + ec.message());
  return aside;
}

bool isDamagedHdf5File(const std::string& path) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  const bool hdf5 = [&] {
    try {
      return H5::H5File::isHdf5(path);
    } catch (const H5::Exception&) {
      return true;  // a signature HDF5 itself cannot follow
    }
  }();
  if (!hdf5) return false;
  try {
    const H5::H5File file(path, H5F_ACC_RDONLY);
    // Every object header: a torn write shows as one HDF5 cannot decode.
    if (H5Ovisit(file.getId(), H5_INDEX_NAME, H5_ITER_NATIVE, visitNothing, nullptr) < 0)
      return true;
    // Every variable-length string's global heap: HDF5 loops forever on a zeroed one, and
    // aborts on one overwritten (the object headers above are fine then).
    detail::checkVariableDataUnder(file.openGroup("/"), path);
    // A batch file killed while it was created: its summary table is not complete.
    if (file.attrExists("study_name") &&
        !(file.nameExists("batch") && file.nameExists(kSummaryPath) &&
          file.openGroup(kSummaryPath).nameExists("done")))
      return true;
  } catch (const H5::Exception&) {
    return true;
  } catch (const InputError&) {
    return true;
  }
  return false;
}

BatchSummaryTable readBatchSummary(const std::string& path) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  BatchSummaryTable summary;
  try {
    const H5::H5File file = detail::openFileForReading(path);
    summary.study = detail::readStringAttribute(file, "study_name", path, "/:");
    const H5::Group table = file.openGroup(kSummaryPath);
    summary.column_names =
        detail::readStringListAttribute(table, "columns", path, kSummaryPath + std::string(":"));
    for (const std::string& name : summary.column_names) {
      const H5::DataSet dataset = table.openDataSet(name);
      const std::string where = kSummaryPath + std::string("/") + name;
      // One row per run: 1-D, bounded before the cells are allocated, as long as the others.
      const std::vector<hsize_t> dims = detail::boundedExtent(
          dataset.getSpace(), sizeof(double), kMaxReadElements, path, "dataset " + where);
      if (dims.size() != 1 || (!summary.cells.empty() && dims[0] != summary.rows)) {
        throw InputError(path + ": dataset " + where + ": expected a column of " +
                         (summary.cells.empty() ? std::string("n") : std::to_string(summary.rows)) +
                         " rows (as the table's others)");
      }
      const hsize_t rows = dims[0];
      summary.rows = rows;
      summary.column_units.push_back(detail::readStringAttribute(dataset, "units", path, where + ":"));
      std::vector<std::string> cells;
      const H5T_class_t type = dataset.getTypeClass();
      if (type == H5T_STRING) {
        cells = detail::readVariableStrings(dataset, path, "dataset " + where);
      } else if (type == H5T_FLOAT) {
        std::vector<double> values(rows);
        dataset.read(values.data(), H5::PredType::NATIVE_DOUBLE);
        for (const double value : values) {
          cells.push_back(std::isfinite(value) ? formatNumber(value)
                                               : std::isnan(value) ? "nan"
                                               : value > 0         ? "inf"
                                                                   : "-inf");
        }
      } else {
        std::vector<long long> values(rows);
        dataset.read(values.data(), H5::PredType::NATIVE_LLONG);
        for (const long long value : values) cells.push_back(std::to_string(value));
      }
      summary.cells.push_back(std::move(cells));
    }
  } catch (const H5::Exception& error) {
    if (std::string why = detail::takeExternalLinkRefusal(); !why.empty()) throw InputError(why);
    throw InputError(path + ": cannot read /batch/summary (" + error.getDetailMsg() + ")");
  }
  return summary;
}

}  // namespace wpg::datasets
