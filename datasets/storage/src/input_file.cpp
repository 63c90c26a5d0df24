// The check of every input file (input_file.hpp).
#include "wpg/datasets/storage/input_file.hpp"

#include <cerrno>
#include <cstring>

#include <sys/stat.h>
#include <unistd.h>

#include "file_type_name.hpp"
#include "wpg/datasets/input/input_error.hpp"

namespace wpg::datasets {

void checkInputFile(const std::string& path) {
  const auto refuse = [&](const std::string& why) {
    throw InputError(escapeControlCharacters(path) + ": cannot read: " + why);
  };
  struct stat s {};
  if (::stat(path.c_str(), &s) != 0) {
    refuse(errno == ENOENT || errno == ENOTDIR ? std::string("no such file") : std::strerror(errno));
  }
  if (S_ISDIR(s.st_mode)) refuse("it is a directory");
  if (!S_ISREG(s.st_mode)) refuse(std::string("expected a regular file, got ") + detail::fileTypeName(s));
  if (::access(path.c_str(), R_OK) != 0) refuse("permission denied");
}

}  // namespace wpg::datasets
