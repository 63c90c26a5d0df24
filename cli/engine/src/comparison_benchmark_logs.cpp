// The OMPL benchmark logs of a comparison study (comparison_benchmark_logs.hpp).
#include "wpg/engine/comparison_benchmark_logs.hpp"

#include <filesystem>
#include <system_error>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/ompl_benchmark_log.hpp"
#include "wpg/datasets/storage/output_file.hpp"

namespace fs = std::filesystem;

namespace wpg::engine {

void checkBenchmarkLogOutputs(const std::string& folder, const std::vector<std::string>& worlds) {
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
    throw datasets::InputError("'" + folder + "' is not a directory");
  }
  for (const std::string& world : worlds) {
    datasets::checkOutputPath((fs::path(folder) / (world + ".log")).string(),
                              datasets::OutputKind::kBenchmarkLog);
  }
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
