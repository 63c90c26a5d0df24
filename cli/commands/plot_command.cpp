// `wpg plot RUN.h5 [-o FIG.png] [--run NAME] [--plan [--at T...]]`: the figure of a run
// dataset, or of one run of a batch file (analysis/plot_run.py, the figure `wpg run` draws
// too); with --plan, what the NMPC previewed against what the robot did.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include "analysis_scripts.hpp"
#include "command_options.hpp"
#include "data_paths.hpp"
#include "exit_codes.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/input_file.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/datasets/storage/stored_strings_check.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {

int plotCommand(const PlotOptions& options) {
  std::error_code ec;
  if (!fs::exists(options.input, ec)) {
    throw UsageError("cannot read run file '" + options.input + "': no such file");
  }
  datasets::checkInputFile(options.input);  // the script would block in a FIFO
  datasets::checkStoredStrings(options.input);  // h5py would loop or crash on a damaged heap
  if (!options.at.empty() && !options.plan) throw UsageError("--at: expected with --plan only");
  fs::path figure = options.output;
  if (figure.empty()) {
    figure = fs::path(options.input)
                 .replace_extension((options.run.empty() ? "" : "." + options.run) +
                                    (options.plan ? ".plan.png" : ".png"));
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
  std::vector<std::string> arguments = {options.input, "-o", figure.string()};
  if (!options.run.empty()) arguments.insert(arguments.end(), {"--run", options.run});
  if (options.plan) arguments.emplace_back("--plan");
  if (!options.at.empty()) {
    arguments.emplace_back("--at");
    for (const double t : options.at) {
      char text[32];
      std::snprintf(text, sizeof text, "%.17g", t);  // the value itself, not 6 decimals
      arguments.emplace_back(text);
    }
  }
  const int status = runAnalysisScript(plotScriptPath(), arguments);
  if (status != kExitSuccess) return kExitBadInput;
  std::cout << "figure: " << figure.string() << '\n';
  return kExitSuccess;
}

}  // namespace wpg::cli
