#pragma once
// The group mpc/plan/ of a run dataset (datasets/SCHEMA.md): what every NMPC iteration
// predicted (libwpg's nmpc_plan.hpp), when the walk recorded it.
#include "hdf5_image.hpp"
#include "wpg/walk_trajectory.hpp"

namespace wpg::datasets::detail {

// Adds plan/ to `mpc` when trajectory.plans holds one row per NMPC iteration; nothing when
// the plans were not recorded.
void writePlans(GroupImage& mpc, const WalkTrajectory& trajectory);

}  // namespace wpg::datasets::detail
