#pragma once
// Reading back a run dataset written by writeRunDataset (datasets/SCHEMA.md): the walk itself
// (samples, footsteps, NMPC log) and the scenario text, enough to replay the walk on the
// multibody model (`wpg replay`) or to write it again. Multibody (but its ZMP errors), checks
// and obstacle groups are not read: they are recomputed from the walk and the scenario.
#include <optional>
#include <string>
#include <vector>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/walk_generator.hpp"

namespace wpg::datasets {

// The ZMP error attributes of /runs/<name>/multibody/ (present when the walk was replayed) [m].
struct StoredZmpError {
  bool filtered = false;
  double rms_before = 0.0, max_before = 0.0, rms_after = 0.0, max_after = 0.0;
};

struct StoredRun {
  // The resolved scenario (loadScenarioText): the run group's `scenario` attribute in a batch
  // file, else the root attribute `scenario`.
  std::string scenario_yaml;
  std::string name;           // the group /runs/<name>
  std::string robot;          // its `robot` attribute
  wpg::WalkResult result;     // trajectory (samples, footsteps, mpc log), success, message
  std::optional<StoredZmpError> zmp_error;  // when the run has a multibody/ group
};

// The names of the groups under /runs (sorted): one for a run file, one per finished run for a
// batch file. Throws InputError as readRunDataset.
std::vector<std::string> listRuns(const std::string& path);

// Reads /runs/<run_name> of `path`; with an empty run_name, the file's only run. Holds
// hdf5Mutex() while it reads.
//
// Throws InputError, one line naming the file and what is wrong: missing or unreadable file, not an
// HDF5 file, no such run (or several runs and no run_name), a dataset of the schema missing, of the
// wrong shape or type, declaring more rows than kMaxStoredSamples (checked before anything is
// allocated, wpg/datasets/storage/read_limits.hpp), per-sample datasets of different lengths, a
// value that is not finite (with its dataset, row and column), `time` or `mpc/time` not strictly
// increasing, codes outside their enums, negative counts, an attribute read as one value holding
// another number of them. Whether the walk belongs to its stored scenario is
// checkStoredRunMatchesScenario's (wpg/datasets/storage/stored_run_consistency.hpp).
StoredRun readRunDataset(const std::string& path, const std::string& run_name = "");

}  // namespace wpg::datasets
