// The `wpg` executable: one registration per subcommand (commands/registration.cpp holds their
// options), then the chosen subcommand runs and its errors become the exit codes.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "data_paths.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "registration.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/engine/mpi_executor.hpp"
#include "wpg/version.hpp"

namespace {

// Exit 3 (could not complete; the temporary output is already removed) without the libraries'
// exit-time cleanup: after a failed write HDF5 may hold a file it could not close, and its
// termination handler crashes on it (exit 139 instead of 3).
[[noreturn]] void leaveIncomplete(const std::string& what) {
  wpg::cli::printError("could not complete: " + what);
  std::cout.flush();
  std::cerr.flush();
  std::_Exit(wpg::cli::kExitIncomplete);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace wpg::cli;
  // Past a file size limit (`ulimit -f`) the kernel's SIGXFSZ would kill the process with its
  // temporary file left behind: ignored, the write fails with EFBIG instead, an I/O error like
  // a full disk (exit 3, the temporary file removed). Inherited by the plot scripts too.
  std::signal(SIGXFSZ, SIG_IGN);

  CLI::App app{
      "wpg: walking pattern generator for humanoid robots, after Naveau et al., \"A Reactive "
      "Walking Pattern Generator Based on Nonlinear Model Predictive Control\", IEEE RA-L 2017.",
      "wpg"};
  app.option_defaults()->always_capture_default();
  app.set_version_flag("--version", std::string("wpg ") + WPG_VERSION_STRING);
  app.require_subcommand(1);
  app.footer(
      "Exit codes (each subcommand's --help lists those it returns): 0 success, 1 a walk "
      "failed (run, bench, batch, merge; the data still written) or the files differ (diff), 2 "
      "bad input (nothing written), 3 could not complete (out of memory, I/O error; no output "
      "file written).\n"
      "Data (robots, scenarios, plot script): " +
      dataDirectory() + " (set WPG_DATA_DIR to use another).");

  CommandAction command;
  registerRunCommand(app, command);
  registerReplayCommand(app, command);
  registerBenchCommand(app, command);
  registerBatchCommand(app, command);
  registerMergeCommand(app, command);
  registerCompareCommand(app, command);
  registerAnalyzeCommand(app, command);
  registerDiffCommand(app, command);
  registerPushSweepCommand(app, command);
  registerPlotCommand(app, command);
  registerViewCommand(app, command);
  registerRobotCommand(app, command);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    printError(std::string(e.what()) + " (see wpg --help)");
    return kExitBadInput;
  }

  try {
    return command();
  } catch (const UsageError& e) {
    printError(e.what());
    return kExitBadInput;
  } catch (const wpg::datasets::InputError& e) {
    printError(e.what());
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    printError(e.what());
    return kExitBadInput;
  } catch (const wpg::engine::RankStopped&) {
    // Rank 0 reports why on stderr and exits with the code (bad input, or could not complete);
    // this rank leaves quietly with 0. A non-zero exit here let mpiexec abort the job, rank 0
    // included, before rank 0 had written its line (seen in CI: no error line at all); mpiexec
    // returns rank 0's code all the same.
    return 0;
  } catch (const std::bad_alloc&) {
    leaveIncomplete("out of memory");
  } catch (const std::exception& e) {
    // A walk that fails returns kExitRunFailed with its dataset written; an exception that
    // reaches here stopped the command before its output was complete (I/O error, disk full).
    leaveIncomplete(e.what());
  }
}
