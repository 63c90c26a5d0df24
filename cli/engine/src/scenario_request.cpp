// One scenario as a front end asks for it (scenario_request.hpp).
#include "wpg/engine/scenario_request.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/yaml_input.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/data_paths.hpp"
#include "wpg/engine/run_input_checks.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {
namespace {

// Every bad-input message names the scenario file (the loader's messages usually do already).
std::string aboutFile(const std::string& path, const std::string& message) {
  if (message.find(path) != std::string::npos) return message;
  return path + ": " + message;
}

}  // namespace

LoadedScenario loadScenarioRequest(const ScenarioRequest& request, RobotModelCache& models) {
  LoadedScenario loaded;
  loaded.path = resolveScenarioPath(request.scenario);
  // After every override, so that the resolved scenario in the dataset says what ran.
  std::vector<std::string> overrides = request.overrides;
  if (request.replay) overrides.push_back("replay=true");
  if (request.filter) overrides.push_back("filter=true");
  const auto named = [&](const std::string& message) {
    return datasets::detail::renameOverrides(message, request.overrides_name);
  };
  try {
    loaded.scenario = datasets::loadScenario(loaded.path, overrides, models.robotsDirectory());
  } catch (const datasets::InputError& e) {
    throw datasets::InputError(aboutFile(loaded.path, named(e.what())));
  } catch (const std::invalid_argument& e) {
    throw datasets::InputError(aboutFile(loaded.path, named(e.what())));
  }
  for (std::string& warning : loaded.scenario.warnings) warning = named(warning);
  checkRunInput(loaded.scenario, loaded.path, models);
  return loaded;
}

std::vector<std::string> runInputs(const LoadedScenario& loaded) {
  const std::string robots = robotsDirectory();
  std::vector<std::string> inputs = {loaded.path,
                                     robotWalkingFilePath(robots, loaded.scenario.robot)};
  const std::string urdf = robotUrdfPath(robots, loaded.scenario.robot, loaded.scenario.multibody);
  if (!urdf.empty()) inputs.push_back(urdf);
  return inputs;
}

RunOutputs runOutputsOf(const LoadedScenario& loaded, const std::string& output, bool figure) {
  RunOutputs outputs;
  const fs::path dataset =
      output.empty() ? fs::path("out") / (loaded.scenario.name + ".h5") : fs::path(output);
  outputs.dataset = dataset.string();
  if (figure) {
    fs::path png = fs::path(dataset).replace_extension(".png");
    if (png == dataset) png += ".png";  // never draw over the dataset
    outputs.figure = png.string();
  }
  return outputs;
}

void checkRunOutputs(const LoadedScenario& loaded, const RunOutputs& outputs) {
  const std::vector<std::string> inputs = runInputs(loaded);
  datasets::checkOutputPath(outputs.dataset, datasets::OutputKind::kHdf5, inputs);
  if (!outputs.figure.empty()) {
    datasets::checkOutputPath(outputs.figure, datasets::OutputKind::kPng, inputs);
  }
  datasets::checkWritableParent(outputs.dataset);
}

void saveRun(const LoadedScenario& loaded, const RunResult& result, const std::string& path) {
  checkRunOutputs(loaded, {path, ""});
  const fs::path dataset(path);
  if (dataset.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(dataset.parent_path(), ec);
    if (ec) {
      throw datasets::InputError("cannot create the folder of '" + path + "': " + ec.message());
    }
  }
  try {
    writeRunDataset(path, loaded.scenario, result);
  } catch (const std::invalid_argument& e) {
    // An inconsistent trajectory is a bug, not bad input.
    throw std::runtime_error(std::string("cannot write the dataset: ") + e.what());
  }
}

}  // namespace wpg::engine
