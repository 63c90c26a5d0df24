// An anonymous spool file (spool_file.hpp).
#include "spool_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace fs = std::filesystem;

namespace wpg::viewer {
namespace {

std::string nearestFolder(const std::string& beside) {
  std::error_code error;
  fs::path folder = fs::absolute(fs::path(beside), error).parent_path();
  while (!folder.empty() && !fs::is_directory(folder, error) && folder != folder.root_path())
    folder = folder.parent_path();
  return folder.empty() ? std::string(".") : folder.string();
}

}  // namespace

SpoolFile::SpoolFile(const std::string& beside) : folder_(nearestFolder(beside)) {
  fd_ = ::open(folder_.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd_ < 0 && (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL)) {
    std::string name = folder_ + "/.wpg-spool-XXXXXX";
    fd_ = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd_ >= 0) ::unlink(name.c_str());
  }
  if (fd_ < 0) {
    throw std::runtime_error("cannot make a temporary file in '" + folder_ + "' (" +
                             std::strerror(errno) + ")");
  }
}

SpoolFile::~SpoolFile() {
  if (fd_ >= 0) ::close(fd_);
}

void SpoolFile::append(const std::string& piece) {
  std::size_t done = 0;
  while (done < piece.size()) {
    const ssize_t written = ::pwrite(fd_, piece.data() + done, piece.size() - done,
                                     static_cast<off_t>(end_ + done));
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      throw std::runtime_error("cannot write a temporary file in '" + folder_ + "' (" +
                               std::strerror(errno) + ")");
    }
    done += static_cast<std::size_t>(written);
  }
  pieces_.emplace_back(end_, piece.size());
  end_ += piece.size();
}

std::string SpoolFile::read(std::size_t index) const {
  const auto [offset, length] = pieces_.at(index);
  std::string piece(length, '\0');
  std::size_t done = 0;
  while (done < length) {
    const ssize_t got = ::pread(fd_, piece.data() + done, length - done,
                                static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      throw std::runtime_error("cannot read back a temporary file in '" + folder_ + "' (" +
                               std::strerror(errno) + ")");
    }
    done += static_cast<std::size_t>(got);
  }
  return piece;
}

}  // namespace wpg::viewer
