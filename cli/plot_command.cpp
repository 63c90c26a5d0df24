// `wpg plot` and the figure drawn at the end of `wpg run`: both run analysis/plot_run.py with
// Debian's Python (/usr/bin/python3: a pyenv python3 first on PATH would not see Debian's
// h5py and matplotlib).
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <system_error>

#include "cli_common.hpp"
#include "wpg/datasets/input_error.hpp"
#include "wpg/datasets/output_file.hpp"
#include "wpg/datasets/provenance.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

constexpr const char* kPython = "/usr/bin/python3";

// Messages are one line: line breaks become spaces, and any other control character (user
// text quoted in a usage error) is escaped.
std::string oneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return datasets::escapeControlCharacters(text);
}

}  // namespace

void printError(const std::string& message) { std::cerr << "wpg: error: " << oneLine(message) << '\n'; }

void printWarning(const std::string& message) {
  std::cerr << "wpg: warning: " << oneLine(message) << '\n';
}

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

int plotCommand(const PlotOptions& options) {
  std::error_code ec;
  if (!fs::exists(options.input, ec)) {
    throw UsageError("cannot read run file '" + options.input + "': no such file");
  }
  if (!fs::is_regular_file(options.input, ec) || !std::ifstream(options.input).good()) {
    throw UsageError("cannot read run file '" + options.input + "'");
  }
  fs::path figure = options.output;
  if (figure.empty()) {
    figure = fs::path(options.input).replace_extension(options.run.empty() ? ".png" : "." + options.run + ".png");
  }
  // Never over the run file, a device, a folder or a file that is not a PNG (output_file.hpp).
  try {
    datasets::checkOutputPath(figure.string(), datasets::OutputKind::kPng, {options.input});
  } catch (const datasets::InputError& e) {
    throw UsageError(e.what());
  }
  if (figure.has_parent_path()) {
    fs::create_directories(figure.parent_path(), ec);
    if (ec) {
      throw UsageError("cannot create the folder of '" + figure.string() + "': " + ec.message());
    }
  }
  // The script checks the file and reports a bad one in one line (exit 2); any failure of it
  // is the input's (no walk ran): exit 2, as every other bad input.
  const int status = drawFigure(options.input, figure.string(), options.run);
  if (status != kExitSuccess) return kExitBadInput;
  std::cout << "figure: " << figure.string() << '\n';
  return kExitSuccess;
}

}  // namespace wpg::cli
