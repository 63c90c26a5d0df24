// The OMPL benchmark logs of `wpg compare` (compare_ompl_log.hpp).
#include "compare_ompl_log.hpp"

#include <filesystem>
#include <system_error>

#include "cli_common.hpp"
#include "wpg/datasets/input_error.hpp"
#include "wpg/datasets/ompl_benchmark_log.hpp"
#include "wpg/datasets/output_file.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {

void checkOmplLogOutputs(const std::string& folder, const std::vector<std::string>& worlds) {
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
    throw UsageError("--ompl-log: '" + folder + "' is not a directory");
  }
  try {
    for (const std::string& world : worlds) {
      datasets::checkOutputPath((fs::path(folder) / (world + ".log")).string(),
                                datasets::OutputKind::kBenchmarkLog);
    }
  } catch (const datasets::InputError& e) {
    throw UsageError(std::string("--ompl-log: ") + e.what());
  }
}

std::vector<std::string> writeOmplLogs(const std::string& study_file, const std::string& folder,
                                       double seconds) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw UsageError("--ompl-log: cannot create '" + folder + "': " + ec.message());
  return datasets::writeBenchmarkLogs(datasets::comparisonBenchmarkExperiments(study_file, seconds),
                                      folder);
}

}  // namespace wpg::cli
