// HDF5 writing helpers (hdf5_writing.hpp).
#include "hdf5_writing.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <stdexcept>

#include <libdeflate.h>

#include "wpg/datasets/storage/output_file.hpp"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace wpg::datasets::detail {
namespace {

// libdeflate's level 1, chosen on the chunks of a batch (docs/performance.md): 12 M
// instructions per 10 s walk and 45.1 % of the raw size, against 20 M and 43.7 % at its levels
// 2-4 and 34 M and 44.1 % for zlib's level 4 (HDF5's filter, before).
constexpr int kDeflateLevel = 1;
constexpr hsize_t kChunkBytes = 64 * 1024;  // ~64 KiB per chunk: small files, fast reads

void describeDataset(H5::DataSet& dataset, const DatasetInfo& info) {
  writeStringAttribute(dataset, "units", info.units);
  if (info.frame) writeStringAttribute(dataset, "frame", info.frame);
  writeStringAttribute(dataset, "description", info.description);
  if (info.columns) writeStringAttribute(dataset, "columns", info.columns);
}

// Bytes per element of the memory types the writers use, known without asking HDF5 (no HDF5
// call may run while recording, off the lock). They are also the file types' sizes, and both
// are little-endian on the platforms we build for, so the memory bytes are the file's.
std::size_t elementSize(const H5::PredType& memory_type) {
  if (&memory_type == &H5::PredType::NATIVE_DOUBLE) return 8;
  if (&memory_type == &H5::PredType::NATIVE_INT) return 4;
  if (&memory_type == &H5::PredType::NATIVE_UINT8) return 1;
  throw std::logic_error("writeDataset: a memory type other than double, int or uint8");
}

thread_local ChunkRecording* t_recording = nullptr;
thread_local RecordingMode t_mode = RecordingMode::kRecord;

// One libdeflate compressor per thread (its tables are allocated once; a compressor must not
// be shared between threads).
libdeflate_compressor* threadCompressor() {
  struct Free {
    void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
  };
  thread_local std::unique_ptr<libdeflate_compressor, Free> compressor(
      libdeflate_alloc_compressor(kDeflateLevel));
  if (!compressor) throw std::runtime_error("libdeflate could not allocate a compressor");
  return compressor.get();
}

// HDF5's shuffle of 8-byte elements (doubles, nearly all of a run's bytes), 8 elements at a
// time: byte b of elements i..i+7 to out[b * elements + i ..], an 8 x 8 transpose of bytes in
// three rounds of interleaving (SSE2, in every x86-64 processor) instead of 64 loads and
// stores of one byte (the byte loop was 3 % of a batch). The same bytes in the same places.
// Returns how many of the `count` elements it shuffled (a multiple of 8; the caller does the
// rest).
std::size_t shuffleDoubles(const unsigned char* in, std::size_t count, std::size_t elements,
                           unsigned char* out) {
#if defined(__SSE2__)
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8) {
    const unsigned char* e = in + 8 * i;
    // x_k: elements 2k and 2k + 1
    const __m128i x0 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(e));
    const __m128i x1 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(e + 16));
    const __m128i x2 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(e + 32));
    const __m128i x3 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(e + 48));
    // y0: bytes 0-7 of elements 0 and 2 interleaved; y1: of 1 and 3; y2: 4 and 6; y3: 5 and 7
    const __m128i y0 = _mm_unpacklo_epi8(x0, x1), y1 = _mm_unpackhi_epi8(x0, x1);
    const __m128i y2 = _mm_unpacklo_epi8(x2, x3), y3 = _mm_unpackhi_epi8(x2, x3);
    // z0: bytes 0-3 of elements 0-3, byte by byte (4 bytes per byte index); z1: bytes 4-7;
    // z2, z3: the same for elements 4-7
    const __m128i z0 = _mm_unpacklo_epi8(y0, y1), z1 = _mm_unpackhi_epi8(y0, y1);
    const __m128i z2 = _mm_unpacklo_epi8(y2, y3), z3 = _mm_unpackhi_epi8(y2, y3);
    // w_k: bytes 2k and 2k + 1 of elements 0-7, 8 bytes each
    const __m128i w[4] = {_mm_unpacklo_epi32(z0, z2), _mm_unpackhi_epi32(z0, z2),
                          _mm_unpacklo_epi32(z1, z3), _mm_unpackhi_epi32(z1, z3)};
    for (std::size_t k = 0; k < 4; ++k) {
      _mm_storel_epi64(reinterpret_cast<__m128i*>(out + (2 * k) * elements + i), w[k]);
      _mm_storel_epi64(reinterpret_cast<__m128i*>(out + (2 * k + 1) * elements + i),
                       _mm_unpackhi_epi64(w[k], w[k]));
    }
  }
  return i;
#else
  (void)in;
  (void)count;
  (void)elements;
  (void)out;
  return 0;
#endif
}

// The stored form of one chunk of `size` bytes whose first `valid` bytes are `bytes` (the rest
// of an edge chunk is zero): HDF5's shuffle filter (the bytes of the same significance
// together), then its deflate filter's format, a zlib stream (libdeflate writes it faster than
// zlib; any inflate reads it: HDF5, h5py). The buffers are not zero-filled first (their every
// byte is written).
std::vector<unsigned char> compressChunk(const unsigned char* bytes, std::size_t valid,
                                         std::size_t size, std::size_t element_size) {
  thread_local std::unique_ptr<unsigned char[]> shuffled, compressed;
  thread_local std::size_t shuffled_capacity = 0, compressed_capacity = 0;
  libdeflate_compressor* compressor = threadCompressor();
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor, size);
  if (shuffled_capacity < size) {
    shuffled.reset(new unsigned char[size]);
    shuffled_capacity = size;
  }
  if (compressed_capacity < bound) {
    compressed.reset(new unsigned char[bound]);
    compressed_capacity = bound;
  }
  const std::size_t elements = size / element_size, valid_elements = valid / element_size;
  std::size_t done = 0;  // elements already shuffled
  if (element_size == 8) done = shuffleDoubles(bytes, valid_elements, elements, shuffled.get());
  for (std::size_t b = 0; b < element_size; ++b) {
    unsigned char* out = shuffled.get() + b * elements;
    const unsigned char* in = bytes + b;
    for (std::size_t i = done; i < valid_elements; ++i) out[i] = in[i * element_size];
    std::fill(out + valid_elements, out + elements, static_cast<unsigned char>(0));
  }
  const std::size_t compressed_size =
      libdeflate_zlib_compress(compressor, shuffled.get(), size, compressed.get(), bound);
  if (compressed_size == 0) throw std::runtime_error("libdeflate could not compress a chunk");
  return std::vector<unsigned char>(compressed.get(), compressed.get() + compressed_size);
}

// The chunks of a dataset of `rows` rows of `row_bytes` bytes, `chunk_rows` rows per chunk,
// compressed (an edge chunk is stored full size: the rows past the end are zero).
RecordedDataset compressDataset(const void* data, hsize_t rows, hsize_t columns,
                                hsize_t chunk_rows, std::size_t element_size) {
  RecordedDataset recorded{{}, rows, columns, chunk_rows, element_size, {}};
  const hsize_t row_bytes = std::max<hsize_t>(1, columns) * element_size;
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (hsize_t first = 0; first < rows; first += chunk_rows) {
    const hsize_t count = std::min(chunk_rows, rows - first);
    recorded.chunks.push_back(compressChunk(bytes + first * row_bytes, count * row_bytes,
                                            chunk_rows * row_bytes, element_size));
  }
  return recorded;
}

}  // namespace

RecordingScope::RecordingScope(ChunkRecording* recording, RecordingMode mode)
    : previous_recording_(t_recording), previous_mode_(t_mode) {
  t_recording = recording;
  t_mode = mode;
}

RecordingScope::~RecordingScope() {
  t_recording = previous_recording_;
  t_mode = previous_mode_;
}

ChunkRecording* activeRecording() {
  return t_mode == RecordingMode::kRecord ? t_recording : nullptr;
}

ChunkRecording* activeReplay() { return t_mode == RecordingMode::kReplay ? t_recording : nullptr; }

H5::H5File createHdf5File(const std::string& path, const H5::FileAccPropList& access) {
  H5::H5File file(path, H5F_ACC_TRUNC, H5::FileCreatPropList::DEFAULT, access);
  forgoWriteOutOnClose(path);
  return file;
}

H5::Group createGroup(H5::Group& parent, const std::string& name) {
  if (activeRecording()) return H5::Group();
  return parent.createGroup(name);
}

H5::Group openGroup(H5::Group& parent, const std::string& name) {
  if (activeRecording()) return H5::Group();
  return parent.openGroup(name);
}

namespace {

// The attributes' string type and scalar dataspace, made once (HDF5 copies them into each
// attribute, so the file is the same): making and closing them for each of a run's ~110
// attributes was ~7 % of the batch writer's serial work. Made on first use, by a caller holding
// hdf5Mutex() like every writer here, and never destroyed (HDF5 closes them at exit).
const H5::StrType& utf8StringType() {
  static const H5::StrType* const type = [] {
    auto* made = new H5::StrType(H5::PredType::C_S1, H5T_VARIABLE);
    made->setCset(H5T_CSET_UTF8);
    return made;
  }();
  return *type;
}

const H5::DataSpace& scalarSpace() {
  static const H5::DataSpace* const space = new H5::DataSpace(H5S_SCALAR);
  return *space;
}

// The creation properties of a chunked dataset (chunk shape, shuffle, deflate), made once per
// chunk shape for the same reason: HDF5 copies them into each dataset it creates, so the file
// is the same, and making, filling and closing them for each of a run's ~20 chunked datasets
// was ~8 % of the batch writer's serial work. The shapes of a study's runs are few (the chunk
// holds the whole dataset up to kChunkBytes); the cache starts again past kMaxShapes. Used
// under hdf5Mutex(), never destroyed (HDF5 closes them at exit), like the two above.
const H5::DSetCreatPropList& chunkedProperties(int rank, hsize_t chunk_rows, hsize_t columns) {
  constexpr std::size_t kMaxShapes = 256;
  using Shape = std::array<hsize_t, 3>;
  static auto* const made = new std::map<Shape, std::unique_ptr<H5::DSetCreatPropList>>();
  const Shape shape = {static_cast<hsize_t>(rank), chunk_rows, columns};
  const auto found = made->find(shape);
  if (found != made->end()) return *found->second;
  if (made->size() >= kMaxShapes) made->clear();
  auto properties = std::make_unique<H5::DSetCreatPropList>();
  const hsize_t chunk[2] = {chunk_rows, columns};
  properties->setChunk(rank, chunk);
  properties->setShuffle();
  properties->setDeflate(kDeflateLevel);
  return *made->emplace(shape, std::move(properties)).first->second;
}

}  // namespace

void writeStringAttribute(H5::H5Object& object, const std::string& name,
                          const std::string& value) {
  if (activeRecording()) return;
  const H5::StrType& type = utf8StringType();
  H5::Attribute attribute = object.createAttribute(name, type, scalarSpace());
  attribute.write(type, value);
}

void writeLinesAttribute(H5::H5Object& object, const std::string& name,
                         const std::vector<std::string>& lines) {
  if (lines.empty()) return;
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  writeStringAttribute(object, name, text);
}

void writeIntAttribute(H5::H5Object& object, const std::string& name, int value) {
  if (activeRecording()) return;
  H5::Attribute attribute =
      object.createAttribute(name, H5::PredType::STD_I32LE, scalarSpace());
  attribute.write(H5::PredType::NATIVE_INT, &value);
}

void writeDoubleAttribute(H5::H5Object& object, const std::string& name, double value) {
  if (activeRecording()) return;
  H5::Attribute attribute =
      object.createAttribute(name, H5::PredType::IEEE_F64LE, scalarSpace());
  attribute.write(H5::PredType::NATIVE_DOUBLE, &value);
}

void writeStringListAttribute(H5::H5Object& object, const std::string& name,
                              const std::vector<std::string>& values) {
  if (activeRecording()) return;
  const H5::StrType& type = utf8StringType();
  const hsize_t count = values.size();
  H5::Attribute attribute = object.createAttribute(name, type, H5::DataSpace(1, &count));
  std::vector<const char*> pointers;
  for (const std::string& value : values) pointers.push_back(value.c_str());
  if (count > 0) attribute.write(type, pointers.data());
}

H5::DataSet writeDataset(H5::Group& group, const std::string& name, const void* data,
                         hsize_t rows, hsize_t columns, const H5::PredType& memory_type,
                         const H5::PredType& file_type, const DatasetInfo& info) {
  const int rank = columns == 0 ? 1 : 2;
  const hsize_t dimensions[2] = {rows, columns};
  const std::size_t element_size = elementSize(memory_type);
  const hsize_t row_bytes = std::max<hsize_t>(1, columns) * element_size;
  const hsize_t chunk_rows = std::min(rows, std::max<hsize_t>(1, kChunkBytes / row_bytes));
  if (ChunkRecording* recording = activeRecording()) {
    recording->datasets.push_back(compressDataset(data, rows, columns, chunk_rows, element_size));
    recording->datasets.back().name = name;
    return H5::DataSet();
  }
  // Written directly too, the chunks are compressed here and written as they are: the same
  // bytes as a batch's, and libdeflate rather than HDF5's zlib.
  RecordedDataset direct;
  const RecordedDataset* recorded = nullptr;
  if (ChunkRecording* replay = activeReplay();
      replay && (replay->replayed < replay->datasets.size() || !replay->partial)) {
    if (replay->replayed >= replay->datasets.size()) {
      throw std::logic_error("writeDataset: replaying more datasets than were recorded");
    }
    recorded = &replay->datasets[replay->replayed++];
    if (recorded->name != name || recorded->rows != rows || recorded->columns != columns ||
        recorded->element_size != element_size) {
      throw std::logic_error("writeDataset: the replayed dataset " + name +
                             " is not the one recorded");
    }
  }
  if (!recorded && rows > 0) {
    direct = compressDataset(data, rows, columns, chunk_rows, element_size);
    recorded = &direct;
  }
  const H5::DataSpace space(rank, dimensions);
  H5::DataSet dataset = group.createDataSet(
      name, file_type, space,
      rows > 0 ? chunkedProperties(rank, chunk_rows, columns) : H5::DSetCreatPropList::DEFAULT);
  if (rows > 0) {
    for (std::size_t c = 0; c < recorded->chunks.size(); ++c) {
      const hsize_t offset[2] = {c * chunk_rows, 0};
      const std::vector<unsigned char>& chunk = recorded->chunks[c];
      if (H5Dwrite_chunk(dataset.getId(), H5P_DEFAULT, 0, offset, chunk.size(), chunk.data()) < 0) {
        throw std::runtime_error("cannot write a chunk of dataset " + name);
      }
    }
  }
  describeDataset(dataset, info);
  return dataset;
}

void writeDoubles(H5::Group& group, const std::string& name, const std::vector<double>& values,
                  hsize_t columns, const DatasetInfo& info) {
  const hsize_t rows = columns == 0 ? values.size() : values.size() / columns;
  writeDataset(group, name, values.data(), rows, columns, H5::PredType::NATIVE_DOUBLE,
               H5::PredType::IEEE_F64LE, info);
}

void writeInts(H5::Group& group, const std::string& name, const std::vector<int>& values,
               const DatasetInfo& info) {
  writeDataset(group, name, values.data(), values.size(), 0, H5::PredType::NATIVE_INT,
               H5::PredType::STD_I32LE, info);
}

H5::DataSet writeCodes(H5::Group& group, const std::string& name,
                       const std::vector<std::uint8_t>& values, const DatasetInfo& info) {
  return writeDataset(group, name, values.data(), values.size(), 0, H5::PredType::NATIVE_UINT8,
                      H5::PredType::STD_U8LE, info);
}

std::vector<double> rowMajor(const Eigen::MatrixXd& matrix) {
  std::vector<double> values(static_cast<std::size_t>(matrix.size()));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      values.data(), matrix.rows(), matrix.cols()) = matrix;
  return values;
}

}  // namespace wpg::datasets::detail
