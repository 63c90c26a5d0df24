// Shard files and the index that joins them (wpg/datasets/storage/batch_index.hpp; layout:
// datasets/SCHEMA.md, "Sharded batches").
//
// The index is built from the first shard's objects, not written anew: its root attributes
// (but `shard`) and /batch (H5Ocopy: the summary table with its fill values, layouts and
// attributes) are copied, so that it is the batch file `wpg batch` would write, bit for bit;
// then each run's row of the result columns (from `done` on) is copied from the shard that
// holds the run, reading only those rows (point selections: the work grows with the runs, not
// with runs x shards).
#include "wpg/datasets/storage/batch_index.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>

#include <H5Cpp.h>
#include <sys/resource.h>

#include "hdf5_bounded_reading.hpp"
#include "string_heap_check.hpp"
#include "hdf5_writing.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/input_limits.hpp"
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

// Copies the elements `rows` of a 1-D dataset of fixed-size elements.
void copyRows(const H5::DataSet& from, H5::DataSet& to, const std::vector<hsize_t>& rows) {
  if (rows.empty()) return;
  const H5::DataType type = from.getDataType();
  std::vector<unsigned char> buffer(rows.size() * type.getSize());
  H5::DataSpace from_space = from.getSpace(), to_space = to.getSpace();
  from_space.selectElements(H5S_SELECT_SET, rows.size(), rows.data());
  to_space.selectElements(H5S_SELECT_SET, rows.size(), rows.data());
  const hsize_t count = rows.size();
  const H5::DataSpace memory(1, &count);
  from.read(buffer.data(), type, memory, from_space);
  to.write(buffer.data(), type, memory, to_space);
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
    if (file.attrExists("created_by")) shard.created_by = detail::readStringAttribute(file, "created_by", path, "/:");
    const H5::Group table = file.openGroup(kSummaryPath);
    const H5::DataSet done = table.openDataSet("done");
    const H5::DataSet name = table.openDataSet("name");
    // One row per run of the study: sizes checked before anything is allocated (a shard can
    // declare 2^40 names in a few kB).
    for (const auto& [column, dataset] : {std::pair<const char*, const H5::DataSet*>{"name", &name},
                                          {"done", &done}}) {
      const H5::DataSpace space = dataset->getSpace();
      const hssize_t rows = space.getSimpleExtentNpoints();
      if (space.getSimpleExtentNdims() != 1 || rows < 0 ||
          static_cast<std::uint64_t>(rows) > kMaxStudyRuns) {
        throw InputError(path + ": " + kSummaryPath + "/" + column + ": expected at most " +
                         std::to_string(kMaxStudyRuns) + " runs (one row each), got " +
                         std::to_string(rows) + " values");
      }
    }
    // Then every string of the shard, once: merge copies its groups (H5Ocopy reads their strings)
    // and --resume its names; HDF5 would loop or crash on a damaged heap.
    detail::checkVariableDataUnder(file.openGroup("/"), path);
    const std::vector<std::string> names = detail::readVariableStrings(name, path, "dataset /batch/summary/name");
    std::vector<unsigned char> flags(names.size());
    if (done.getSpace().getSimpleExtentNpoints() != static_cast<hssize_t>(names.size())) {
      throw InputError(path + ": /batch/summary/done and name have different lengths");
    }
    done.read(flags.data(), H5::PredType::NATIVE_UCHAR);
    const H5::Group runs = file.openGroup("runs");
    shard.done.assign(names.size(), false);
    // A flag counts with its group only (batch_dataset.cpp writes the flag after the group).
    for (std::size_t i = 0; i < names.size(); ++i) {
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
            shard.study_fingerprint != first.study_fingerprint || shard.done.size() != first.done.size()) {
          throw InputError(shard.path + ": holds study '" + shard.study_name + "' (fingerprint " +
                           shard.study_fingerprint + "), not '" + first.study_name +
                           "' (fingerprint " + first.study_fingerprint + ") as " + first.path);
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
  const std::size_t total = first.done.size();
  std::vector<int> owner(total, -1);
  for (std::size_t s = 0; s < contents.size(); ++s) {
    for (std::size_t i = 0; i < total; ++i) {
      if (owner[i] < 0 && contents[s].done[i]) owner[i] = static_cast<int>(s);
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

  // Runs per shard, in index order.
  std::vector<std::vector<hsize_t>> rows(contents.size());
  for (std::size_t i = 0; i < total; ++i) rows[static_cast<std::size_t>(owner[i])].push_back(i);
  IndexReport report;
  report.runs = total;
  for (const auto& shard_rows : rows) report.shards_used += !shard_rows.empty();

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
      std::vector<std::string> names;
      {
        const H5::H5File source(first.path, H5F_ACC_RDONLY);
        copyAttributes(source.getId(), index.getId(), "shard");
        if (H5Ocopy(source.getId(), "batch", index.getId(), "batch", H5P_DEFAULT, H5P_DEFAULT) < 0) {
          throw H5::Exception("H5Ocopy", "cannot copy /batch from " + first.path);
        }
        names = detail::readVariableStrings(source.openDataSet(std::string(kSummaryPath) + "/name"),
                                            first.path, "dataset /batch/summary/name");
      }
      // The result columns: `done` and every column after it (batch_dataset.cpp's order).
      const auto done_column = std::find(first_columns.begin(), first_columns.end(), "done");
      const std::vector<std::string> results(done_column, first_columns.end());
      H5::Group runs = index.createGroup("runs");
      H5::Group table = index.openGroup(kSummaryPath);
      for (std::size_t s = 0; s < contents.size(); ++s) {
        if (rows[s].empty()) continue;
        const H5::H5File source(contents[s].path, H5F_ACC_RDONLY);
        if (s > 0) {
          const H5::Group source_table = source.openGroup(kSummaryPath);
          for (const std::string& column : results) {
            H5::DataSet target = table.openDataSet(column);
            copyRows(source_table.openDataSet(column), target, rows[s]);
          }
        }
        const std::string link_target =
            layout == IndexLayout::kLinks ? relativeTo(contents[s].path, output) : std::string();
        for (const hsize_t row : rows[s]) {
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
