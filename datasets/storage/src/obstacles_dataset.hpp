#pragma once
// The obstacles group of a run dataset (datasets/SCHEMA.md, "obstacles"): the scenario's
// obstacles as a table, so that plots and analyses need nothing but the file.
#include <vector>

#include "hdf5_image.hpp"

#include "wpg/obstacles.hpp"

namespace wpg::datasets::detail {

// /runs/<name>/obstacles: one row per obstacle, in the scenario's order.
void writeObstacles(GroupImage& run, const std::vector<Obstacle>& obstacles);

}  // namespace wpg::datasets::detail
