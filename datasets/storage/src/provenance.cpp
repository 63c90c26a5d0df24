// The version, commit, host and date written into every output (provenance.hpp). The commit is
// a compile definition of this file only (datasets/CMakeLists.txt): a new commit recompiles
// one file, not the library.
#include "wpg/datasets/storage/provenance.hpp"
#include "wpg/version.hpp"

#include <unistd.h>

#include <climits>
#include <ctime>

#ifndef WPG_GIT_COMMIT
#define WPG_GIT_COMMIT "unknown"
#endif

namespace wpg::datasets {

const char* buildCommit() { return WPG_GIT_COMMIT; }

Provenance currentProvenance() {
  Provenance provenance;
  provenance.version = WPG_VERSION_STRING;
  provenance.commit = buildCommit();
  char host[HOST_NAME_MAX + 1] = {};
  provenance.machine = ::gethostname(host, sizeof host - 1) == 0 && host[0] ? host : "unknown";
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  char date[32] = "unknown";
  if (::gmtime_r(&now, &utc)) std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
  provenance.date = date;
  return provenance;
}

}  // namespace wpg::datasets
