// Output files (wpg/datasets/storage/output_file.hpp): the checks of an output path, the
// exclusive temporary file and its removal on SIGINT / SIGTERM.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/output_file.hpp"

namespace {

namespace fs = std::filesystem;
using wpg::datasets::checkOutputPath;
using wpg::datasets::InputError;
using wpg::datasets::OutputKind;
using wpg::datasets::TemporaryOutput;

class OutputFile : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/wpg-output-file.XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    folder_ = pattern;
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::string file(const std::string& name, const std::string& content) const {
    const std::string path = (fs::path(folder_) / name).string();
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }
  int entries() const {
    int n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(folder_)) ++n;
    return n;
  }
  std::string folder_;
};

TEST_F(OutputFile, RefusesWhatIsNotARegularFileOfItsKind) {
  EXPECT_NO_THROW(checkOutputPath(folder_ + "/new.h5", OutputKind::kHdf5));
  EXPECT_THROW(checkOutputPath(folder_, OutputKind::kHdf5), InputError);
  EXPECT_THROW(checkOutputPath(folder_ + "/sub/", OutputKind::kHdf5), InputError);
  EXPECT_THROW(checkOutputPath("/dev/null", OutputKind::kHdf5), InputError);
  // A name whose temporary file (".<name>.XXXXXX") would not fit in 255 bytes: refused before
  // the work, not when the output is written.
  EXPECT_NO_THROW(checkOutputPath(folder_ + "/" + std::string(244, 'n') + ".h5", OutputKind::kHdf5));
  try {
    checkOutputPath(folder_ + "/" + std::string(245, 'n') + ".h5", OutputKind::kHdf5);
    ADD_FAILURE() << "a 248-byte file name was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("a file name of 248 bytes"), std::string::npos)
        << error.what();
  }
  const std::string hdf5 = file("a.h5", std::string("\x89HDF\r\n\x1a\n", 8) + "rest");
  const std::string png = file("a.png", std::string("\x89PNG\r\n\x1a\n", 8) + "rest");
  const std::string json = file("a.json", "  \n{\"x\": 1}");
  const std::string yaml = file("a.yaml", "name: x\n");
  const std::string empty = file("empty", "");
  EXPECT_NO_THROW(checkOutputPath(hdf5, OutputKind::kHdf5));
  EXPECT_NO_THROW(checkOutputPath(png, OutputKind::kPng));
  EXPECT_NO_THROW(checkOutputPath(json, OutputKind::kJson));
  EXPECT_NO_THROW(checkOutputPath(empty, OutputKind::kPng));
  EXPECT_THROW(checkOutputPath(hdf5, OutputKind::kPng), InputError);
  EXPECT_THROW(checkOutputPath(yaml, OutputKind::kHdf5), InputError);
  EXPECT_THROW(checkOutputPath(png, OutputKind::kJson), InputError);
  // An HDF5 superblock after a 512-byte user block.
  const std::string userblock = file("u.h5", std::string(512, ' ') + "\x89HDF\r\n\x1a\n" + "x");
  EXPECT_NO_THROW(checkOutputPath(userblock, OutputKind::kHdf5));
  // The same file as an input, by any name.
  const std::string link = (fs::path(folder_) / "second_name.h5").string();
  ASSERT_EQ(::link(hdf5.c_str(), link.c_str()), 0);
  EXPECT_THROW(checkOutputPath(link, OutputKind::kHdf5, {hdf5}), InputError);
  EXPECT_NO_THROW(checkOutputPath(link, OutputKind::kHdf5, {png, folder_ + "/missing"}));
  try {
    checkOutputPath("/dev/null", OutputKind::kHdf5);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("character device"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

TEST_F(OutputFile, TemporaryIsExclusiveUnpredictableAndRemoved) {
  const std::string target = (fs::path(folder_) / "out.h5").string();
  {
    TemporaryOutput a(target), b(target);
    EXPECT_NE(a.path(), b.path());
    EXPECT_EQ(fs::path(a.path()).parent_path(), fs::path(target).parent_path());
    EXPECT_EQ(a.path().find(".tmp-" + std::to_string(::getpid())), std::string::npos);
    EXPECT_TRUE(fs::is_regular_file(a.path()));
    EXPECT_FALSE(fs::is_symlink(a.path()));
    EXPECT_EQ(entries(), 2);
  }
  EXPECT_EQ(entries(), 0);  // not committed: removed
  {
    TemporaryOutput a(target);
    std::ofstream(a.path()) << "data";
    a.commit();
  }
  EXPECT_EQ(entries(), 1);
  std::ifstream in(target);
  std::string content;
  in >> content;
  EXPECT_EQ(content, "data");
  // Mode: 0666 less the umask, as a file the program creates.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat s {};
  ASSERT_EQ(::stat(target.c_str(), &s), 0);
  EXPECT_EQ(s.st_mode & 0777, 0666 & ~mask);
}

// A process killed by SIGTERM or SIGINT while its temporary file exists leaves nothing behind.
TEST_F(OutputFile, TemporaryRemovedOnTermination) {
  for (const int signal_number : {SIGTERM, SIGINT}) {
    // Started with the signal ignored (SIGINT, in a background job of a non-interactive
    // shell), the process goes on after it: IgnoredSignalKeepsTheTemporary.
    struct sigaction current {};
    ::sigaction(signal_number, nullptr, &current);
    if (current.sa_handler == SIG_IGN) continue;
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::close(ready[0]);
      TemporaryOutput temporary((fs::path(folder_) / "out.h5").string());
      std::ofstream(temporary.path()) << std::string(1 << 20, 'x');  // a partly written output
      const char byte = 1;
      if (::write(ready[1], &byte, 1) != 1) ::_exit(3);
      for (;;) ::pause();
    }
    ::close(ready[1]);
    char byte = 0;
    ASSERT_EQ(::read(ready[0], &byte, 1), 1);
    ::close(ready[0]);
    EXPECT_EQ(entries(), 1);
    ::kill(child, signal_number);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), signal_number);  // the default action still ends it
    EXPECT_EQ(entries(), 0) << "signal " << signal_number;
  }
}

// A process started with SIGINT ignored (`wpg batch ... &` in a script: POSIX shells start
// background jobs so) goes on after a SIGINT: its temporary output must stay, or the process
// writes on into an unlinked file and cannot rename it at the end. The removal on a signal is
// for signals that end the process. In a fresh process (a death test re-executes the binary),
// so that no handler installed by an earlier test is inherited.
TEST_F(OutputFile, IgnoredSignalKeepsTheTemporary) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const std::string target = (fs::path(folder_) / "out.h5").string();
  EXPECT_EXIT(
      {
        ::signal(SIGINT, SIG_IGN);
        TemporaryOutput temporary(target);
        std::ofstream(temporary.path()) << "partly written";
        ::raise(SIGINT);  // ignored, as it was when the process started
        std::_Exit(fs::exists(temporary.path()) ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace

// forgoWriteOutOnClose opens and closes the file once more: the claim (an open-file-description
// lock) must survive that close, as a classic fcntl lock would not.
TEST_F(OutputFile, ForgoingTheWriteOutOnCloseKeepsTheClaim) {
  const std::string path = (fs::path(folder_) / "batch.h5").string();
  wpg::datasets::OutputClaim claim(path);
  ASSERT_TRUE(claim.created());
  wpg::datasets::forgoWriteOutOnClose(path);
  try {
    wpg::datasets::OutputClaim second(path);
    ADD_FAILURE() << "a second claim was granted after forgoWriteOutOnClose";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("in use by another wpg"), std::string::npos)
        << error.what();
  }
  wpg::datasets::forgoWriteOutOnClose((fs::path(folder_) / "missing.h5").string());  // no-op
  EXPECT_FALSE(fs::exists(fs::path(folder_) / "missing.h5"));
}
