#pragma once
// The provenance (wpg/datasets/storage/provenance.hpp) as root attributes of an HDF5 file: wpg_commit,
// created_on (the host) and created_at (UTC, ISO 8601), beside the wpg_version each writer
// already writes (datasets/SCHEMA.md).
#include "hdf5_image.hpp"

namespace wpg::datasets::detail {

void writeProvenanceAttributes(ObjectImage& file);

}  // namespace wpg::datasets::detail
