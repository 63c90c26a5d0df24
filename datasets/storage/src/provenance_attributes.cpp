// Provenance root attributes (provenance_attributes.hpp).
#include "provenance_attributes.hpp"

#include "hdf5_writing.hpp"
#include "wpg/datasets/storage/provenance.hpp"

namespace wpg::datasets::detail {

void writeProvenanceAttributes(ObjectImage& file) {
  const Provenance provenance = currentProvenance();
  writeStringAttribute(file, "wpg_commit", provenance.commit);
  writeStringAttribute(file, "created_on", provenance.machine);
  writeStringAttribute(file, "created_at", provenance.date);
}

}  // namespace wpg::datasets::detail
