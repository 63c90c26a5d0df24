#pragma once
// What the Python package asks of the engine, in plain C++ (no pybind11 here: it is heavy, and
// python_bindings.cpp is the one file that includes it). Each call is the engine's call that the
// `wpg` subcommand of the same name makes (scenario_request.hpp, batch_study_run.hpp,
// comparison_study_run.hpp), which owns every input and output check: the same refusals before
// anything is written, the same files, the same exit meaning; bad input is a
// datasets::InputError whose one-line message names the file and the key.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/storage/run_scene_reader.hpp"
#include "wpg/engine/data_paths.hpp"
#include "wpg/engine/scenario_request.hpp"
#include "wpg/engine/scenario_run.hpp"

namespace wpg::python {

// The data folders and scenario arguments, found as `wpg` finds them (the engine's).
using engine::dataDirectory;
using engine::resolveScenarioPath;
using engine::robotsDirectory;
using engine::shippedScenarioNames;

// A run held for Python: the scenario it ran and its result. A run read back from a file has
// `stored_file` set and no replay (its multibody datasets stay in the file).
struct RunSession {
  engine::LoadedScenario loaded;  // the scenario and its file (no file for a run read back)
  engine::RunResult result;
  std::string stored_file, stored_name;
};

// `wpg run SCENARIO --set KEY=VALUE... [--replay] [--filter]` without its files: loads and
// checks the scenario (InputError, nothing run), then runScenario. Call without the GIL.
std::shared_ptr<RunSession> runScenarioFile(const std::string& scenario,
                                            std::vector<std::string> overrides, bool replay,
                                            bool filter);

// The route plans of a walk to a goal (empty otherwise), as a run file stores them: from the
// result of a run, or read back from the file of a run loaded (datasets::readRoutePlans, bounded
// and checked: InputError).
std::vector<datasets::StoredRoutePlan> routePlans(const RunSession& run);

// The run's dataset at `path`, as `wpg run -o PATH` writes it: the output path checked first
// (never over an input, a folder, a device or a file that is not HDF5: InputError), its folder
// created, the file written atomically.
void saveRun(const RunSession& run, const std::string& path);

// The run `name` of a run, batch, merged or MPI index file (empty name: the file's only run),
// checked against its stored scenario, with the metrics `wpg analyze` computes from it.
std::shared_ptr<RunSession> loadStoredRun(const std::string& path, const std::string& name);
std::vector<std::string> storedRunNames(const std::string& path);
// The variable-length strings below `group` of the file checked before h5py reads them
// (wpg/datasets/storage/stored_strings_check.hpp): HDF5 would hang or crash the interpreter.
void checkStoredStrings(const std::string& path, const std::string& group);

// Called after each run of a study, on the thread that delivers it; throws to stop the study
// the way the engine stops on any error while delivering: no new run is handed out, the running
// ones finish (a run's time at most), and the batch file holds every run delivered, for
// `resume` to finish. The bindings throw when Python has a signal pending (Ctrl-C).
using StopCheck = std::function<void()>;

// What messages call the overrides of wpg.run() and OnlineGenerator (`--set` in `wpg`).
inline constexpr const char* kOverridesName = "overrides";

// The scenario of an OnlineGenerator, loaded and checked as wpg.run()'s.
datasets::Scenario loadOnlineScenario(const std::string& scenario,
                                      const std::vector<std::string>& overrides);

// `wpg batch STUDY -o OUTPUT -j JOBS [--resume]`: OUTPUT and OUTPUT.summary.csv/.md; with
// `figure`, OUTPUT.summary.png is checked with them (the package draws it after). Returns the
// number of failed runs (exit status 1 when not 0). Call without the GIL.
struct StudyFiles {
  std::string batch_file;
  std::size_t runs = 0, failed_runs = 0;
};
// `fields` (--fields): what each run stores; none: the study's.
StudyFiles runBatch(const std::string& study, const std::string& output, int jobs, bool resume,
                    bool figure, const std::optional<std::vector<std::string>>& fields,
                    const StopCheck& stop);

// `wpg compare STUDY -o FOLDER -j JOBS`: FOLDER/study.h5, summary.csv and summary.md; with
// `figures`, the figures' paths are checked with them (the package draws them after). Call
// without the GIL.
StudyFiles runCompare(const std::string& study, const std::string& folder, int jobs,
                      bool figures, const StopCheck& stop);

}  // namespace wpg::python
