// The OMPL benchmark logs of a comparison study (comparison_benchmark_logs.hpp).
#include "wpg/engine/comparison_benchmark_logs.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <unistd.h>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/ompl_benchmark_log.hpp"
#include "wpg/datasets/storage/output_file.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {

namespace {

[[noreturn]] void cannotCreate(const std::string& folder, const std::string& why) {
  throw datasets::InputError("cannot create '" + folder + "': " + why);
}

// The folder exists, or can be made, and files can be made in it: tried now, so that a study
// never runs to its end to find that its logs cannot be written. Folders made to try are removed
// again (the logs make them when they are written).
void checkFolderCanHoldFiles(const std::string& folder) {
  std::error_code ec;
  fs::path existing = fs::path(folder);
  while (!existing.empty() && !fs::exists(existing, ec)) existing = existing.parent_path();
  if (existing.empty()) existing = ".";
  if (!fs::is_directory(existing, ec)) cannotCreate(folder, "'" + existing.string() + "' is not a folder");
  if (::access(existing.c_str(), W_OK | X_OK) != 0) cannotCreate(folder, std::strerror(errno));
  if (existing == fs::path(folder)) return;
  const bool made = fs::create_directories(folder, ec);
  if (ec || !made) cannotCreate(folder, ec ? ec.message() : "it is made meanwhile");
  for (fs::path made_folder = folder; !made_folder.empty() && made_folder != existing;
       made_folder = made_folder.parent_path()) {
    fs::remove(made_folder, ec);
  }
}

}  // namespace

void checkBenchmarkLogOutputs(const std::string& folder, const std::vector<std::string>& worlds) {
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
    throw datasets::InputError("'" + folder + "' is not a directory");
  }
  checkFolderCanHoldFiles(folder);
  for (const std::string& world : worlds) {
    datasets::checkOutputPath((fs::path(folder) / (world + ".log")).string(),
                              datasets::OutputKind::kBenchmarkLog);
  }
  datasets::checkOutputPath(benchmarkDatabasePath(folder), datasets::OutputKind::kSqlite);
}

std::string benchmarkDatabasePath(const std::string& folder) {
  return (fs::path(folder) / "benchmark.db").string();
}

std::vector<std::string> writeComparisonBenchmarkLogs(const std::string& study_file,
                                                      const std::string& folder, double seconds) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw datasets::InputError("cannot create '" + folder + "': " + ec.message());
  return datasets::writeBenchmarkLogs(datasets::comparisonBenchmarkExperiments(study_file, seconds),
                                      folder);
}

}  // namespace wpg::engine
