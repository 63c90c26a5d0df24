#pragma once
// The group /runs/<name> of the run schema (datasets/SCHEMA.md), written into an open file:
// writeRunDataset writes one into a file of its own, the batch writer (batch_dataset.cpp) one
// per finished run of a study into the batch file.
#include <string>

#include <H5Cpp.h>

#include "wpg/datasets/storage/dataset_checks.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"

namespace wpg::datasets::detail {

// The checks of writeRunDataset on its inputs (std::invalid_argument, see there).
void checkRunInputs(const Scenario& scenario, const wpg::WalkResult& result,
                    const FootstepClearances* clearances, const MultibodyRecord* multibody);

// Creates runs/<group_name> with everything of the run schema; the caller holds hdf5Mutex().
// `checks`: computeDatasetChecks of these inputs when the caller has them (the engine computed
// them for its run result), else null: computed here.
H5::Group writeRunGroup(H5::Group& runs, const std::string& group_name, const Scenario& scenario,
                        const wpg::WalkResult& result, const FootstepClearances* clearances,
                        const MultibodyRecord* multibody,
                        const GoalOutcome* goal = nullptr,
                        const DatasetChecks* checks = nullptr);

}  // namespace wpg::datasets::detail
