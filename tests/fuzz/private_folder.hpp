#pragma once
// A fuzz target's private folder for the files it writes for every input: in /dev/shm when it
// is writable (memory, not the disk), else the temporary directory.
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace wpg_fuzz {

// Creates <parent>/<prefix>XXXXXX and returns its path; "" when it cannot.
inline std::string makePrivateFolder(const std::string& prefix) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path parent = fs::is_directory("/dev/shm", ec) && access("/dev/shm", W_OK) == 0
                              ? fs::path("/dev/shm")
                              : fs::temp_directory_path();
  std::string pattern = (parent / (prefix + "XXXXXX")).string();
  return mkdtemp(pattern.data()) != nullptr ? pattern : std::string();
}

}  // namespace wpg_fuzz
