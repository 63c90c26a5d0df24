#pragma once
// Who wrote a file, where and when: written into every file wpg writes (HDF5 root attributes
// wpg_version, wpg_commit, created_on, created_at; the header of the pages of `wpg view`; the
// OMPL benchmark logs of `wpg compare --ompl-log`), as OMPL's benchmark logs name their
// version, host and date. They are not part of the data: `wpg diff` and the comparisons of the
// tests leave them out (isProvenanceAttribute, dataset_diff.hpp).
#include <string>

namespace wpg::datasets {

struct Provenance {
  std::string version;  // the CMake project version (WPG_VERSION_STRING)
  std::string commit;   // the git commit the build was configured from, or "unknown"
  std::string machine;  // the host name, or "unknown"
  std::string date;     // now, UTC, ISO 8601: "2025-11-25T16:03:00Z"
};

Provenance currentProvenance();

// The commit alone (cmake/wpg_git_commit.cmake).
const char* buildCommit();

}  // namespace wpg::datasets
