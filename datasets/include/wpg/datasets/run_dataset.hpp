#pragma once
// One run, written to HDF5 (layout: datasets/SCHEMA.md, a contract with every reader).
#include <mutex>
#include <string>

#include "wpg/datasets/scenario.hpp"
#include "wpg/walk_generator.hpp"

namespace wpg::datasets {

// The HDF5 schema version written in the root attribute `schema_version`.
constexpr int kRunDatasetSchemaVersion = 1;

// Writes `result` of `scenario` to `path` (group /runs/<scenario.name>), atomically: the file
// is written as `<path>.tmp-<pid>` in the same directory, then renamed over `path`; on any
// error the temporary file is removed and `path` is left as it was. Creates the parent
// directory when missing.
//
// Throws std::invalid_argument when the trajectory's per-sample arrays differ in length or the
// scenario name cannot be an HDF5 group name, std::runtime_error on I/O errors (message names
// the path).
void writeRunDataset(const std::string& path, const Scenario& scenario,
                     const wpg::WalkResult& result);

// Debian's HDF5 is built without thread safety: every use of the HDF5 library in this process
// (writeRunDataset takes it itself) must hold this lock, e.g. when batch workers write files.
std::mutex& hdf5Mutex();

}  // namespace wpg::datasets
