#pragma once
// The group /runs/<name> of the run schema (datasets/SCHEMA.md), written into an open file:
// writeRunDataset writes one into a file of its own, the batch writer (batch_dataset.cpp) one
// per finished run of a study into the batch file.
#include <future>
#include <memory>
#include <string>

#include <H5Cpp.h>

#include "hdf5_writing.hpp"
#include "wpg/datasets/storage/dataset_checks.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"

namespace wpg::datasets::detail {

// The checks of writeRunDataset on its inputs (std::invalid_argument, see there).
void checkRunInputs(const Scenario& scenario, const wpg::WalkResult& result,
                    const FootstepClearances* clearances, const MultibodyRecord* multibody);

// The multibody fields' chunks being recorded on another thread (writeRunDataset), taken where
// the writer reaches them; an invalid future, or one that failed: compressed by the writer.
using PendingRecording = std::future<std::unique_ptr<ChunkRecording>>;

// Creates runs/<group_name> with everything of the run schema; the caller holds hdf5Mutex().
// `checks`: computeDatasetChecks of these inputs when the caller has them (the engine computed
// them for its run result), else null: computed here.
H5::Group writeRunGroup(H5::Group& runs, const std::string& group_name, const Scenario& scenario,
                        const wpg::WalkResult& result, const FootstepClearances* clearances,
                        const MultibodyRecord* multibody,
                        const GoalOutcome* goal = nullptr,
                        const DatasetChecks* checks = nullptr,
                        PendingRecording* multibody_chunks = nullptr);

}  // namespace wpg::datasets::detail
