#pragma once
// Output files that never destroy what is not theirs (docs/commands.md):
//  * checkOutputPath refuses, before anything is computed or written, an output path that is
//    a folder (or ends with '/'), that exists and is not a regular file (a device such as
//    /dev/null, a FIFO, /proc/self/fd/1), that is the same file (device and inode, whatever the
//    name) as one of the command's inputs, or that exists and holds another kind of data than
//    the command writes there (an HDF5 output over a scenario or a figure, a figure over a
//    dataset). A symbolic link is refused too (never followed: its target may be anything).
//    Policy for an existing output of the same kind (an HDF5 file where wpg writes a
//    dataset, a PNG where it draws a figure, a JSON file where it writes JSON): it is replaced,
//    atomically. Empty files count as any kind.
//  * TemporaryOutput is where the data is written before it replaces the target: a file created
//    exclusively (O_EXCL, mkstemp) with an unpredictable name in the target's folder (a symlink
//    planted there cannot redirect the write), renamed over the target by commit() (atomic on
//    one file system), removed by the destructor otherwise, and removed too when the process
//    gets SIGINT or SIGTERM while it exists (not a signal the process was started ignoring: it
//    goes on after that one).
#include <string>
#include <vector>

namespace wpg::datasets {

enum class OutputKind {
  kHdf5,  // "\x89HDF\r\n\x1a\n" at offset 0, 512, 1024, ... (HDF5's superblock signature)
  kPng,   // "\x89PNG\r\n\x1a\n" at offset 0
  kJson,  // first non-blank character '{' or '['
  kHtml,  // first non-blank character '<' (the pages of `wpg view`)
  kBenchmarkLog,  // first line "<library> version <number>" (OMPL's benchmark log format)
  kSqlite,  // "SQLite format 3\0" at offset 0 (the Planner Arena database of --ompl-log)
  kText,  // CSV, Markdown, YAML: no NUL byte in the first 64 KiB (a dataset or figure has one)
};
const char* outputKindName(OutputKind kind);  // "an HDF5 file", "a PNG image", "a JSON file"

// Throws InputError (one line naming `path`, e.g. "'/dev/null': expected a regular file to
// write an HDF5 file to, got a character device") when `path` may not be written as `kind`
// (above). `inputs`: the files the command reads (missing ones are skipped).
void checkOutputPath(const std::string& path, OutputKind kind,
                     const std::vector<std::string>& inputs = {});

// Every file a command will write, checked together before any work (checkOutputPath on each,
// checkWritableParent on each, and no two outputs the same path): side outputs (a batch's
// OUT.summary.csv/.md/.png, a comparison's DIR/summary.*, push-sweep's OUT.<situation>.yaml)
// are held to the same rules as the main output.
struct PlannedOutput {
  std::string path;
  OutputKind kind;
};
void checkOutputPaths(const std::vector<PlannedOutput>& outputs,
                      const std::vector<std::string>& inputs = {});

// A folder a command writes its outputs into (the run pages of `wpg view`, PAGE_runs/): absent
// (created when written) or a folder, never a symbolic link (not followed: the pages would go
// wherever it points). Throws InputError naming `folder` and what it is otherwise. The files
// in it are checked one by one (checkOutputPaths).
void checkOutputFolder(const std::string& folder);

// Writes `content` to `path` atomically (TemporaryOutput, then rename). Throws
// std::runtime_error naming `path` on an I/O error (a full disk, a file size limit: EFBIG),
// leaving neither the temporary file nor a partial `path`.
void writeFileAtomically(const std::string& path, const std::string& content);

// Call right after HDF5 has created `path` (H5F_ACC_TRUNC, an open with O_TRUNC), for the
// files that hold a whole study (the batch file, a copied index) only. ext4 (its default
// auto_da_alloc) marks a file truncated to zero for writing out at its next close, a heuristic
// for programs that rewrite a file without fsync; closing a 47 MB batch file then spent 2-8 ms
// in close() allocating and queueing all of it (strace of 9 `wpg batch -j 2` runs), on the one
// thread that finishes the study. The mark is the inode's and the first close of any
// descriptor takes it, so an open and a close now, while the file holds nothing, leave the
// data to the kernel's usual writeback. A run file (a few hundred kB) is not worth it.
// Elsewhere an open and a close, nothing more; errors are ignored (an optimisation).
void forgoWriteOutOnClose(const std::string& path);

// An exclusive claim on an output file that is written in place for a long time (a batch file,
// resumed later): an open-file-description lock (fcntl F_OFD_SETLK) on the file itself, held
// until destruction, taken BEFORE the file is truncated or its health examined. A file another
// process holds (another wpg writing it, or any program with it open through HDF5, whose lock
// is a flock) is refused with InputError "'<path>': in use by another wpg or HDF5 program
// (nothing written)" and left untouched. A file created by acquire() that is still empty when
// the claim ends is removed.
class OutputClaim {
 public:
  explicit OutputClaim(const std::string& path);
  ~OutputClaim();
  OutputClaim(const OutputClaim&) = delete;
  OutputClaim& operator=(const OutputClaim&) = delete;
  bool created() const { return created_; }  // the file did not exist before

 private:
  std::string path_;
  int fd_ = -1;
  bool created_ = false;
};

// An exclusive claim on a folder of files that one job writes together (the shards of `wpg
// batch` under MPI, OUT.shards/): a flock on the folder itself (created when missing), held
// until destruction and released by the kernel however the process ends (an aborted MPI job
// leaves nothing behind). A folder another process holds is refused with InputError
// "'<owner>': in use by another wpg (<folder> is held by a running job; nothing written)".
class FolderClaim {
 public:
  FolderClaim(const std::string& folder, const std::string& owner);
  ~FolderClaim();
  FolderClaim(const FolderClaim&) = delete;
  FolderClaim& operator=(const FolderClaim&) = delete;

 private:
  int fd_ = -1;
};

// Throws InputError ("cannot write output '<output>': '<folder>' is not a writable directory")
// unless the nearest existing folder above `output` is a directory this process may write in.
void checkWritableParent(const std::string& output);

class TemporaryOutput {
 public:
  // Creates the target's folder if needed and the temporary file in it (empty, mode 0666 less
  // the umask, like a file the program would create). Throws std::runtime_error naming the
  // folder when it cannot.
  explicit TemporaryOutput(const std::string& target);
  ~TemporaryOutput();  // removes the temporary file unless committed
  TemporaryOutput(const TemporaryOutput&) = delete;
  TemporaryOutput& operator=(const TemporaryOutput&) = delete;

  const std::string& path() const { return path_; }  // where to write
  // Renames the temporary file over the target. Throws std::runtime_error naming both.
  void commit();

 private:
  std::string target_;
  std::string path_;
  int slot_ = -1;  // in the signal handler's table
  bool committed_ = false;
};

}  // namespace wpg::datasets
