#pragma once
// What `wpg batch` and `wpg compare` print while a study runs (the engine's StudyObserver): the
// runs' scenario warnings once the study is accepted, the progress on stderr
// (batch_progress.hpp), and one line for a resume, a damaged file moved aside, the MPI ranks'
// statistics or a rank's error.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "batch_progress.hpp"
#include "wpg/engine/study_executor.hpp"

namespace wpg::cli {

class StudyProgress : public engine::StudyObserver {
 public:
  void accepted(const std::string& name, const std::vector<std::string>& warnings) override;
  void movedDamagedFile(const std::string& file, const std::string& aside, bool shard) override;
  void resuming(std::size_t already, std::size_t total, const std::string& where) override;
  void started(std::size_t runs_to_do) override;
  void runFinished(bool failed) override;
  void finished() override;
  void ranksFinished(const engine::RankStatistics& statistics) override;
  void rankFailed(int rank, const std::string& what) override;

  std::size_t failures() const { return progress_ ? progress_->failures() : 0; }

 private:
  std::string study_;
  std::optional<BatchProgress> progress_;
};

}  // namespace wpg::cli
