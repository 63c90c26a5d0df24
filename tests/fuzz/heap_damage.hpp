#pragma once
// Global-heap-aware damage for the HDF5 fuzz targets: after the file of an image is written
// (hdf5_image.hpp, always valid), its global heap collections (where HDF5 keeps the
// variable-length strings) and the heap IDs that point into them are overwritten as the
// image's damage entries say. HDF5 1.10 reads these without bounds (a zeroed collection loops
// forever, 0xff bytes abort, a bad length allocates gigabytes); the readers must refuse them
// first (datasets/storage/src/string_heap_check.hpp). Random bytes anywhere would spend the
// fuzzer's time in HDF5's object-header and B-tree parsers, which are not ours to fix.
#include <cstdint>
#include <string>

namespace wpg_fuzz {

// One overwrite. `heap_id` false: inside collection number `which` (of those in the file, in
// file order), at `offset` (modulo its size); true: at heap ID number `which` (the places
// where a collection's address is stored, in file order), at `offset` (modulo 16: its
// length, address and index). Mode (modulo 4): 0 zeros, 1 0xff bytes, 2 `bytes`, 3 each byte
// plus the matching byte of `bytes` (a small change of a size). `length` bytes, 1 to 64.
struct HeapDamage {
  bool heap_id = false;
  std::uint16_t which = 0, offset = 0;
  std::uint8_t mode = 0, length = 1;
  std::string bytes;
};

// Applies `damage` to the file at `path` in place; false when the file cannot be read or
// written. A file without global heaps is left as it is.
bool applyHeapDamage(const std::string& path, const HeapDamage& damage);

}  // namespace wpg_fuzz
