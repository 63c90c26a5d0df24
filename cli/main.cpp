// The `wpg` executable: command-line parsing only (CLI11 is the slowest header of the project
// to compile, so it stays in this file); the subcommands live in the other cli/*.cpp files.
#include <exception>
#include <iostream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli_common.hpp"
#include "wpg/datasets/input_error.hpp"

int main(int argc, char** argv) {
  using namespace wpg::cli;

  CLI::App app{
      "wpg: walking pattern generator for humanoid robots, after Naveau et al., \"A Reactive "
      "Walking Pattern Generator Based on Nonlinear Model Predictive Control\", IEEE RA-L 2017.",
      "wpg"};
  app.option_defaults()->always_capture_default();
  app.set_version_flag("--version", std::string("wpg ") + WPG_VERSION_STRING);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 the walk failed (dataset still written), 2 bad input (nothing "
      "written).\nData (robots, scenarios, plot script): " + dataDirectory() +
      " (set WPG_DATA_DIR to use another).");

  RunOptions run;
  CLI::App* run_app = app.add_subcommand(
      "run", "Generate one walk from a scenario (default: walk_forward); write the HDF5 dataset and its figure.");
  std::string shipped;
  for (const std::string& name : shippedScenarioNames()) shipped += (shipped.empty() ? "" : ", ") + name;
  run_app
      ->add_option("scenario", run.scenario,
                   "Scenario file, or the name of a shipped scenario (" +
                       (shipped.empty() ? std::string("none found") : shipped) + ")")
      ->type_name("SCENARIO");
  run_app->add_option("-o,--output", run.output, "HDF5 dataset to write; the figure goes next to it (.png)")
      ->default_str("out/<scenario name>.h5")
      ->type_name("OUT.h5");
  run_app->add_option("--set", run.overrides,
                      "Override a scenario field after loading, key=value (repeatable), e.g. "
                      "--set duration=5")
      ->type_name("KEY=VALUE")
      ->default_str("");
  bool no_plot = false;
  run_app->add_flag("--no-plot", no_plot, "Do not draw the figure");

  PlotOptions plot;
  CLI::App* plot_app = app.add_subcommand("plot", "Draw the figure of a run dataset (PNG).");
  plot_app->add_option("run_file", plot.input, "HDF5 dataset written by `wpg run`")
      ->required()
      ->type_name("RUN.h5");
  plot_app->add_option("-o,--output", plot.output, "PNG to write")
      ->default_str("RUN.png next to RUN.h5")
      ->type_name("FIG.png");

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    printError(std::string(e.what()) + " (see wpg --help)");
    return kExitBadInput;
  }

  try {
    if (run_app->parsed()) {
      run.plot = !no_plot;
      return runCommand(run);
    }
    return plotCommand(plot);
  } catch (const UsageError& e) {
    printError(e.what());
    return kExitBadInput;
  } catch (const wpg::datasets::InputError& e) {
    printError(e.what());
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    printError(e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    printError(e.what());
    return kExitRunFailed;
  }
}
