#pragma once
// A run read back from a file (readRunDataset) against the scenario stored beside it: a file we
// did not write may pair a walk with a scenario that did not generate it (another control
// period, CoM height or duration), and replaying such a walk gives NaN or garbage downstream
// (the dynamic filter integrates at the scenario's period). `wpg replay` and `wpg analyze` check
// it after loading the scenario and before using the walk.
#include <string>

#include "wpg/datasets/storage/run_dataset_reader.hpp"
#include "wpg/datasets/input/scenario.hpp"

namespace wpg::datasets {

// Throws InputError, one line naming `path`, the dataset (and row) and what was expected, when
// the walk of `stored` cannot come from `scenario` as the generator writes it
// (libwpg/src/walk_generator.cpp):
// - its `robot` attribute is the scenario's robot;
// - sample i is at i x walking.control_period, and there are at most
//   round(duration / sampling_period) x round(sampling_period / control_period) + 1 of them;
// - `com` z is walking.com_height (the LIPM's constant height, eq. 3);
// - NMPC iteration j is at j x walking.sampling_period, one for every NMPC instant before the
//   walk's last sample (and the one at it when the robot fell), none after it;
// - the footsteps start with the initial left and right feet at landing time 0, then land in
//   time order within the walk, at most one per NMPC iteration.
void checkStoredRunMatchesScenario(const std::string& path, const StoredRun& stored,
                                   const Scenario& scenario);

}  // namespace wpg::datasets
