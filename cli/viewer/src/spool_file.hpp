#pragma once
// A spool: pieces of text appended to an anonymous temporary file and read back by their
// index. `wpg view` of a study keeps each run page's data there while it reads the runs, and
// writes the pages from it once every run has been read (study_dashboard.cpp): the data of
// 10^4 run pages does not fit in memory, and reading every run twice was half the command's
// time. The file has no name (O_TMPFILE): nothing is left behind however the process ends,
// even on SIGKILL. Where a file system has no O_TMPFILE, a named temporary is made with
// mkstemp and unlinked at once.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace wpg::viewer {

class SpoolFile {
 public:
  // In the folder of `beside` (a file to be written), or the nearest folder above it that
  // exists: the pages go on the same file system, so the spool takes space where they will.
  // Throws std::runtime_error naming the folder when no file can be made there.
  explicit SpoolFile(const std::string& beside);
  ~SpoolFile();
  SpoolFile(const SpoolFile&) = delete;
  SpoolFile& operator=(const SpoolFile&) = delete;

  void append(const std::string& piece);    // throws std::runtime_error (a full disk)
  std::string read(std::size_t index) const;  // the index-th piece appended

 private:
  int fd_ = -1;
  std::string folder_;  // for messages
  std::uint64_t end_ = 0;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> pieces_;  // offset, length
};

}  // namespace wpg::viewer
