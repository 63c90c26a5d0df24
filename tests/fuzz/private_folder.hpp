#pragma once
// Where a fuzz target writes the files it rewrites for every input: /dev/shm when it is
// writable (memory, not the disk), else the temporary directory; a private folder there, or
// one file removed when the process exits.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace wpg_fuzz {

inline std::filesystem::path scratchParent() {
  namespace fs = std::filesystem;
  std::error_code ec;
  return fs::is_directory("/dev/shm", ec) && access("/dev/shm", W_OK) == 0
             ? fs::path("/dev/shm")
             : fs::temp_directory_path();
}

// <parent>/<stem><pid>.h5, removed when the process exits (one per process: a second call
// names another file and removes only that one).
inline const std::string& scratchFile(const std::string& stem) {
  static std::string path;
  path = (scratchParent() / (stem + std::to_string(getpid()) + ".h5")).string();
  std::atexit([] {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  });
  return path;
}

// Creates <parent>/<prefix>XXXXXX and returns its path; "" when it cannot.
inline std::string makePrivateFolder(const std::string& prefix) {
  const std::filesystem::path parent = scratchParent();
  std::string pattern = (parent / (prefix + "XXXXXX")).string();
  return mkdtemp(pattern.data()) != nullptr ? pattern : std::string();
}

}  // namespace wpg_fuzz
