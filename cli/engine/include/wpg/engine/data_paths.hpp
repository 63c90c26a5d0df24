#pragma once
// Where wpg finds robots/, datasets/scenarios/ and analysis/ (the CLI, the Python package and
// any other program of the engine's), and how a SCENARIO argument becomes a file path.
#include <string>
#include <vector>

namespace wpg::engine {

// The folder holding robots/, datasets/scenarios/ and analysis/: $WPG_DATA_DIR when set and
// non-empty, else the source tree wpg was built from when it still exists, else the installed
// share/wpg.
std::string dataDirectory();
std::string robotsDirectory();
std::string scenariosDirectory();
std::string plotScriptPath();  // analysis/plot_run.py, the figure of a run

// The name of the default scenario (datasets/scenarios/<name>.yaml).
constexpr const char* kDefaultScenario = "walk_forward";

// Names of the shipped scenarios (file stems of datasets/scenarios/*.yaml), sorted.
std::vector<std::string> shippedScenarioNames();

// A SCENARIO argument is an existing file path, or the name of a shipped scenario (with or
// without ".yaml"). Returns the file path; throws datasets::InputError naming the argument
// (control characters escaped) otherwise.
std::string resolveScenarioPath(const std::string& argument);

}  // namespace wpg::engine
