// What `wpg batch` and `wpg compare` print while a study runs (study_progress.hpp).
#include "study_progress.hpp"

#include <cstdio>
#include <iostream>

#include "error_messages.hpp"

namespace wpg::cli {

void StudyProgress::accepted(const std::string& name, const std::vector<std::string>& warnings) {
  study_ = name;
  printWarnings(warnings);
}

void StudyProgress::movedDamagedFile(const std::string& file, const std::string& aside,
                                     bool shard) {
  std::cerr << study_ << ": " << file << " cannot be read by HDF5 ("
            << (shard ? "a rank killed inside a write); moved to " + aside + ", its runs are run again"
                      : "killed inside a write); moved to " + aside + ", starting again")
            << "\n";
}

void StudyProgress::resuming(std::size_t already, std::size_t total, const std::string& where) {
  std::cerr << study_ << ": resuming, " << already << " of " << total << " runs already in "
            << where << "\n";
}

void StudyProgress::started(std::size_t runs_to_do) {
  progress_.emplace(study_, runs_to_do, stderr);
}

void StudyProgress::runFinished(bool failed) {
  if (progress_) progress_->runFinished(failed);
}

void StudyProgress::finished() {
  if (progress_) progress_->finish();
}

void StudyProgress::ranksFinished(const engine::RankStatistics& s) {
  char line[256];
  std::snprintf(line, sizeof line,
                "%s: %d ranks x %d workers; rank 0 answered %zu requests of other ranks, %.1f us "
                "each (max %.1f us); index of %zu runs written in %.3f s\n",
                study_.c_str(), s.ranks, s.workers_per_rank, s.remote_handouts,
                s.remote_handouts ? 1e6 * s.service_seconds / static_cast<double>(s.remote_handouts) : 0.0,
                1e6 * s.service_max_seconds, s.runs, s.index_seconds);
  std::cerr << line;
}

void StudyProgress::rankFailed(int rank, const std::string& what) {
  printError("rank " + std::to_string(rank) + ": " + what);
}

}  // namespace wpg::cli
