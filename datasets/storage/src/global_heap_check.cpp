// Global heap collections checked before HDF5 reads them (global_heap_check.hpp). The layout
// is the HDF5 file format specification's, "Global Heap" (III.E); the walk below mirrors
// H5HG__cache_heap_deserialize of HDF5 1.10, so that every collection it would loop on or read
// out of bounds is refused first.
#include "global_heap_check.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <limits>

#include <H5Cpp.h>

#include "wpg/datasets/storage/read_limits.hpp"

namespace wpg::datasets::detail {
namespace {

constexpr std::uint64_t kAbsent = std::numeric_limits<std::uint64_t>::max();
// H5HG_MINSIZE: HDF5 never makes a smaller collection, and reads that much before the header.
constexpr std::uint64_t kMinCollectionSize = 4096;

std::string at(std::uint64_t address) { return "the global heap at byte " + std::to_string(address); }

}  // namespace

std::uint64_t decodeLittleEndian(const unsigned char* p, unsigned bytes) {
  std::uint64_t value = 0;
  for (unsigned i = bytes; i-- > 0;) value = (value << 8) | p[i];
  return value;
}

FileBytes::FileBytes(std::int64_t hid) {
  const hid_t file = H5Iget_file_id(hid);
  if (file < 0) throw H5::Exception("H5Iget_file_id", "not an object of an open file");
  const hid_t creation = H5Fget_create_plist(file);
  hsize_t user_block = 0;
  std::size_t address_bytes = 8, length_bytes = 8;
  if (creation >= 0) {
    H5Pget_userblock(creation, &user_block);
    H5Pget_sizes(creation, &address_bytes, &length_bytes);
    H5Pclose(creation);
  }
  base_ = user_block;
  address_bytes_ = static_cast<unsigned>(address_bytes);
  length_bytes_ = static_cast<unsigned>(length_bytes);
  // HDF5's descriptor when it reads through the POSIX driver (every reader here), so that the
  // bytes are those of the file HDF5 has open (a rename meanwhile changes nothing).
  const hid_t access = H5Fget_access_plist(file);
  void* handle = nullptr;
  if (access >= 0 && H5Pget_driver(access) == H5FD_SEC2 &&
      H5Fget_vfd_handle(file, access, &handle) >= 0 && handle) {
    fd_ = *static_cast<int*>(handle);
  }
  if (access >= 0) H5Pclose(access);
  if (fd_ < 0) {
    const ssize_t length = H5Fget_name(file, nullptr, 0);
    std::string name(length > 0 ? static_cast<std::size_t>(length) : 0, '\0');
    if (length > 0) H5Fget_name(file, name.data(), name.size() + 1);
    fd_ = ::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    own_fd_ = fd_ >= 0;
  }
  H5Fclose(file);
  struct stat status {};
  if (fd_ < 0 || ::fstat(fd_, &status) != 0 || !S_ISREG(status.st_mode)) {
    if (own_fd_) ::close(fd_);
    throw H5::Exception("FileBytes", "cannot read the file's bytes");
  }
  size_ = static_cast<std::uint64_t>(status.st_size);
  if (address_bytes_ < 2 || address_bytes_ > 8 || length_bytes_ < 2 || length_bytes_ > 8) {
    address_bytes_ = length_bytes_ = 0;  // read() then refuses everything
  }
}

FileBytes::~FileBytes() {
  if (own_fd_) ::close(fd_);
}

bool FileBytes::read(std::uint64_t offset, std::uint64_t length,
                     std::vector<unsigned char>& out) const {
  if (address_bytes_ == 0 || offset > size_ || length > size_ - offset) return false;
  out.resize(static_cast<std::size_t>(length));
  std::uint64_t done = 0;
  while (done < length) {
    const ssize_t got = ::pread(fd_, out.data() + done, static_cast<std::size_t>(length - done),
                                static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    done += static_cast<std::uint64_t>(got);
  }
  return true;
}

const HeapChecker::Collection& HeapChecker::collection(std::uint64_t address) {
  if (const auto found = collections_.find(address); found != collections_.end()) {
    return found->second;
  }
  Collection& c = collections_[address];
  const unsigned L = file_.lengthBytes();
  const std::uint64_t header = 8 + L;          // "GCOL", version, 3 reserved, size
  const std::uint64_t object_header = 8 + L;   // index, references, 4 reserved, size
  const std::uint64_t offset = file_.base() + address;
  if (address > file_.size() || !file_.read(offset, header, buffer_)) {
    c.damage = at(address) + " is past the file's end";
    return c;
  }
  if (buffer_[0] != 'G' || buffer_[1] != 'C' || buffer_[2] != 'O' || buffer_[3] != 'L') {
    c.damage = at(address) + " has no GCOL signature";
    return c;
  }
  if (buffer_[4] != 1) {
    c.damage = at(address) + " is of version " + std::to_string(buffer_[4]) + ", expected 1";
    return c;
  }
  const std::uint64_t size = decodeLittleEndian(buffer_.data() + 8, L);
  if (size < kMinCollectionSize || size > kMaxReadBytes || !file_.read(offset, size, buffer_)) {
    c.damage = at(address) + " declares " + std::to_string(size) +
               " bytes: expected 4096 or more, inside the file";
    return c;
  }
  // Objects follow the header up to the collection's end; the free space is object 0, whose
  // size counts its header. HDF5 steps by each object's size: one that would not move it on,
  // or would move it past the end, is damage.
  std::uint64_t p = header;
  while (p < size) {
    if (p + object_header > size) break;  // a tail too short for an object: free space
    const std::uint64_t index = decodeLittleEndian(buffer_.data() + p, 2);
    const std::uint64_t object = decodeLittleEndian(buffer_.data() + p + 8, L);
    std::uint64_t step = object;
    if (index > 0) {
      if (object > size) step = size;  // past the end whatever the padding
      else step = object_header + ((object + 7) & ~std::uint64_t{7});
    }
    if (step == 0 || step > size - p) {
      c.damage = at(address) + ": object " + std::to_string(index) + " at byte " +
                 std::to_string(address + p) + " declares " + std::to_string(object) +
                 " bytes, " + (step == 0 ? "none" : "past the collection's end");
      c.sizes.clear();
      return c;
    }
    if (index > 0) {
      if (c.sizes.size() <= index) c.sizes.resize(index + 1, kAbsent);
      c.sizes[index] = object;
    }
    p += step;
  }
  return c;
}

std::string HeapChecker::check(const unsigned char* ids, std::uint64_t count,
                               std::uint64_t element_size) {
  const unsigned A = file_.addressBytes();
  const std::uint64_t id_size = 8 + A;
  for (std::uint64_t i = 0; i < count; ++i) {
    const unsigned char* id = ids + i * id_size;
    const std::uint64_t length = decodeLittleEndian(id, 4);
    const std::uint64_t address = decodeLittleEndian(id + 4, A);
    const std::uint64_t index = decodeLittleEndian(id + 4 + A, 4);
    if (address == 0) continue;  // HDF5's null string: nothing is read
    const Collection& c = collection(address);
    if (!c.damage.empty()) return "element " + std::to_string(i) + ": " + c.damage;
    // HDF5 allocates the length x element size, then copies the whole object into it.
    if (index == 0 || index >= c.sizes.size() || c.sizes[index] == kAbsent) {
      return "element " + std::to_string(i) + ": " + at(address) + " has no object " +
             std::to_string(index);
    }
    if (element_size == 0 || length > kMaxReadBytes / element_size ||
        c.sizes[index] != length * element_size) {
      return "element " + std::to_string(i) + ": declares " + std::to_string(length) +
             " elements, its object in " + at(address) + " holds " +
             std::to_string(c.sizes[index]) + " bytes";
    }
  }
  return "";
}

}  // namespace wpg::datasets::detail
