// External links checked before they are followed (external_link_guard.hpp).
//
// Why a replacement of the link class and not a check in each reader: HDF5 follows a link
// wherever a name is resolved (H5Oget_info_by_name of a listing, openGroup, a generic walk of
// `wpg diff`), and its own traversal opens the target with open(2) before looking at it, which
// blocks forever on a FIFO. Registering a class with the id of external links replaces HDF5's
// traversal for every call of the process (H5Lregister: a class of the same id is replaced).
#include "external_link_guard.hpp"

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <H5Cpp.h>
#include <sys/stat.h>

#include "file_type_name.hpp"
#include "wpg/datasets/input/input_error.hpp"

namespace wpg::datasets::detail {
namespace fs = std::filesystem;

namespace {

thread_local std::string refusal;
thread_local int depth = 0;

std::string nameOf(hid_t id, bool file) {
  const ssize_t size = file ? H5Fget_name(id, nullptr, 0) : H5Iget_name(id, nullptr, 0);
  if (size <= 0) return "?";
  std::vector<char> text(static_cast<std::size_t>(size) + 1);
  if (file) H5Fget_name(id, text.data(), text.size());
  else H5Iget_name(id, text.data(), text.size());
  return std::string(text.data());
}

hid_t traverse(const char* link_name, hid_t group, const void* data, size_t size, hid_t,
               hid_t) {
  const char* target = nullptr;
  const char* object = nullptr;
  unsigned flags = 0;
  const std::string parent = nameOf(group, true);
  std::string where = nameOf(group, false);
  where = (where == "/" ? "" : where) + "/" + link_name;
  const auto refuse = [&](const std::string& why) -> hid_t {
    refusal = escapeControlCharacters(parent) + ": " + escapeControlCharacters(where) +
              ": external link" + (target ? " to '" + escapeControlCharacters(target) + "'" : "") +
              ": " + why;
    return -1;
  };
  if (H5Lunpack_elink_val(data, size, &flags, &target, &object) < 0 || !target || !object)
    return refuse("its value cannot be read");
  if (depth >= kMaxExternalLinkDepth)
    return refuse("more than " + std::to_string(kMaxExternalLinkDepth) +
                  " external links followed one inside another (a cycle?)");
  // Where HDF5 looks (without HDF5_EXT_PREFIX): an absolute name as it is; a relative one
  // beside the file holding the link, then from the working folder.
  std::vector<fs::path> candidates;
  const fs::path name(target);
  if (name.is_absolute()) {
    candidates.push_back(name);
  } else {
    candidates.push_back(fs::path(parent).parent_path() / name);
    candidates.push_back(name);
  }
  for (const fs::path& candidate : candidates) {
    struct stat s {};
    if (::stat(candidate.c_str(), &s) != 0) continue;
    if (!S_ISREG(s.st_mode)) {
      return refuse(std::string("expected a regular file, got ") + detail::fileTypeName(s));
    }
    const hid_t parent_file = H5Iget_file_id(group);
    unsigned intent = H5F_ACC_RDONLY;
    if (parent_file >= 0) {
      H5Fget_intent(parent_file, &intent);
      H5Fclose(parent_file);
    }
    const hid_t file =
        H5Fopen(candidate.c_str(), (intent & H5F_ACC_RDWR) ? H5F_ACC_RDWR : H5F_ACC_RDONLY,
                H5P_DEFAULT);
    if (file < 0) return refuse("cannot open it as an HDF5 file");
    ++depth;
    const hid_t opened = H5Oopen(file, object, H5P_DEFAULT);
    --depth;
    H5Fclose(file);  // stays open while the object is (HDF5's weak close degree)
    if (opened < 0 && refusal.empty())
      return refuse("no object '" + escapeControlCharacters(object) + "' in it");
    return opened;
  }
  return refuse("no such file");
}

ssize_t query(const char*, const void* data, size_t size, void* buffer, size_t buffer_size) {
  if (buffer && buffer_size > 0) std::memcpy(buffer, data, size < buffer_size ? size : buffer_size);
  return static_cast<ssize_t>(size);
}

}  // namespace

void installExternalLinkGuard() {
  static const H5L_class_t guarded = {H5L_LINK_CLASS_T_VERS,
                                      H5L_TYPE_EXTERNAL,
                                      "external link, target checked first (wpg)",
                                      nullptr,
                                      nullptr,
                                      nullptr,
                                      traverse,
                                      nullptr,
                                      query};
  H5Lregister(&guarded);
}

std::string takeExternalLinkRefusal() {
  std::string message;
  message.swap(refusal);
  return message;
}

}  // namespace wpg::datasets::detail
