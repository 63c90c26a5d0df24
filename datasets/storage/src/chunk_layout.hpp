#pragma once
// How a run's datasets are chunked and compressed: what the image's builder (hdf5_image.cpp)
// compresses and what the commit (hdf5_commit.cpp) declares to HDF5 must agree.
#include <algorithm>
#include <cstdint>

namespace wpg::datasets::detail {

// libdeflate's level 1, chosen on the chunks of a batch (CHANGELOG.md, "Batch"): 12 M
// instructions per 10 s walk and 45.1 % of the raw size, against 20 M and 43.7 % at its levels
// 2-4 and 34 M and 44.1 % for zlib's level 4 (HDF5's filter, before).
constexpr int kDeflateLevel = 1;
constexpr std::uint64_t kChunkBytes = 64 * 1024;  // ~64 KiB per chunk: small files, fast reads

// Rows per chunk of a dataset of `rows` rows of `row_bytes` bytes: the whole dataset up to
// kChunkBytes (an edge chunk is stored full size: the rows past the end are zero).
inline std::uint64_t chunkRows(std::uint64_t rows, std::uint64_t row_bytes) {
  return std::min(rows, std::max<std::uint64_t>(1, kChunkBytes / row_bytes));
}

}  // namespace wpg::datasets::detail
