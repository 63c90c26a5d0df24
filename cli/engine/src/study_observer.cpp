// What a study's caller hears by default: nothing (study_executor.hpp, StudyObserver).
#include "wpg/engine/study_executor.hpp"

namespace wpg::engine {

void StudyObserver::accepted(const std::string&, const std::vector<std::string>&) {}
void StudyObserver::movedDamagedFile(const std::string&, const std::string&, bool) {}
void StudyObserver::resuming(std::size_t, std::size_t, const std::string&) {}
void StudyObserver::started(std::size_t) {}
void StudyObserver::runFinished(bool) {}
void StudyObserver::finished() {}
void StudyObserver::ranksFinished(const RankStatistics&) {}
void StudyObserver::rankFailed(int, const std::string&) {}

}  // namespace wpg::engine
