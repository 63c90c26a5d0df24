// The figures: analysis/'s Python scripts run with Debian's Python (analysis_scripts.hpp).
#include "analysis_scripts.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "data_paths.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "wpg/datasets/storage/provenance.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

constexpr const char* kPython = "/usr/bin/python3";

}  // namespace

int drawFigure(const std::string& run_file, const std::string& figure_file, const std::string& run) {
  std::vector<std::string> arguments = {run_file, "-o", figure_file};
  if (!run.empty()) arguments.insert(arguments.end(), {"--run", run});
  return runAnalysisScript(plotScriptPath(), arguments);
}

int runAnalysisScript(const std::string& script, const std::vector<std::string>& arguments) {
  if (::access(kPython, X_OK) != 0) {
    printError(std::string("plotting needs ") + kPython +
               " with h5py and matplotlib: install the Debian packages python3 python3-h5py "
               "python3-matplotlib");
    return kExitBadInput;
  }
  std::error_code ec;
  if (!fs::is_regular_file(script, ec)) {
    printError("plot script not found: " + script + " (set WPG_DATA_DIR to the wpg data folder)");
    return kExitBadInput;
  }
  // The script reports its errors as "wpg: error: ..." like the rest of the CLI, and writes who
  // drew the figure into the PNG (its Software text, as every file of wpg names its writer).
  ::setenv("WPG_PLOT_PROG", "wpg", 1);
  const datasets::Provenance who = datasets::currentProvenance();
  ::setenv("WPG_PROVENANCE", ("wpg " + who.version + " (commit " + who.commit + ") on " +
                              who.machine + " at " + who.date).c_str(), 1);
  std::vector<std::string> args{kPython, script};
  args.insert(args.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (int err = ::posix_spawn(&pid, kPython, nullptr, nullptr, argv.data(), environ); err != 0) {
    printError(std::string("cannot start ") + kPython + ": " + std::strerror(err));
    return kExitBadInput;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      printError(std::string("waiting for the plot script: ") + std::strerror(errno));
      return kExitRunFailed;
    }
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  printError("the plot script was killed by signal " + std::to_string(WTERMSIG(status)));
  return kExitRunFailed;
}

}  // namespace wpg::cli
