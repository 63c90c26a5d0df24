#pragma once
// One scenario as a front end asks for it (`wpg run`, wpg.run and Run.save): the scenario
// argument, its overrides, the replay and filter switches, and where its dataset and figure go.
// The engine owns every check of it, so that every front end refuses the same input and the
// same outputs the same way, before anything runs or is written: loadScenarioRequest (the
// scenario, the robot's model, the filter's controller, the goal), checkRunOutputs (the
// dataset and figure paths against the run's inputs), saveRun (checked again, then written).
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/engine/robot_models.hpp"
#include "wpg/engine/scenario_run.hpp"

namespace wpg::engine {

struct ScenarioRequest {
  std::string scenario;                // a file, or the name of a shipped scenario
  std::vector<std::string> overrides;  // "key=value", as `--set` (the front end's syntax checked)
  bool replay = false;                 // as the scenario's `replay: true`, after every override
  bool filter = false;                 // as `filter: true` (implies the replay)
  // What the front end calls the overrides: messages and warnings say "(set by --set '...')"
  // in `wpg`, "(set by overrides '...')" in Python.
  std::string overrides_name = "--set";
};

// A scenario loaded from a request and checked: ready to run (runScenario).
struct LoadedScenario {
  datasets::Scenario scenario;
  std::string path;  // the scenario file
};

// Resolves, loads and checks the request's scenario (datasets/input), then what needs more than
// its file (checkRunInput: the robot's multibody model, loaded into `models` when it replays,
// the filter's controller, the goal). Throws datasets::InputError, one line naming the file.
LoadedScenario loadScenarioRequest(const ScenarioRequest& request, RobotModelCache& models);

// The files a run of `loaded` reads (the scenario, the robot's walking.yaml and URDF): never
// overwritten by its outputs.
std::vector<std::string> runInputs(const LoadedScenario& loaded);

// Where a run's files go: the dataset (HDF5) and, when not empty, the figure the front end
// draws of it (PNG).
struct RunOutputs {
  std::string dataset;
  std::string figure;
};
// `output` (empty: out/<scenario name>.h5) and, with `figure`, the PNG beside it (its extension
// replaced; never the dataset's own path).
RunOutputs runOutputsOf(const LoadedScenario& loaded, const std::string& output, bool figure);

// Both outputs may be written (datasets::checkOutputPath against runInputs, and a writable
// folder). Throws datasets::InputError naming the path.
void checkRunOutputs(const LoadedScenario& loaded, const RunOutputs& outputs);

// The run's dataset at `path` (checkRunOutputs first, the folder created, written atomically).
void saveRun(const LoadedScenario& loaded, const RunResult& result, const std::string& path);

}  // namespace wpg::engine
