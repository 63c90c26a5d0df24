// OMPL's benchmark log format (ompl_benchmark_log.hpp), written from the grammar of OMPL's
// documentation ("The benchmark logfile format"): a preamble (version, experiment, its
// properties, host, date, the setup and CPU texts between "<<<|" and "|>>>", seed, limits, run
// count, total time, the status enum, the planner count), then per planner its name, its
// common properties, its run property names and one line per run of "value; " items, closed by
// a line ".".
#include "wpg/datasets/storage/ompl_benchmark_log.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "wpg/datasets/storage/output_file.hpp"

namespace fs = std::filesystem;

namespace wpg::datasets {
namespace {

void checkLine(const std::string& text, const std::string& what) {
  if (text.find('\n') != std::string::npos || text.find('\r') != std::string::npos) {
    throw std::invalid_argument(what + " '" + text + "' holds a line break");
  }
}

}  // namespace

std::string benchmarkNumber(double value) {
  if (std::isnan(value)) return "nan";
  // The grammar knows "inf" and "nan" only: -inf (no such value) is written as "nan".
  if (std::isinf(value)) return value > 0 ? "inf" : "nan";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  for (int digits = 1; digits <= 17; ++digits) {
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.*g", digits, value);
    if (std::strtod(shorter, nullptr) == value) return shorter;
  }
  return text;
}

namespace {

// A multi-line text between the markers, each line ended, the markers never inside it.
void writeMultiline(std::ostream& out, std::string text) {
  out << "<<<|\n";
  if (!text.empty() && text.back() != '\n') text += '\n';
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("|>>>", 0) == 0) line = " " + line;
    out << line << '\n';
  }
  out << "|>>>\n";
}

}  // namespace

const std::vector<std::string>& plannerStatusNames() {
  static const std::vector<std::string> names = {
      "Unknown status", "Invalid start", "Invalid goal", "Unrecognized goal type", "Timeout",
      "Approximate solution", "Exact solution", "Crash", "Abort"};
  return names;
}

void writeBenchmarkLog(std::ostream& out, const BenchmarkExperiment& e) {
  checkLine(e.library + e.version, "version");
  out << e.library << " version " << e.version << '\n';
  std::string name = e.name.empty() ? "NO_NAME" : e.name;
  for (char& c : name) {
    if (c == ' ' || c == '\t') c = '_';
  }
  checkLine(name, "experiment name");
  out << "Experiment " << name << '\n';
  out << e.properties.size() << " experiment properties\n";
  for (const BenchmarkValue& property : e.properties) {
    checkLine(property.first + property.second, "experiment property");
    out << property.first << " = " << property.second << '\n';
  }
  checkLine(e.host + e.date, "host or date");
  out << "Running on " << (e.host.empty() ? "UNKNOWN" : e.host) << '\n';
  out << "Starting at " << e.date << '\n';
  writeMultiline(out, e.setup);
  writeMultiline(out, e.cpu_info);
  out << e.seed << " is the random seed\n";
  out << benchmarkNumber(e.time_limit) << " seconds per run\n";
  out << benchmarkNumber(e.memory_limit) << " MB per run\n";
  out << e.runs_per_planner << " runs per planner\n";
  out << benchmarkNumber(e.total_time) << " seconds spent to collect the data\n";
  out << "1 enum type\nstatus";
  for (const std::string& status : plannerStatusNames()) out << '|' << status;
  out << '\n';
  out << e.planners.size() << " planners\n";
  for (const BenchmarkPlanner& planner : e.planners) {
    checkLine(planner.name, "planner name");
    out << planner.name << '\n';
    out << planner.common.size() << " common properties\n";
    for (const BenchmarkValue& common : planner.common) {
      checkLine(common.first + common.second, "planner property");
      out << common.first << " = " << common.second << '\n';
    }
    out << planner.properties.size() << " properties for each run\n";
    for (const std::string& property : planner.properties) {
      checkLine(property, "run property");
      out << property << '\n';
    }
    out << planner.runs.size() << " runs\n";
    for (const std::vector<std::string>& run : planner.runs) {
      if (run.size() != planner.properties.size()) {
        throw std::invalid_argument("planner " + planner.name + ": a run of " +
                                    std::to_string(run.size()) + " values for " +
                                    std::to_string(planner.properties.size()) + " properties");
      }
      for (const std::string& value : run) {
        checkLine(value, "run value");
        out << value << "; ";
      }
      out << '\n';
    }
    out << ".\n";
  }
}

std::vector<std::string> writeBenchmarkLogs(const std::vector<BenchmarkExperiment>& experiments,
                                            const std::string& folder) {
  std::vector<std::string> paths;
  for (const BenchmarkExperiment& experiment : experiments) {
    std::string file = experiment.name;
    for (char& c : file) {
      const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                         (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
      if (!plain) c = '_';
    }
    const std::string path = (fs::path(folder) / (file + ".log")).string();
    std::ostringstream text;
    writeBenchmarkLog(text, experiment);
    TemporaryOutput temporary(path);
    {
      std::ofstream out(temporary.path(), std::ios::binary | std::ios::trunc);
      out << text.str();
      out.close();
      if (!out) throw std::runtime_error(path + ": cannot write it");
    }
    temporary.commit();
    paths.push_back(path);
  }
  return paths;
}

}  // namespace wpg::datasets
