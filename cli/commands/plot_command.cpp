// `wpg plot RUN.h5 [-o FIG.png] [--run NAME]`: the figure of a run dataset, or of one run of a
// batch file (analysis/plot_run.py, the figure `wpg run` draws too).
#include <filesystem>
#include <iostream>
#include <system_error>

#include "analysis_scripts.hpp"
#include "command_options.hpp"
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
