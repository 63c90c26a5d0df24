// Where wpg finds robots/, datasets/scenarios/ and analysis/, and how a SCENARIO argument
// becomes a file path (data_paths.hpp).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "wpg/engine/data_paths.hpp"

#include "wpg/datasets/input/input_error.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {

std::string dataDirectory() {
  if (const char* from_env = std::getenv("WPG_DATA_DIR"); from_env && *from_env) {
    return from_env;
  }
  std::error_code ec;
  // Built from a source tree that is still there: use its data, so that edits to scenarios
  // and robots are seen without installing.
  if (fs::is_directory(fs::path(WPG_SOURCE_DATA_DIR) / "robots", ec)) return WPG_SOURCE_DATA_DIR;
  return WPG_INSTALLED_DATA_DIR;
}

std::string robotsDirectory() { return (fs::path(dataDirectory()) / "robots").string(); }

std::string scenariosDirectory() {
  return (fs::path(dataDirectory()) / "datasets" / "scenarios").string();
}

std::string plotScriptPath() {
  return (fs::path(dataDirectory()) / "analysis" / "plot_run.py").string();
}

std::vector<std::string> shippedScenarioNames() {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(scenariosDirectory(), ec), end; !ec && it != end;
       it.increment(ec)) {
    if (it->path().extension() == ".yaml") names.push_back(it->path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string resolveScenarioPath(const std::string& argument) {
  if (argument.empty()) throw datasets::InputError("empty scenario name");
  const std::string shown = datasets::escapeControlCharacters(argument);
  std::error_code ec;
  const fs::path as_path(argument);
  if (fs::exists(as_path, ec)) {
    if (fs::is_directory(as_path, ec)) {
      throw datasets::InputError("cannot read scenario '" + shown + "': it is a directory");
    }
    return argument;
  }
  // A path with a folder part must exist; a bare name may be a shipped scenario.
  if (as_path.has_parent_path()) {
    throw datasets::InputError("cannot read scenario file '" + shown + "': no such file");
  }
  fs::path shipped = fs::path(scenariosDirectory()) / as_path;
  if (shipped.extension() != ".yaml") shipped += ".yaml";
  if (fs::is_regular_file(shipped, ec)) return shipped.string();
  std::string known;
  for (const std::string& name : shippedScenarioNames()) known += (known.empty() ? "" : ", ") + name;
  throw datasets::InputError("cannot read scenario '" + shown +
                   "': no such file, and no shipped scenario of that name (shipped: " +
                   (known.empty() ? "none found in " + scenariosDirectory() : known) + ")");
}

}  // namespace wpg::engine
