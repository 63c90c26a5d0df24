// Building the image of an HDF5 group (hdf5_image.hpp): its datasets' chunks shuffled and
// deflated as HDF5's filters would, without any HDF5 call.
#include "hdf5_image.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include <libdeflate.h>

#include "chunk_layout.hpp"
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace wpg::datasets::detail {
namespace {

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

std::size_t elementSize(ElementType type) {
  switch (type) {
    case ElementType::kFloat64: return 8;
    case ElementType::kInt32: return 4;
    case ElementType::kUint8: return 1;
    case ElementType::kString: break;
  }
  throw std::logic_error("writeDataset: unknown element type");
}

void describe(DatasetImage& dataset, const DatasetInfo& info) {
  writeStringAttribute(dataset, "units", info.units);
  if (info.frame) writeStringAttribute(dataset, "frame", info.frame);
  writeStringAttribute(dataset, "description", info.description);
  if (info.columns) writeStringAttribute(dataset, "columns", info.columns);
}

}  // namespace

DatasetImage& GroupImage::addDataset(DatasetImage dataset) {
  return std::get<DatasetImage>(entries_.emplace_back(std::move(dataset)));
}

GroupImage& GroupImage::createGroup(const std::string& name) {
  auto& child = std::get<std::unique_ptr<Child>>(
      entries_.emplace_back(std::make_unique<Child>(Child{name, false, {}})));
  return child->group;
}

GroupImage& GroupImage::openGroup(const std::string& name) {
  auto& child = std::get<std::unique_ptr<Child>>(
      entries_.emplace_back(std::make_unique<Child>(Child{name, true, {}})));
  return child->group;
}

void GroupImage::addPart(std::shared_ptr<const GroupImage> part) {
  if (!part) throw std::logic_error("GroupImage::addPart: no part");
  entries_.emplace_back(std::move(part));
}

DatasetImage& writeDataset(GroupImage& group, const std::string& name, const void* data,
                           std::uint64_t rows, std::uint64_t columns, ElementType type,
                           const DatasetInfo& info) {
  DatasetImage dataset;
  dataset.name = name;
  dataset.rows = rows;
  dataset.columns = columns;
  dataset.type = type;
  const std::size_t element_size = elementSize(type);
  const std::uint64_t row_bytes = std::max<std::uint64_t>(1, columns) * element_size;
  dataset.chunk_rows = chunkRows(rows, row_bytes);
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::uint64_t first = 0; first < rows; first += dataset.chunk_rows) {
    const std::uint64_t count = std::min(dataset.chunk_rows, rows - first);
    dataset.chunks.push_back(compressChunk(bytes + first * row_bytes, count * row_bytes,
                                           dataset.chunk_rows * row_bytes, element_size));
  }
  describe(dataset, info);
  return group.addDataset(std::move(dataset));
}

DatasetImage& writeDoubles(GroupImage& group, const std::string& name,
                           const std::vector<double>& values, std::uint64_t columns,
                           const DatasetInfo& info) {
  const std::uint64_t rows = columns == 0 ? values.size() : values.size() / columns;
  return writeDataset(group, name, values.data(), rows, columns, ElementType::kFloat64, info);
}

DatasetImage& writeInts(GroupImage& group, const std::string& name,
                        const std::vector<int>& values, const DatasetInfo& info) {
  return writeDataset(group, name, values.data(), values.size(), 0, ElementType::kInt32, info);
}

DatasetImage& writeCodes(GroupImage& group, const std::string& name,
                         const std::vector<std::uint8_t>& values, const DatasetInfo& info) {
  return writeDataset(group, name, values.data(), values.size(), 0, ElementType::kUint8, info);
}

DatasetImage& writeStrings(GroupImage& group, const std::string& name,
                           const std::vector<std::string>& values, const char* description) {
  DatasetImage dataset;
  dataset.name = name;
  dataset.rows = values.size();
  dataset.type = ElementType::kString;
  dataset.strings = values;
  writeStringAttribute(dataset, "units", "1");
  writeStringAttribute(dataset, "description", description);
  return group.addDataset(std::move(dataset));
}

void writeStringAttribute(ObjectImage& object, const std::string& name, const std::string& value) {
  object.add({name, value});
}

void writeLinesAttribute(ObjectImage& object, const std::string& name,
                         const std::vector<std::string>& lines) {
  if (lines.empty()) return;
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  object.add({name, std::move(text)});
}

void writeIntAttribute(ObjectImage& object, const std::string& name, int value) {
  object.add({name, value});
}

void writeDoubleAttribute(ObjectImage& object, const std::string& name, double value) {
  object.add({name, value});
}

void writeStringListAttribute(ObjectImage& object, const std::string& name,
                              const std::vector<std::string>& values) {
  object.add({name, values});
}

}  // namespace wpg::datasets::detail
