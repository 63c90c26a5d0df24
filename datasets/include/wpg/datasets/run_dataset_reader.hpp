#pragma once
// Reading back a run dataset written by writeRunDataset (datasets/SCHEMA.md): the walk itself
// (samples, footsteps, NMPC log) and the scenario text, enough to replay the walk on the
// multibody model (`wpg replay`) or to write it again. Multibody, checks and obstacle groups
// are not read: they are recomputed from the walk and the scenario.
#include <string>

#include "wpg/datasets/input_error.hpp"
#include "wpg/walk_generator.hpp"

namespace wpg::datasets {

struct StoredRun {
  std::string scenario_yaml;  // root attribute `scenario`: the resolved scenario (loadScenarioText)
  std::string name;           // the group /runs/<name>
  std::string robot;          // its `robot` attribute
  wpg::WalkResult result;     // trajectory (samples, footsteps, mpc log), success, message
};

// Reads /runs/<run_name> of `path`; with an empty run_name, the file's only run. Holds
// hdf5Mutex() while it reads.
//
// Throws InputError, one line naming the file and what is wrong: missing or unreadable file,
// not an HDF5 file, no such run (or several runs and no run_name), a dataset of the schema
// missing, of the wrong shape or type, per-sample datasets of different lengths, codes outside
// their enums.
StoredRun readRunDataset(const std::string& path, const std::string& run_name = "");

}  // namespace wpg::datasets
