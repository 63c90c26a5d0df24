// Finding the heap IDs of variable-length data in a file's bytes (string_heap_check.hpp): a
// contiguous dataset's data from H5Dget_offset; an attribute's data in its message of its
// object's header, parsed here (the HDF5 file format specification, "Data Object Headers"
// IV.A: version 1 and 2 headers, their continuation chunks, attribute messages 1 to 3). HDF5
// itself has no call that hands the stored IDs over without reading the heaps behind them.
#include "string_heap_check.hpp"

#include <cstring>
#include <mutex>
#include <deque>
#include <functional>
#include <utility>

#include "external_link_guard.hpp"
#include "global_heap_check.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/input_file.hpp"
#include "wpg/datasets/storage/read_limits.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/storage/stored_strings_check.hpp"

namespace wpg::datasets::detail {
namespace {

constexpr unsigned kAttributeMessage = 0x000C;
constexpr unsigned kContinuationMessage = 0x0010;
// Chunks of one header followed, at most: wpg writes one or two; a cycle of continuation
// messages in a damaged header would otherwise be followed forever.
constexpr int kMaxHeaderChunks = 256;

[[noreturn]] void refuse(const std::string& file, const std::string& what,
                         const std::string& why) {
  throw InputError(file + ": " + what + ": damaged variable-length data (" + why + ")");
}

// Where an object's header is, and in which open file (H5Oget_info of an attribute
// describes the object it is attached to).
struct ObjectPlace {
  unsigned long file_number = 0;
  std::uint64_t header = 0;
};

ObjectPlace objectPlace(hid_t object) {
#if H5_VERSION_GE(1, 12, 0)
  H5O_info2_t info;
  haddr_t address = HADDR_UNDEF;
  if (H5Oget_info3(object, &info, H5O_INFO_BASIC) < 0 ||
      H5VLnative_token_to_addr(object, info.token, &address) < 0) {
    throw H5::Exception("H5Oget_info3", "cannot find the object's header");
  }
  return {info.fileno, address};
#else
  H5O_info_t info;
  if (H5Oget_info2(object, &info, H5O_INFO_BASIC) < 0) {
    throw H5::Exception("H5Oget_info2", "cannot find the object's header");
  }
  return {info.fileno, info.addr};
#endif
}

// True when elements of `type` are of variable length; refuses a variable-length type inside
// another (a compound's member, an array's base), which wpg never writes.
bool isVariable(hid_t type, const std::string& file, const std::string& what) {
  const H5T_class_t type_class = H5Tget_class(type);
  if (type_class == H5T_VLEN || (type_class == H5T_STRING && H5Tis_variable_str(type) > 0)) {
    return true;
  }
  if (H5Tdetect_class(type, H5T_VLEN) > 0) {
    throw InputError(file + ": " + what +
                     ": variable-length data inside another type (not read: wpg writes none)");
  }
  return false;
}

// Calls `visit(type, data, size)` for each message of the header at `address`; returns why
// the header cannot be walked ("" when it can).
using MessageVisitor = std::function<void(unsigned, const unsigned char*, std::uint64_t)>;
std::string forEachMessage(const FileBytes& file, std::uint64_t address,
                           const MessageVisitor& visit) {
  const unsigned A = file.addressBytes(), L = file.lengthBytes();
  std::vector<unsigned char> bytes;
  const std::uint64_t start = file.base() + address;
  if (!file.read(start, 16, bytes)) return "its header is past the file's end";
  bool v2 = false;
  std::deque<std::pair<std::uint64_t, std::uint64_t>> chunks;  // messages: offset, length
  if (std::memcmp(bytes.data(), "OHDR", 4) == 0 && bytes[4] == 2) {
    v2 = true;
    const unsigned flags = bytes[5];
    std::uint64_t p = 6 + ((flags & 0x20) ? 16 : 0) + ((flags & 0x10) ? 4 : 0);
    const unsigned width = 1u << (flags & 3);
    if (!file.read(start, p + width, bytes)) return "its header is past the file's end";
    chunks.emplace_back(start + p + width, decodeLittleEndian(bytes.data() + p, width));
  } else if (bytes[0] == 1) {
    chunks.emplace_back(start + 16, decodeLittleEndian(bytes.data() + 8, 4));
  } else {
    return "its header is of an unknown version";
  }
  const std::uint64_t message_header = v2 ? 4 : 8;
  for (int followed = 0; !chunks.empty(); ++followed) {
    if (followed == kMaxHeaderChunks) return "its header has too many continuation chunks";
    const auto [offset, length] = chunks.front();
    chunks.pop_front();
    if (length > kMaxReadBytes || !file.read(offset, length, bytes)) {
      return "a chunk of its header is past the file's end";
    }
    std::uint64_t p = (v2 && followed > 0) ? 4 : 0;  // "OCHK"
    const std::uint64_t end = (v2 && followed > 0) ? (length >= 4 ? length - 4 : 0) : length;
    while (p + message_header <= end) {
      const unsigned char* m = bytes.data() + p;
      const unsigned type = v2 ? m[0] : static_cast<unsigned>(decodeLittleEndian(m, 2));
      const std::uint64_t size = decodeLittleEndian(m + (v2 ? 1 : 2), 2);
      const std::uint64_t skip = message_header + ((v2 && (m[3] & 0x04)) ? 2 : 0);
      if (p + skip + size > end) return "a message of its header runs past its chunk";
      const unsigned char* data = bytes.data() + p + skip;
      if (type == kContinuationMessage) {
        if (size < A + L) return "a continuation message is too short";
        chunks.emplace_back(file.base() + decodeLittleEndian(data, A),
                            decodeLittleEndian(data + A, L));
      } else {
        visit(type, data, size);
      }
      p += skip + size;
    }
  }
  return "";
}

// What an attribute message holds, as far as its variable-length data goes.
struct AttributeMessage {
  std::string name;
  bool variable = false;           // a string or a sequence of variable length
  std::uint64_t element_size = 0;  // bytes of one element of the sequence (1: a string)
  std::uint64_t count = 0;         // elements (heap IDs)
  const unsigned char* ids = nullptr;
  std::string damage;
};

AttributeMessage parseAttribute(const unsigned char* d, std::uint64_t size, unsigned L,
                                unsigned A) {
  AttributeMessage a;
  if (size < 9) return a.damage = "an attribute message is too short", a;
  const unsigned version = d[0];
  if (version < 1 || version > 3) return a.damage = "an attribute message of an unknown version", a;
  const auto padded = [&](std::uint64_t n) { return version == 1 ? (n + 7) & ~std::uint64_t{7} : n; };
  const std::uint64_t name_size = decodeLittleEndian(d + 2, 2);
  const std::uint64_t type_size = decodeLittleEndian(d + 4, 2);
  const std::uint64_t space_size = decodeLittleEndian(d + 6, 2);
  const std::uint64_t name_at = version == 3 ? 9 : 8;
  const std::uint64_t type_at = name_at + padded(name_size);
  const std::uint64_t space_at = type_at + padded(type_size);
  const std::uint64_t data_at = space_at + padded(space_size);
  if (data_at > size || type_size < 8 || space_size < 4) {
    return a.damage = "an attribute message's parts run past it", a;
  }
  a.name.assign(reinterpret_cast<const char*>(d + name_at),
                strnlen(reinterpret_cast<const char*>(d + name_at), name_size));
  const unsigned char* type = d + type_at;
  if ((type[0] & 0x0f) != 9) return a;  // not of variable length: nothing in the heaps
  a.variable = true;
  if (version > 1 && (d[1] & 0x01)) return a.damage = "attribute " + a.name + " has a shared type", a;
  if ((type[1] & 0x0f) == 1) {
    a.element_size = 1;
  } else if (type_size >= 16) {
    a.element_size = decodeLittleEndian(type + 12, 4);  // the base type's size
  }
  const unsigned char* space = d + space_at;
  const unsigned rank = space[1];
  const bool null_space = space[0] >= 2 && space[3] == 2;
  const std::uint64_t dims_at = space[0] == 1 ? 8 : 4;
  if (rank > 32 || dims_at + std::uint64_t{rank} * L > space_size) {
    return a.damage = "attribute " + a.name + " has a damaged dataspace", a;
  }
  a.count = null_space ? 0 : 1;
  for (unsigned i = 0; i < rank && a.count != 0; ++i) {
    const std::uint64_t dim = decodeLittleEndian(space + dims_at + std::uint64_t{i} * L, L);
    if (dim != 0 && a.count > kMaxReadElements / dim) {
      return a.damage = "attribute " + a.name + " declares too many elements", a;
    }
    a.count *= dim;
  }
  if (a.count > (size - data_at) / (8 + A)) {
    return a.damage = "attribute " + a.name + "'s data runs past its message", a;
  }
  a.ids = d + data_at;
  return a;
}

// The variable-length attributes of the object whose header is at `address`: the one named
// `name`, or all of them when `name` is null.
void checkHeader(const FileBytes& bytes, HeapChecker& heaps, std::uint64_t address,
                 const char* name, const std::string& file, const std::string& what) {
  bool found = false;
  std::string damage;
  const std::string walk = forEachMessage(
      bytes, address, [&](unsigned type, const unsigned char* data, std::uint64_t size) {
        if (type != kAttributeMessage || !damage.empty()) return;
        const AttributeMessage a = parseAttribute(data, size, bytes.lengthBytes(), bytes.addressBytes());
        if (name && a.name != name) return;
        found = true;
        if (!a.damage.empty()) damage = a.damage;
        else if (a.variable) damage = heaps.check(a.ids, a.count, a.element_size);
        if (!damage.empty() && !name) damage = "attribute " + a.name + ": " + damage;
      });
  if (!walk.empty()) refuse(file, what, walk);
  if (!damage.empty()) refuse(file, what, damage);
  if (name && !found) {
    refuse(file, what, "not found in its object's header, where HDF5 writes attributes");
  }
}

// An identifier HDF5 handed over (H5Dget_type, H5Dget_space, ...), released on every path.
// The C++ API's wrappers built from an identifier take a reference of their own, so wrapping
// these would leave one behind per object checked.
class OwnedId {
 public:
  OwnedId(hid_t id, const char* call) : id_(id) {
    if (id_ < 0) throw H5::Exception(call, "failed");
  }
  ~OwnedId() { H5Idec_ref(id_); }
  OwnedId(const OwnedId&) = delete;
  OwnedId& operator=(const OwnedId&) = delete;
  hid_t get() const { return id_; }

 private:
  hid_t id_;
};

// The heap IDs of a dataset whose `type` is variable-length (isVariable), checked.
void checkDatasetData(const FileBytes& bytes, HeapChecker& heaps, hid_t dataset, hid_t type,
                      const std::string& file, const std::string& what) {
  std::uint64_t element_size = 1;
  if (H5Tget_class(type) == H5T_VLEN) {
    const hid_t base = H5Tget_super(type);
    element_size = base >= 0 ? H5Tget_size(base) : 0;
    if (base >= 0) H5Tclose(base);
  }
  const hssize_t points =
      H5Sget_simple_extent_npoints(OwnedId(H5Dget_space(dataset), "H5Dget_space").get());
  if (points < 0 || static_cast<std::uint64_t>(points) > kMaxReadElements) {
    refuse(file, what, "it declares too many elements");
  }
  const std::uint64_t count = static_cast<std::uint64_t>(points);
  if (count == 0) return;
  const haddr_t offset = H5Dget_offset(dataset);
  if (offset == HADDR_UNDEF) {
    const OwnedId creation(H5Dget_create_plist(dataset), "H5Dget_create_plist");
    // Never written: HDF5 hands fill values (null strings) over, no heap read.
    if (H5Pget_layout(creation.get()) == H5D_CONTIGUOUS && H5Dget_storage_size(dataset) == 0) {
      return;
    }
    throw InputError(file + ": " + what +
                     ": expected variable-length data stored contiguously, as wpg writes it");
  }
  std::vector<unsigned char> ids;
  const std::uint64_t id_size = 8 + bytes.addressBytes();
  if (count > kMaxReadBytes / id_size || !bytes.read(offset, count * id_size, ids)) {
    refuse(file, what, "its data is past the file's end");
  }
  const std::string damage = heaps.check(ids.data(), count, element_size);
  if (!damage.empty()) refuse(file, what, damage);
}

// The objects below one group of one file (and through its external links, other files').
struct SubtreeCheck {
  const FileBytes& bytes;
  HeapChecker heaps;
  const std::string& file;
  std::string prefix;  // the group's path, for messages
  int depth;
  std::string error;   // an InputError's message, raised once HDF5's iteration has returned
};

void checkSubtree(hid_t group, const std::string& file, const std::string& prefix, int depth);

herr_t visitObject(hid_t group, const char* name, const H5O_info_t* info, void* data) {
  auto& check = *static_cast<SubtreeCheck*>(data);
  const std::string path =
      std::strcmp(name, ".") == 0 ? check.prefix : check.prefix + "/" + name;
  try {
    checkHeader(check.bytes, check.heaps, info->addr, nullptr, check.file,
                "object " + (path.empty() ? std::string("/") : path));
    if (info->type == H5O_TYPE_DATASET) {
      const hid_t dataset = H5Dopen2(group, name, H5P_DEFAULT);
      if (dataset < 0) throw H5::Exception("H5Dopen2", "cannot open dataset " + path);
      try {
        const OwnedId type(H5Dget_type(dataset), "H5Dget_type");
        if (isVariable(type.get(), check.file, "dataset " + path)) {
          checkDatasetData(check.bytes, check.heaps, dataset, type.get(), check.file,
                           "dataset " + path);
        }
      } catch (...) {
        H5Dclose(dataset);
        throw;
      }
      H5Dclose(dataset);
    }
  } catch (const InputError& error) {
    check.error = error.what();
    return -1;
  } catch (const H5::Exception& error) {
    check.error = check.file + ": cannot read " + path + " (" + error.getDetailMsg() + ")";
    return -1;
  }
  return 0;
}

herr_t visitLink(hid_t group, const char* name, const H5L_info_t* link, void* data) {
  auto& check = *static_cast<SubtreeCheck*>(data);
  if (link->type != H5L_TYPE_EXTERNAL) return 0;
  const std::string path = check.prefix + "/" + name;
  if (check.depth >= kMaxExternalLinkDepth) {
    check.error = check.file + ": " + path + ": external links more than " +
                  std::to_string(kMaxExternalLinkDepth) + " deep";
    return -1;
  }
  const hid_t target = H5Oopen(group, name, H5P_DEFAULT);  // the guard checks the target
  if (target < 0) {
    std::string why = takeExternalLinkRefusal();
    check.error = why.empty() ? check.file + ": cannot follow the external link " + path : why;
    return -1;
  }
  try {
    checkSubtree(target, check.file, path, check.depth + 1);
  } catch (const InputError& error) {
    check.error = error.what();
  } catch (const H5::Exception& error) {
    check.error = check.file + ": cannot read " + path + " (" + error.getDetailMsg() + ")";
  }
  H5Oclose(target);
  return check.error.empty() ? 0 : -1;
}

void checkSubtree(hid_t group, const std::string& file, const std::string& prefix, int depth) {
  const FileBytes bytes(group);
  SubtreeCheck check{bytes, HeapChecker(bytes), file, prefix, depth, ""};
  const herr_t visited =
      H5Ovisit2(group, H5_INDEX_NAME, H5_ITER_NATIVE, visitObject, &check, H5O_INFO_BASIC);
  if (!check.error.empty()) throw InputError(check.error);
  if (visited < 0) throw H5::Exception("H5Ovisit2", "cannot walk " + prefix);
  if (H5Iget_type(group) != H5I_GROUP) return;
  const herr_t linked =
      H5Lvisit(group, H5_INDEX_NAME, H5_ITER_NATIVE, visitLink, &check);
  if (!check.error.empty()) throw InputError(check.error);
  if (linked < 0) throw H5::Exception("H5Lvisit", "cannot walk the links of " + prefix);
}

}  // namespace

struct VariableDataChecker::OpenFile {
  explicit OpenFile(hid_t object) : bytes(object), heaps(bytes) {}
  FileBytes bytes;
  HeapChecker heaps;
};

VariableDataChecker::VariableDataChecker() = default;
VariableDataChecker::~VariableDataChecker() = default;

VariableDataChecker::OpenFile& VariableDataChecker::openFile(hid_t object,
                                                             unsigned long file_number) {
  std::unique_ptr<OpenFile>& open = files_[file_number];
  if (!open) open = std::make_unique<OpenFile>(object);
  return *open;
}

void VariableDataChecker::check(const H5::DataSet& dataset, const std::string& file,
                                const std::string& what) {
  const H5::DataType type = dataset.getDataType();
  if (!isVariable(type.getId(), file, what)) return;
  OpenFile& open = openFile(dataset.getId(), objectPlace(dataset.getId()).file_number);
  checkDatasetData(open.bytes, open.heaps, dataset.getId(), type.getId(), file, what);
}

void VariableDataChecker::check(const H5::Attribute& attribute, const std::string& file,
                                const std::string& what) {
  const H5::DataType type = attribute.getDataType();
  if (!isVariable(type.getId(), file, what)) return;
  const ObjectPlace place = objectPlace(attribute.getId());
  OpenFile& open = openFile(attribute.getId(), place.file_number);
  const std::string name = attribute.getName();
  checkHeader(open.bytes, open.heaps, place.header, name.c_str(), file, what);
}

void checkVariableData(const H5::DataSet& dataset, const std::string& file,
                       const std::string& what) {
  VariableDataChecker().check(dataset, file, what);
}

void checkVariableData(const H5::Attribute& attribute, const std::string& file,
                       const std::string& what) {
  VariableDataChecker().check(attribute, file, what);
}

void checkVariableDataUnder(const H5::Group& group, const std::string& file) {
  const ssize_t length = H5Iget_name(group.getId(), nullptr, 0);
  std::string name(length > 0 ? static_cast<std::size_t>(length) : 0, '\0');
  if (length > 0) H5Iget_name(group.getId(), name.data(), name.size() + 1);
  checkSubtree(group.getId(), file, name == "/" ? "" : name, 0);
}

}  // namespace wpg::datasets::detail

namespace wpg::datasets {

void checkStoredStrings(const std::string& path, const std::string& group) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  checkInputFile(path);
  try {
    if (!H5::H5File::isHdf5(path)) return;
    const H5::H5File file(path, H5F_ACC_RDONLY);
    if (group != "/" && !file.nameExists(group)) return;
    detail::checkVariableDataUnder(file.openGroup(group), path);
  } catch (const H5::Exception&) {
    if (std::string why = detail::takeExternalLinkRefusal(); !why.empty()) throw InputError(why);
  }
}

}  // namespace wpg::datasets
