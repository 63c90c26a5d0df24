#pragma once
// The group /runs/<name> of the run schema (datasets/SCHEMA.md), built as an image
// (hdf5_image.hpp) without any HDF5 call, on any thread: writeRunDataset commits one into a
// file of its own, the batch writer (batch_dataset.cpp) one per finished run of a study into
// the batch file.
#include <memory>
#include <string>

#include "hdf5_image.hpp"
#include "wpg/datasets/storage/dataset_checks.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/study_design/run_fields.hpp"

namespace wpg::datasets::detail {

// The checks of writeRunDataset on its inputs (std::invalid_argument, see there).
void checkRunInputs(const Scenario& scenario, const wpg::WalkResult& result,
                    const FootstepClearances* clearances, const MultibodyRecord* multibody);

// The walk's part of a run group: the trajectory, the NMPC log and the obstacles, the first
// entries buildRunGroup makes.
std::shared_ptr<const GroupImage> buildWalkPart(const Scenario& scenario,
                                                const wpg::WalkResult& result,
                                                RunFields fields = RunFields::all());
// The multibody fields (writeMultibody) as a part of their own.
std::shared_ptr<const GroupImage> buildMultibodyPart(const Scenario& scenario,
                                                     const MultibodyRecord& multibody);

// What buildRunGroup may be given ready.
struct RunGroupParts {
  // computeDatasetChecks of the inputs (the engine computed them for its run result), or null:
  // computed here
  const DatasetChecks* checks = nullptr;
  std::shared_ptr<const GroupImage> walk;       // buildWalkPart of the inputs, or null
  std::shared_ptr<const GroupImage> multibody;  // buildMultibodyPart of the inputs, or null
};

// Adds runs/<group_name> with everything of the run schema to `runs` (the image of the group
// /runs) and returns it; with `fields`, only those (run_fields.hpp; `parts.walk` must then be
// built with the same fields). The inputs are checked first (checkRunInputs).
GroupImage& buildRunGroup(GroupImage& runs, const std::string& group_name,
                          const Scenario& scenario, const wpg::WalkResult& result,
                          const FootstepClearances* clearances, const MultibodyRecord* multibody,
                          const GoalOutcome* goal, const RunGroupParts& parts = {},
                          RunFields fields = RunFields::all());

void writeMultibody(GroupImage& run, const Scenario& scenario, const MultibodyRecord& multibody);

}  // namespace wpg::datasets::detail
