// Output paths checked before use, and temporary files that are created exclusively and never
// outlive an interrupted write (output_file.hpp).
#include "wpg/datasets/storage/output_file.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <stdexcept>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "file_type_name.hpp"
#include "wpg/datasets/input/input_error.hpp"

namespace wpg::datasets {
namespace fs = std::filesystem;

namespace {

// --- temporary files removed on SIGINT / SIGTERM --------------------------------------------
// A fixed table (no allocation, no lock in the handler): a slot is claimed with a CAS, its
// path copied, then published; the handler unlinks every published path (unlink is
// async-signal-safe), restores the previous action and raises the signal again.
constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
std::atomic<int> slot_state[kSlots];  // 0 free, 1 being written, 2 published
char slot_path[kSlots][kPathBytes];
struct sigaction previous_int, previous_term;
std::once_flag handlers_installed;

void removeTemporaries(int signal_number) {
  for (int i = 0; i < kSlots; ++i)
    if (slot_state[i].load() == 2) ::unlink(slot_path[i]);
  ::sigaction(signal_number, signal_number == SIGINT ? &previous_int : &previous_term, nullptr);
  ::raise(signal_number);
}

// Not for a signal the process was started ignoring: a background job of a non-interactive
// shell (`wpg batch ... &` in a script) starts with SIGINT ignored, and goes on after one; its
// temporary output removed, it would write on into an unlinked file and fail to rename it.
void installHandlers() {
  struct sigaction action {};
  action.sa_handler = removeTemporaries;
  sigemptyset(&action.sa_mask);
  for (const int signal_number : {SIGINT, SIGTERM}) {
    struct sigaction& previous = signal_number == SIGINT ? previous_int : previous_term;
    ::sigaction(signal_number, nullptr, &previous);
    if (previous.sa_handler != SIG_IGN) ::sigaction(signal_number, &action, nullptr);
  }
}

int publish(const std::string& path) {
  std::call_once(handlers_installed, installHandlers);
  if (path.size() >= kPathBytes) return -1;  // not removed on a signal; still removed normally
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (slot_state[i].compare_exchange_strong(expected, 1)) {
      std::memcpy(slot_path[i], path.c_str(), path.size() + 1);
      slot_state[i].store(2);
      return i;
    }
  }
  return -1;  // more than kSlots temporaries at once: the rest are not covered by the handler
}

void release(int slot) {
  if (slot >= 0) slot_state[slot].store(0);
}

mode_t creationMode() {
  static const mode_t mode = [] {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return static_cast<mode_t>(0666 & ~mask);
  }();
  return mode;
}

// --- kinds ----------------------------------------------------------------------------------

bool hasSignatureAt(std::ifstream& in, std::streamoff offset, const char (&signature)[9]) {
  char bytes[8] = {};
  in.clear();
  in.seekg(offset);
  return in.read(bytes, 8) && std::memcmp(bytes, signature, 8) == 0;
}

bool holdsKind(const std::string& path, OutputKind kind, std::uintmax_t size) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  switch (kind) {
    case OutputKind::kHdf5: {
      static const char signature[9] = "\x89HDF\r\n\x1a\n";
      // The superblock may follow a user block of 512 * 2^k bytes.
      for (std::uintmax_t offset = 0; offset + 8 <= size; offset = offset ? 2 * offset : 512)
        if (hasSignatureAt(in, static_cast<std::streamoff>(offset), signature)) return true;
      return false;
    }
    case OutputKind::kPng: {
      static const char signature[9] = "\x89PNG\r\n\x1a\n";
      return hasSignatureAt(in, 0, signature);
    }
    case OutputKind::kJson: {
      char c = 0;
      while (in.get(c))
        if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return c == '{' || c == '[';
      return false;
    }
    case OutputKind::kHtml: {
      char c = 0;
      while (in.get(c))
        if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return c == '<';
      return false;
    }
    case OutputKind::kBenchmarkLog: {
      std::string first;
      std::getline(in, first);
      const std::size_t space = first.find(' ');
      return space != std::string::npos && first.compare(space, 9, " version ") == 0;
    }
    case OutputKind::kSqlite: {
      static const char signature[17] = "SQLite format 3";  // and its NUL: 16 bytes
      char bytes[16] = {};
      return in.read(bytes, 16) && std::memcmp(bytes, signature, 16) == 0;
    }
    case OutputKind::kText: {
      char c = 0;
      for (int i = 0; i < (1 << 16) && in.get(c); ++i)
        if (c == '\0') return false;
      return true;
    }
  }
  return false;
}

[[noreturn]] void refuse(const std::string& path, OutputKind kind, const std::string& got) {
  throw InputError("'" + escapeControlCharacters(path) + "': expected a regular file to write " +
                   outputKindName(kind) + " to, got " + got + " (nothing written)");
}

}  // namespace

const char* outputKindName(OutputKind kind) {
  switch (kind) {
    case OutputKind::kHdf5: return "an HDF5 file";
    case OutputKind::kPng: return "a PNG image";
    case OutputKind::kJson: return "a JSON file";
    case OutputKind::kHtml: return "an HTML page";
    case OutputKind::kBenchmarkLog: return "a benchmark log";
    case OutputKind::kSqlite: return "an SQLite database";
    case OutputKind::kText: return "a text file";
  }
  return "a file";
}

namespace {
constexpr std::size_t kMaxFileNameBytes = 255;   // NAME_MAX of Linux file systems
constexpr std::size_t kTemporaryNameExtra = 8;   // "." before, ".XXXXXX" after
}  // namespace

void checkOutputPath(const std::string& path, OutputKind kind,
                     const std::vector<std::string>& inputs) {
  if (path.empty()) refuse(path, kind, "an empty path");
  if (path.back() == '/') refuse(path, kind, "a folder name (it ends with '/')");
  // The temporary file ".<name>.XXXXXX" (TemporaryOutput) must fit in a file name too: checked
  // here, before the work, not when the output is written.
  const std::size_t name_length = fs::path(path).filename().string().size();
  if (name_length + kTemporaryNameExtra > kMaxFileNameBytes) {
    refuse(path, kind, "a file name of " + std::to_string(name_length) + " bytes (at most " +
                           std::to_string(kMaxFileNameBytes - kTemporaryNameExtra) +
                           ": the temporary file beside it adds " +
                           std::to_string(kTemporaryNameExtra) + ")");
  }
  struct stat target {};
  if (::lstat(path.c_str(), &target) != 0) {
    if (errno == ENOENT) return;  // a new file (its folder is created when written)
    refuse(path, kind, std::string("a path that cannot be examined: ") + std::strerror(errno));
  }
  // Never followed: the link's target may be an input, another user's file, a device.
  if (S_ISLNK(target.st_mode)) refuse(path, kind, "a symbolic link (not followed)");
  if (!S_ISREG(target.st_mode)) refuse(path, kind, detail::fileTypeName(target));
  for (const std::string& input : inputs) {
    struct stat other {};
    if (::stat(input.c_str(), &other) == 0 && other.st_dev == target.st_dev &&
        other.st_ino == target.st_ino)
      refuse(path, kind, "an input of the command ('" + input + "')");
  }
  const auto size = static_cast<std::uintmax_t>(target.st_size);
  if (size > 0 && !holdsKind(path, kind, size))
    refuse(path, kind, "an existing file of another kind (only " +
                           std::string(outputKindName(kind)) + " is replaced)");
}

void checkWritableParent(const std::string& output) {
  std::error_code ec;
  const fs::path path(output);
  for (fs::path folder = path.parent_path(); !folder.empty(); folder = folder.parent_path()) {
    if (fs::exists(folder, ec)) {
      if (!fs::is_directory(folder, ec) || ::access(folder.c_str(), W_OK | X_OK) != 0) {
        throw InputError("cannot write output '" + output + "': '" + folder.string() +
                         "' is not a writable directory");
      }
      break;
    }
    if (folder == folder.parent_path()) break;
  }
}

void checkOutputPaths(const std::vector<PlannedOutput>& outputs,
                      const std::vector<std::string>& inputs) {
  // A set, not a pair-wise comparison: the run pages of a study's dashboard are one output
  // per run (10^4 runs were 5 * 10^7 comparisons).
  std::set<fs::path> seen;
  for (const PlannedOutput& output : outputs) {
    checkOutputPath(output.path, output.kind, inputs);
    checkWritableParent(output.path);
    if (!seen.insert(fs::path(output.path).lexically_normal()).second)
      refuse(output.path, output.kind, "a path the command also writes another output to");
  }
}

void checkOutputFolder(const std::string& folder) {
  struct stat target {};
  if (::lstat(folder.c_str(), &target) != 0) {
    if (errno == ENOENT) return;
    throw InputError("'" + escapeControlCharacters(folder) + "': expected a folder to write into, " +
                     "got a path that cannot be examined: " + std::strerror(errno) + " (nothing written)");
  }
  if (S_ISDIR(target.st_mode)) return;
  throw InputError("'" + escapeControlCharacters(folder) + "': expected a folder to write into, got " +
                   (S_ISLNK(target.st_mode)   ? std::string("a symbolic link (not followed)")
                    : S_ISREG(target.st_mode) ? std::string("a file")
                                              : std::string(detail::fileTypeName(target))) +
                   " (nothing written)");
}

void writeFileAtomically(const std::string& path, const std::string& content) {
  TemporaryOutput temporary(path);
  const int fd = ::open(temporary.path().c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      ::close(fd);
      throw std::runtime_error("cannot write " + path + ": " + std::strerror(error));
    }
    written += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0)
    throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  temporary.commit();
}

void forgoWriteOutOnClose(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd >= 0) ::close(fd);  // another description: HDF5's flock and our OFD claim stay
}

OutputClaim::OutputClaim(const std::string& path) : path_(path) {
  const auto in_use = [&] {
    return InputError("'" + escapeControlCharacters(path) +
                      "': in use by another wpg or HDF5 program (nothing written)");
  };
  // Never O_TRUNC here: the file is examined before anything of it may change.
  fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
  if (fd_ < 0 && errno == ENOENT) {
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, creationMode());
    created_ = fd_ >= 0;
  }
  if (fd_ < 0)
    throw std::runtime_error("cannot open " + path + ": " + std::strerror(errno));
  struct flock claim {};
  claim.l_type = F_WRLCK;
  claim.l_whence = SEEK_SET;  // l_start = l_len = 0: the whole file
  if (::fcntl(fd_, F_OFD_SETLK, &claim) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw in_use();
  }
  // HDF5's own lock (a flock, held while a program has the file open): probed, then released
  // so that this process's HDF5 can take it.
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    if (created_) ::unlink(path.c_str());
    ::close(fd_);
    fd_ = -1;
    throw in_use();
  }
  ::flock(fd_, LOCK_UN);
}

OutputClaim::~OutputClaim() {
  if (fd_ < 0) return;
  struct stat s {};
  if (created_ && ::fstat(fd_, &s) == 0 && s.st_size == 0) ::unlink(path_.c_str());
  ::close(fd_);  // releases the claim
}

FolderClaim::FolderClaim(const std::string& folder, const std::string& owner) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  fd_ = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC | O_NOFOLLOW);
  if (fd_ < 0) throw std::runtime_error("cannot open " + folder + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw InputError("'" + escapeControlCharacters(owner) + "': in use by another wpg ('" +
                     escapeControlCharacters(folder) +
                     "' is held by a running job; nothing written)");
  }
}

FolderClaim::~FolderClaim() {
  if (fd_ >= 0) ::close(fd_);  // releases the flock
}

TemporaryOutput::TemporaryOutput(const std::string& target) : target_(target) {
  const fs::path file(target);
  if (target.empty() || !file.has_filename())
    throw std::runtime_error("'" + target + "' is not a file path");
  const fs::path folder = file.parent_path();
  if (!folder.empty()) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec)
      throw std::runtime_error(target + ": cannot create the folder '" + folder.string() + "': " +
                               ec.message());
  }
  // ".<name>.XXXXXX" beside the target: same file system (atomic rename), hidden, and a name
  // nobody can guess in advance; mkstemp opens it with O_CREAT | O_EXCL.
  std::string pattern =
      (folder / ("." + file.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0)
    throw std::runtime_error(target + ": cannot create a temporary file in '" +
                             (folder.empty() ? std::string(".") : folder.string()) +
                             "': " + std::strerror(errno));
  ::fchmod(fd, creationMode());
  ::close(fd);
  path_ = pattern;
  slot_ = publish(path_);
}

TemporaryOutput::~TemporaryOutput() {
  if (!committed_) ::unlink(path_.c_str());
  release(slot_);
}

void TemporaryOutput::commit() {
  if (std::rename(path_.c_str(), target_.c_str()) != 0) {
    const int error = errno;
    throw std::runtime_error(target_ + ": cannot move the temporary file " + path_ +
                             " into place: " + std::strerror(error));
  }
  committed_ = true;
  release(slot_);
  slot_ = -1;
}

}  // namespace wpg::datasets
