#pragma once
// The global heaps of an HDF5 file, checked before HDF5 reads them. Variable-length strings
// (run names, summary columns, stored scenarios) are not stored where their dataset or
// attribute is: each element is a heap ID (its length, the address of a global heap
// collection, an object's index in it), and the text is an object of that collection. HDF5
// 1.10 reads a collection without bounds: an object of size 0 makes its parser loop forever
// (a zeroed collection), an object's size past the collection's end makes it read and free
// outside its buffers (0xff bytes: abort or segfault), and a string's length is allocated
// before its object is read (2^32 - 1: 4 GiB). HeapChecker reads the IDs and the collections
// itself, with pread(2), every size bounded by the file, and refuses what HDF5 would not
// survive; string_heap_check.hpp finds the IDs of a dataset or an attribute.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace wpg::datasets::detail {

// The bytes of one open HDF5 file, read with pread(2) from HDF5's own descriptor (or from the
// file reopened by name when HDF5 uses another driver). `hid` is any object of the file.
class FileBytes {
 public:
  explicit FileBytes(std::int64_t hid);
  ~FileBytes();
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;

  // `length` bytes at `offset` (from the start of the file) into `out`; false when they are
  // not all inside the file.
  bool read(std::uint64_t offset, std::uint64_t length, std::vector<unsigned char>& out) const;
  std::uint64_t size() const { return size_; }
  // HDF5's addresses count from the base address (the user block's end, 0 without one).
  std::uint64_t base() const { return base_; }
  unsigned addressBytes() const { return address_bytes_; }  // 8 unless the file says otherwise
  unsigned lengthBytes() const { return length_bytes_; }

 private:
  int fd_ = -1;
  bool own_fd_ = false;
  std::uint64_t size_ = 0, base_ = 0;
  unsigned address_bytes_ = 8, length_bytes_ = 8;
};

// A little-endian unsigned number of `bytes` bytes (1 to 8) at `p`.
std::uint64_t decodeLittleEndian(const unsigned char* p, unsigned bytes);

// Checks heap IDs against the collections they point to. Each collection is read and walked
// once per checker (a summary column of 10^4 names points into a few dozen of them).
class HeapChecker {
 public:
  explicit HeapChecker(const FileBytes& file) : file_(file) {}

  // The heap IDs of `count` elements stored at `ids` (4 + address + 4 bytes each), whose
  // elements are `element_size` bytes (1 for a string). Returns "" when HDF5 can read them
  // all, else why not (for the caller's message).
  std::string check(const unsigned char* ids, std::uint64_t count, std::uint64_t element_size);

 private:
  struct Collection {
    std::string damage;                  // why HDF5 cannot read it; "" when it can
    std::vector<std::uint64_t> sizes;    // object sizes by index (kAbsent: no such object)
  };
  const Collection& collection(std::uint64_t address);

  const FileBytes& file_;
  std::unordered_map<std::uint64_t, Collection> collections_;
  std::vector<unsigned char> buffer_;
};

}  // namespace wpg::datasets::detail
