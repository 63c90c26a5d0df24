#pragma once
// Writing plain HDF5 that h5py reads without code of ours (conventions: datasets/SCHEMA.md):
// scalar and string-list attributes, time-major numeric datasets that carry `units`,
// `frame`, `description` and `columns` attributes, chunked and compressed.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <H5Cpp.h>

namespace wpg::datasets::detail {

// --- compression off the HDF5 lock ----------------------------------------------------------
// Debian's HDF5 is not thread-safe, so everything it does runs under hdf5Mutex(), one thread at
// a time; compressing the chunks is most of a run's writing time. writeDataset never lets HDF5
// compress: it shuffles and deflates each chunk as HDF5's shuffle and deflate filters would
// (a zlib stream, written by libdeflate) and writes the chunks as they are (H5Dwrite_chunk);
// h5py and HDF5 read them with the same filters. A batch worker runs the writer of a run
// twice: first recording (on its own thread, without the lock, no HDF5 call: writeDataset
// compresses the chunks and keeps them; attributes and groups are skipped), then replaying
// under the lock (writeDataset creates each dataset and writes the recorded chunks). The file
// is the same as one written directly.

struct RecordedDataset {
  std::string name;
  hsize_t rows = 0, columns = 0, chunk_rows = 0;
  std::size_t element_size = 0;
  std::vector<std::vector<unsigned char>> chunks;  // shuffled + deflated, in row order
};

class ChunkRecording {
 public:
  std::vector<RecordedDataset> datasets;  // in the order of the writer's writeDataset calls
  std::size_t replayed = 0;               // datasets taken back by the replay so far
  std::shared_ptr<const void> cache;      // what the writer computed while recording (checks)
  // The first datasets only (prepareWalkDatasets): past them the replaying writer compresses
  // the rest itself.
  bool partial = false;
};

enum class RecordingMode { kRecord, kReplay };

// While alive, writeDataset and the helpers below on this thread record into / replay from
// `recording` (null: write directly, the default).
class RecordingScope {
 public:
  RecordingScope(ChunkRecording* recording, RecordingMode mode);
  ~RecordingScope();
  RecordingScope(const RecordingScope&) = delete;
  RecordingScope& operator=(const RecordingScope&) = delete;

 private:
  ChunkRecording* previous_recording_;
  RecordingMode previous_mode_;
};

// The recording of this thread when it is recording (nullptr otherwise).
ChunkRecording* activeRecording();
// The recording of this thread when it is replaying (nullptr otherwise).
ChunkRecording* activeReplay();

// A new HDF5 file at `path` (H5F_ACC_TRUNC, replacing what is there), without ext4's forced
// write-out at its close (forgoWriteOutOnClose, output_file.hpp): every file wpg writes is
// created here. The caller holds hdf5Mutex().
H5::H5File createHdf5File(const std::string& path,
                          const H5::FileAccPropList& access = H5::FileAccPropList::DEFAULT);

// parent.createGroup(name); a placeholder while recording.
H5::Group createGroup(H5::Group& parent, const std::string& name);
// An existing group (an empty handle while recording, like createGroup).
H5::Group openGroup(H5::Group& parent, const std::string& name);

// --- attributes ------------------------------------------------------------------------------

void writeStringAttribute(H5::H5Object& object, const std::string& name,
                          const std::string& value);
// `lines` as one string attribute, each line ending with a line feed; no attribute when `lines`
// is empty (a run without the loader's warnings reads as before they were recorded).
void writeLinesAttribute(H5::H5Object& object, const std::string& name,
                         const std::vector<std::string>& lines);  // variable-length UTF-8
void writeIntAttribute(H5::H5Object& object, const std::string& name, int value);
void writeDoubleAttribute(H5::H5Object& object, const std::string& name, double value);
// A 1-D attribute of variable-length UTF-8 strings (h5py: an array of str).
void writeStringListAttribute(H5::H5Object& object, const std::string& name,
                              const std::vector<std::string>& values);

// --- datasets --------------------------------------------------------------------------------

struct DatasetInfo {
  const char* units;        // "s", "m", "m, m, m, rad" (one per column when they differ), "1"
  const char* frame;        // "world", or nullptr where no frame applies
  const char* description;  // one sentence
  const char* columns;      // column names of a 2-D dataset, nullptr for 1-D
};

// rows x columns, row-major (time-major); columns == 0 makes a 1-D dataset of `rows`.
// Chunked and compressed when it has rows; a 0-row dataset is contiguous (a chunk cannot be
// larger than a fixed-size dataset) and nothing is written into it.
H5::DataSet writeDataset(H5::Group& group, const std::string& name, const void* data,
                         hsize_t rows, hsize_t columns, const H5::PredType& memory_type,
                         const H5::PredType& file_type, const DatasetInfo& info);
// float64; rows = values.size() / columns (1-D when columns == 0).
void writeDoubles(H5::Group& group, const std::string& name, const std::vector<double>& values,
                  hsize_t columns, const DatasetInfo& info);
void writeInts(H5::Group& group, const std::string& name, const std::vector<int>& values,
               const DatasetInfo& info);  // int32, 1-D
H5::DataSet writeCodes(H5::Group& group, const std::string& name,
                       const std::vector<std::uint8_t>& values,
                       const DatasetInfo& info);  // uint8, 1-D; the caller adds `codes`

// --- rows to the flat, time-major layout ------------------------------------------------------

// The rows are stored back to back (a fixed-size Eigen vector is its Size doubles): one copy,
// not one insertion per row (the batch writer runs this on its serial path too).
template <int Size>
std::vector<double> flatten(const std::vector<Eigen::Matrix<double, Size, 1>>& rows) {
  static_assert(sizeof(Eigen::Matrix<double, Size, 1>) == Size * sizeof(double),
                "rows without padding");
  if (rows.empty()) return {};
  const double* first = rows.front().data();
  return std::vector<double>(first, first + rows.size() * Size);
}

// get(row) for every row.
template <typename Row, typename Get>
std::vector<double> column(const std::vector<Row>& rows, Get get) {
  std::vector<double> values;
  values.reserve(rows.size());
  for (const Row& row : rows) values.push_back(get(row));
  return values;
}

// An Eigen matrix as a time-major (row-major) vector; a 1-column matrix stays 2-D.
std::vector<double> rowMajor(const Eigen::MatrixXd& matrix);

}  // namespace wpg::datasets::detail
