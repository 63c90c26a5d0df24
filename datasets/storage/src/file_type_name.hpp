#pragma once
// What a path is when it is not a regular file, in the words of the storage's messages ("got a
// FIFO (pipe)"): output checks (output_file.cpp) and external links (external_link_guard.cpp).
#include <sys/stat.h>

namespace wpg::datasets::detail {

inline const char* fileTypeName(const struct stat& s) {
  if (S_ISDIR(s.st_mode)) return "a folder";
  if (S_ISCHR(s.st_mode)) return "a character device";
  if (S_ISBLK(s.st_mode)) return "a block device";
  if (S_ISFIFO(s.st_mode)) return "a FIFO (pipe)";
  if (S_ISSOCK(s.st_mode)) return "a socket";
  return "not a regular file";
}

}  // namespace wpg::datasets::detail
