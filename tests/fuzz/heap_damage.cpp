// Global-heap-aware damage (heap_damage.hpp).
#include "heap_damage.hpp"

#include "hdf5_image.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace wpg_fuzz {

bool applyHeapDamage(const std::string& path, const HeapDamage& damage) {
  std::vector<char> file;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    file.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // The collections: their signature and version 1 (wpg's and h5py's 8-byte sizes).
  std::vector<std::size_t> collections;
  static const char kSignature[] = {'G', 'C', 'O', 'L', 1};
  for (auto at = file.begin();
       (at = std::search(at, file.end(), kSignature, kSignature + 5)) != file.end(); ++at) {
    collections.push_back(static_cast<std::size_t>(at - file.begin()));
  }
  if (collections.empty()) return true;
  std::size_t start = 0;
  if (!damage.heap_id) {
    const std::size_t at = collections[damage.which % collections.size()];
    std::uint64_t size = 0;
    if (at + 16 <= file.size()) std::memcpy(&size, file.data() + at + 8, 8);  // little-endian
    size = std::min<std::uint64_t>(std::max<std::uint64_t>(size, 1), file.size() - at);
    start = at + damage.offset % size;
  } else {
    // Heap IDs: 4 bytes of length, then the collection's address (8 bytes, little-endian).
    std::vector<std::size_t> ids;
    for (std::size_t p = 4; p + 12 <= file.size(); ++p) {
      std::uint64_t address = 0;
      std::memcpy(&address, file.data() + p, 8);
      if (std::binary_search(collections.begin(), collections.end(), address)) ids.push_back(p - 4);
    }
    if (ids.empty()) return true;
    start = ids[damage.which % ids.size()] + damage.offset % 16;
  }
  const std::size_t length = std::min<std::size_t>(std::max(1, std::min<int>(damage.length, 64)),
                                                   file.size() - std::min(start, file.size()));
  for (std::size_t i = 0; i < length; ++i) {
    char& byte = file[start + i];
    const char given = damage.bytes.empty() ? 0 : damage.bytes[i % damage.bytes.size()];
    switch (damage.mode % 4) {
      case 0: byte = 0; break;
      case 1: byte = static_cast<char>(0xff); break;
      case 2: byte = given; break;
      default: byte = static_cast<char>(byte + given); break;
    }
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(file.data(), static_cast<std::streamsize>(file.size()));
  return static_cast<bool>(out);
}

void applyImageDamage(const FileImage& image, const std::string& path) {
  for (const Entry& entry : image.entries) {
    if (entry.kind == Entry::Kind::kHeapDamage) applyHeapDamage(path, entry.damage);
  }
}

}  // namespace wpg_fuzz
