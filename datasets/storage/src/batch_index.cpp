// Shard files and the index that joins them (wpg/datasets/storage/batch_index.hpp; layout:
// datasets/SCHEMA.md, "Sharded batches").
//
// The index is built from the first shard's objects: its root attributes (but `shard`), and a
// summary table of every run whose columns have the first shard's types, layouts, fill values
// and attributes, so that it holds what `wpg batch` would write; then each run's row of every
// column is copied from the shard that holds the run, reading only those rows (point
// selections: the work grows with the runs, not with runs x shards). A slice's table holds its
// runs only (its `index` column names them), an MPI rank's every run.
#include "wpg/datasets/storage/batch_index.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>

#include <H5Cpp.h>
#include <sys/resource.h>

#include "batch_fields.hpp"
#include "hdf5_bounded_reading.hpp"
#include "string_heap_check.hpp"
#include "hdf5_writing.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/input_limits.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"

namespace fs = std::filesystem;

namespace wpg::datasets {
namespace {

constexpr const char* kSummaryPath = "/batch/summary";

// Every root attribute of `from` but `skip` onto `to`, with its own type and shape.
void copyAttributes(hid_t from, hid_t to, const std::string& skip) {
  H5O_info_t info;
  if (H5Oget_info(from, &info) < 0) throw H5::Exception("H5Oget_info", "cannot list attributes");
  for (hsize_t i = 0; i < info.num_attrs; ++i) {
    const hid_t attribute = H5Aopen_by_idx(from, ".", H5_INDEX_NAME, H5_ITER_INC, i, H5P_DEFAULT,
                                           H5P_DEFAULT);
    if (attribute < 0) throw H5::Exception("H5Aopen_by_idx", "cannot open an attribute");
    const ssize_t name_length = H5Aget_name(attribute, 0, nullptr);
    std::string name(static_cast<std::size_t>(name_length), '\0');
    H5Aget_name(attribute, name.size() + 1, name.data());
    if (name == skip) {
      H5Aclose(attribute);
      continue;
    }
    const hid_t type = H5Aget_type(attribute), space = H5Aget_space(attribute);
    const hssize_t points = H5Sget_simple_extent_npoints(space);
    // Variable-length strings are read as char* in memory, written back from them.
    std::vector<unsigned char> buffer(static_cast<std::size_t>(points) * H5Tget_size(type));
    herr_t status = H5Aread(attribute, type, buffer.data());
    const hid_t copy = status < 0 ? -1 : H5Acreate2(to, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
    if (copy >= 0) status = H5Awrite(copy, type, buffer.data());
    if (H5Tdetect_class(type, H5T_VLEN) > 0 || H5Tis_variable_str(type) > 0) {
      H5Dvlen_reclaim(type, space, H5P_DEFAULT, buffer.data());
    }
    if (copy >= 0) H5Aclose(copy);
    H5Sclose(space);
    H5Tclose(type);
    H5Aclose(attribute);
    if (copy < 0 || status < 0) throw H5::Exception("copyAttributes", "cannot copy attribute " + name);
  }
}

// Copies the elements `from_rows` of a 1-D dataset to the elements `to_rows` of another of the
// same type (variable-length strings too: read as pointers, written, then reclaimed).
void copyRows(const H5::DataSet& from, H5::DataSet& to, const std::vector<hsize_t>& from_rows,
              const std::vector<hsize_t>& to_rows) {
  if (from_rows.empty()) return;
  const H5::DataType type = from.getDataType();
  std::vector<unsigned char> buffer(from_rows.size() * type.getSize());
  H5::DataSpace from_space = from.getSpace(), to_space = to.getSpace();
  from_space.selectElements(H5S_SELECT_SET, from_rows.size(), from_rows.data());
  to_space.selectElements(H5S_SELECT_SET, to_rows.size(), to_rows.data());
  const hsize_t count = from_rows.size();
  const H5::DataSpace memory(1, &count);
  from.read(buffer.data(), type, memory, from_space);
  const bool variable = H5Tis_variable_str(type.getId()) > 0;
  try {
    to.write(buffer.data(), type, memory, to_space);
  } catch (...) {
    if (variable) H5Dvlen_reclaim(type.getId(), memory.getId(), H5P_DEFAULT, buffer.data());
    throw;
  }
  if (variable) H5Dvlen_reclaim(type.getId(), memory.getId(), H5P_DEFAULT, buffer.data());
}

// A column of `rows` rows like `like` (type, layout, fill value, attributes) in `table`.
H5::DataSet createColumnLike(const H5::DataSet& like, H5::Group& table, const std::string& name,
                             hsize_t rows) {
  const H5::DataSpace space(1, &rows);
  const H5::DSetCreatPropList properties = like.getCreatePlist();
  H5::DataSet column = table.createDataSet(name, like.getDataType(), space, properties);
  copyAttributes(like.getId(), column.getId(), "");
  return column;
}

// "runs 3, 7, 11, ... (12 of 48)"
std::string listRuns(const std::vector<std::size_t>& runs, std::size_t total) {
  std::string text = "run" + std::string(runs.size() > 1 ? "s " : " ");
  for (std::size_t i = 0; i < runs.size() && i < 5; ++i) text += (i ? ", " : "") + std::to_string(runs[i]);
  if (runs.size() > 5) text += ", ...";
  return text + " (" + std::to_string(runs.size()) + " of " + std::to_string(total) + ")";
}

// The slice K/N of a label "K/N", or false.
bool parseSliceLabel(const std::string& label, int* shard, int* count) {
  const std::size_t slash = label.find('/');
  if (slash == std::string::npos) return false;
  try {
    *shard = std::stoi(label.substr(0, slash));
    *count = std::stoi(label.substr(slash + 1));
  } catch (const std::exception&) {
    return false;
  }
  return *count > 0 && *shard >= 0 && *shard < *count;
}

// The relative name HDF5 finds `shard` by from the index's folder (H5Lcreate_external: a
// relative target is looked up in the folder of the file holding the link first). Symbolic links
// and '..' are resolved where the system can name the files absolutely; in a working folder
// whose absolute name is over PATH_MAX it cannot, and the names are related as they are given.
std::string relativeTo(const std::string& shard, const std::string& output) {
  std::error_code output_error, shard_error;
  const fs::path resolved_output = fs::weakly_canonical(fs::absolute(output), output_error);
  const fs::path resolved_shard = fs::weakly_canonical(fs::absolute(shard), shard_error);
  if (!output_error && !shard_error) {
    return resolved_shard.lexically_relative(resolved_output.parent_path()).string();
  }
  fs::path folder = fs::path(output).lexically_normal().parent_path();
  if (folder.empty()) folder = ".";
  return fs::path(shard).lexically_normal().lexically_relative(folder).string();
}

// An index of copies holds every run of the shards: at most their sizes added up. Throws
// std::runtime_error (an I/O error: exit 3) when the file size limit or the free space of the
// index's file system is below that.
void checkRoomForCopy(const std::string& output, const std::string& temporary,
                      const std::vector<ShardContents>& contents) {
  std::uintmax_t needed = 0;
  std::error_code ec;
  for (const ShardContents& shard : contents) needed += fs::file_size(shard.path, ec);
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      static_cast<std::uintmax_t>(limit.rlim_cur) < needed) {
    throw std::runtime_error(output + ": cannot write the index: its copies need up to " +
                             std::to_string(needed) + " bytes, over the file size limit of " +
                             std::to_string(limit.rlim_cur) + " bytes (ulimit -f)");
  }
  const fs::space_info space = fs::space(fs::path(temporary).parent_path().empty()
                                             ? fs::path(".")
                                             : fs::path(temporary).parent_path(), ec);
  if (!ec && space.available < needed) {
    throw std::runtime_error(output + ": cannot write the index: its copies need up to " +
                             std::to_string(needed) + " bytes, " +
                             std::to_string(space.available) + " are free on its file system");
  }
}

}  // namespace

std::string shardSliceLabel(int shard, int shard_count) {
  return std::to_string(shard) + "/" + std::to_string(shard_count);
}

std::string mpiRankLabel(int rank, int ranks) {
  return "rank " + std::to_string(rank) + " of " + std::to_string(ranks);
}

ShardContents readShardContents(const std::string& path) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  ShardContents shard;
  shard.path = path;
  try {
    const H5::H5File file = detail::openFileForReading(path);
    if (!file.attrExists("study_name") || !file.attrExists("study_fingerprint") ||
        !file.nameExists("batch") || !file.nameExists(kSummaryPath) || !file.nameExists("runs")) {
      throw InputError(path + ": not a batch or shard file (no study_name, /batch/summary, /runs)");
    }
    shard.study_name = detail::readStringAttribute(file, "study_name", path, "/:");
    shard.study_fingerprint = detail::readStringAttribute(file, "study_fingerprint", path, "/:");
    if (file.attrExists("shard")) shard.label = detail::readStringAttribute(file, "shard", path, "/:");
    shard.fields = storedFieldsText(file, path);
    if (file.attrExists("created_by")) shard.created_by = detail::readStringAttribute(file, "created_by", path, "/:");
    const double run_count =
        file.attrExists("run_count") ? detail::readNumberAttribute(file, "run_count", path, "/:") : -1.0;
    if (!(run_count >= 0 && run_count <= static_cast<double>(kMaxSweepRuns)) ||
        run_count != std::floor(run_count)) {
      throw InputError(path + ": expected a root attribute run_count, a number of runs from 0 to " +
                       std::to_string(kMaxSweepRuns));
    }
    shard.run_count = static_cast<std::size_t>(run_count);
    const H5::Group table = file.openGroup(kSummaryPath);
    if (!table.nameExists("index")) throw InputError(path + ": " + kSummaryPath + " has no index column");
    const H5::DataSet done = table.openDataSet("done");
    const H5::DataSet name = table.openDataSet("name");
    const H5::DataSet index = table.openDataSet("index");
    // One row per run of the file: sizes checked before anything is allocated (a shard can
    // declare 2^40 names in a few kB).
    for (const auto& [column, dataset] : {std::pair<const char*, const H5::DataSet*>{"name", &name},
                                          {"done", &done}, {"index", &index}}) {
      const H5::DataSpace space = dataset->getSpace();
      const hssize_t rows = space.getSimpleExtentNpoints();
      if (space.getSimpleExtentNdims() != 1 || rows < 0 ||
          static_cast<std::uint64_t>(rows) > kMaxBatchFileRuns) {
        throw InputError(path + ": " + kSummaryPath + "/" + column + ": expected at most " +
                         std::to_string(kMaxBatchFileRuns) + " runs (one row each), got " +
                         std::to_string(rows) + " values");
      }
    }
    // Then every string of the shard, once: merge copies its groups (H5Ocopy reads their strings)
    // and --resume its names; HDF5 would loop or crash on a damaged heap.
    detail::checkVariableDataUnder(file.openGroup("/"), path);
    const std::vector<std::string> names = detail::readVariableStrings(name, path, "dataset /batch/summary/name");
    std::vector<unsigned char> flags(names.size());
    std::vector<long long> indices(names.size());
    if (done.getSpace().getSimpleExtentNpoints() != static_cast<hssize_t>(names.size()) ||
        index.getSpace().getSimpleExtentNpoints() != static_cast<hssize_t>(names.size())) {
      throw InputError(path + ": /batch/summary/done, index and name have different lengths");
    }
    if (index.getTypeClass() != H5T_INTEGER) {
      throw InputError(path + ": /batch/summary/index: expected integers");
    }
    done.read(flags.data(), H5::PredType::NATIVE_UCHAR);
    index.read(indices.data(), H5::PredType::NATIVE_LLONG);
    const H5::Group runs = file.openGroup("runs");
    shard.runs.resize(names.size());
    shard.done.assign(names.size(), false);
    for (std::size_t i = 0; i < names.size(); ++i) {
      // Runs of the study, each once, in order: a table of another shape is not merged.
      if (indices[i] < 0 || static_cast<std::uint64_t>(indices[i]) >= shard.run_count ||
          (i > 0 && indices[i] <= indices[i - 1])) {
        throw InputError(path + ": /batch/summary/index: expected increasing run indices below " +
                         std::to_string(shard.run_count) + ", got " + std::to_string(indices[i]) +
                         " in row " + std::to_string(i));
      }
      shard.runs[i] = static_cast<std::size_t>(indices[i]);
      // A flag counts with its group only (batch_dataset.cpp writes the flag after the group).
      shard.done[i] = flags[i] && runs.nameExists(names[i]);
    }
  } catch (const H5::Exception& error) {
    throw InputError(path + ": cannot read it as a batch or shard file (" + error.getDetailMsg() + ")");
  }
  return shard;
}

IndexReport writeBatchIndex(const std::string& output, const std::vector<std::string>& shards,
                            IndexLayout layout,
                            const std::function<void(const std::string& index)>& complete) {
  if (shards.empty()) throw InputError("merge: expected at least one shard file");
  // Every check first: nothing is written for bad input.
  std::vector<ShardContents> contents;
  for (const std::string& path : shards) contents.push_back(readShardContents(path));
  const ShardContents& first = contents.front();
  std::vector<std::string> first_columns;
  {
    std::lock_guard<std::mutex> lock(hdf5Mutex());
    try {
      for (const ShardContents& shard : contents) {
        const H5::H5File file(shard.path, H5F_ACC_RDONLY);
        const std::vector<std::string> columns =
            detail::readStringListAttribute(file.openGroup(kSummaryPath), "columns", shard.path,
                                            std::string(kSummaryPath) + ":");
        if (&shard == &first) first_columns = columns;
        if (shard.study_name != first.study_name ||
            shard.study_fingerprint != first.study_fingerprint || shard.run_count != first.run_count) {
          throw InputError(shard.path + ": holds study '" + shard.study_name + "' (fingerprint " +
                           shard.study_fingerprint + "), not '" + first.study_name +
                           "' (fingerprint " + first.study_fingerprint + ") as " + first.path);
        }
        if (shard.fields != first.fields) {
          throw InputError(shard.path + ": its runs store the fields " + shard.fields + ", those of " +
                           first.path + " " + first.fields +
                           ": shards of one index store the same fields (run the slice again "
                           "with the study's fields)");
        }
        if (columns != first_columns) {
          throw InputError(shard.path + ": its summary columns differ from those of " + first.path +
                           " (written by another wpg command or version?)");
        }
        // Each column one value per run, of the first shard's type: rows are copied between
        // them as they are (a string column where numbers are would fail mid-write).
        const H5::H5File first_file(first.path, H5F_ACC_RDONLY);
        const H5::Group table = file.openGroup(kSummaryPath);
        const H5::Group first_table = first_file.openGroup(kSummaryPath);
        for (const std::string& column : columns) {
          const std::string where = shard.path + ": " + kSummaryPath + "/" + column;
          if (!table.nameExists(column) || table.childObjType(column) != H5O_TYPE_DATASET)
            throw InputError(where + ": expected a summary column (a dataset), got none");
          const H5::DataSet data = table.openDataSet(column);
          const H5::DataSpace space = data.getSpace();
          hsize_t rows = 0;
          if (space.getSimpleExtentNdims() != 1 || (space.getSimpleExtentDims(&rows), rows) !=
                                                       static_cast<hsize_t>(shard.done.size()))
            throw InputError(where + ": expected one value per run (" +
                             std::to_string(shard.done.size()) + " rows)");
          const bool result_column =
              std::find(columns.begin(), columns.end(), "done") <=
              std::find(columns.begin(), columns.end(), column);
          if (result_column && data.getTypeClass() != H5T_INTEGER &&
              data.getTypeClass() != H5T_FLOAT)
            throw InputError(where + ": expected numbers (a result column), got " +
                             (data.getTypeClass() == H5T_STRING ? "text" : "another type"));
          if (!(data.getDataType() == first_table.openDataSet(column).getDataType()))
            throw InputError(where + ": expected the type of the column in " + first.path +
                             " (" + (data.getTypeClass() == H5T_STRING ? "got text" : "got another type") +
                             ")");
        }
      }
    } catch (const H5::Exception& error) {
      throw InputError("merge: cannot read the shards' summary tables (" + error.getDetailMsg() + ")");
    }
  }
  const std::size_t total = first.run_count;
  if (total > kMaxBatchFileRuns) {
    throw InputError("merge: study '" + first.study_name + "' has " + std::to_string(total) +
                     " runs, over the " + std::to_string(kMaxBatchFileRuns) +
                     " an index file holds (nothing written)");
  }
  // Each run from the first file that holds it: its shard and its row there.
  std::vector<int> owner(total, -1);
  std::vector<std::vector<hsize_t>> from_rows(contents.size()), to_rows(contents.size());
  for (std::size_t s = 0; s < contents.size(); ++s) {
    for (std::size_t row = 0; row < contents[s].done.size(); ++row) {
      const std::size_t run = contents[s].runs[row];
      if (owner[run] < 0 && contents[s].done[row]) {
        owner[run] = static_cast<int>(s);
        from_rows[s].push_back(row);
        to_rows[s].push_back(run);
      }
    }
  }
  std::vector<std::size_t> missing;
  for (std::size_t i = 0; i < total; ++i) {
    if (owner[i] < 0) missing.push_back(i);
  }
  if (!missing.empty()) {
    std::string hint;
    int shard = 0, count = 0;
    if (parseSliceLabel(first.label, &shard, &count)) {
      std::set<int> slices;
      for (const std::size_t i : missing) slices.insert(static_cast<int>(i % static_cast<std::size_t>(count)));
      hint = "; missing or unfinished shards:";
      for (const int slice : slices) hint += " " + shardSliceLabel(slice, count);
    }
    throw InputError("merge: " + listRuns(missing, total) + " of study '" + first.study_name +
                     "' are in none of the " + std::to_string(contents.size()) + " files given" +
                     hint + " (nothing written)");
  }

  IndexReport report;
  report.runs = total;
  for (const auto& shard_rows : from_rows) report.shards_used += !shard_rows.empty();

  TemporaryOutput temporary(output);
  // HDF5 1.10's H5Ocopy crashes (a segfault in its own clean-up) when a write inside it fails:
  // the room a copy needs is checked first, so that it never runs out inside H5Ocopy.
  if (layout == IndexLayout::kCopy) checkRoomForCopy(output, temporary.path(), contents);
  {  // the index closed and the lock let go before `complete` reads it
    std::lock_guard<std::mutex> lock(hdf5Mutex());
    H5::Exception::dontPrint();
    try {
      H5::H5File index(temporary.path(), H5F_ACC_TRUNC);
      forgoWriteOutOnClose(temporary.path());  // a copied index is a study's size
      H5::Group runs = index.createGroup("runs");
      H5::Group table = index.createGroup("batch").createGroup("summary");
      std::vector<H5::DataSet> columns;
      {
        const H5::H5File source(first.path, H5F_ACC_RDONLY);
        copyAttributes(source.getId(), index.getId(), "shard");
        copyAttributes(source.openGroup("batch").getId(), index.openGroup("batch").getId(), "");
        const H5::Group source_table = source.openGroup(kSummaryPath);
        copyAttributes(source_table.getId(), table.getId(), "description");
        detail::writeStringAttribute(table, "description", kSummaryDescription);
        for (const std::string& column : first_columns) {
          columns.push_back(createColumnLike(source_table.openDataSet(column), table, column, total));
        }
      }
      for (std::size_t s = 0; s < contents.size(); ++s) {
        if (from_rows[s].empty()) continue;
        const H5::H5File source(contents[s].path, H5F_ACC_RDONLY);
        const H5::Group source_table = source.openGroup(kSummaryPath);
        for (std::size_t c = 0; c < first_columns.size(); ++c) {
          copyRows(source_table.openDataSet(first_columns[c]), columns[c], from_rows[s], to_rows[s]);
        }
        const std::vector<std::string> names = detail::readVariableStrings(
            source_table.openDataSet("name"), contents[s].path, "dataset /batch/summary/name");
        const std::string link_target =
            layout == IndexLayout::kLinks ? relativeTo(contents[s].path, output) : std::string();
        for (const hsize_t row : from_rows[s]) {
          const std::string& name = names[row];
          const std::string object = "/runs/" + name;
          const herr_t status =
              layout == IndexLayout::kLinks
                  ? H5Lcreate_external(link_target.c_str(), object.c_str(), runs.getId(),
                                       name.c_str(), H5P_DEFAULT, H5P_DEFAULT)
                  : H5Ocopy(source.getId(), object.c_str(), runs.getId(), name.c_str(),
                            H5P_DEFAULT, H5P_DEFAULT);
          if (status < 0) throw H5::Exception("writeBatchIndex", "cannot add run " + name);
        }
      }
      columns.clear();
      runs.close();
      table.close();
      index.close();
    } catch (const H5::Exception& error) {
      throw std::runtime_error(output + ": cannot write the index (" + error.getFuncName() + ": " +
                               error.getDetailMsg() + ")");
    }
  }
  if (complete) complete(temporary.path());
  temporary.commit();
  return report;
}

}  // namespace wpg::datasets
