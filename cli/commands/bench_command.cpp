// `wpg bench [SCENARIO...]`: the paper's Sec. V-C table. For each scenario: run the online loop
// of Fig. 3 (WPG + dynamic filter + IK, the engine's control_chain_benchmark.hpp) and print the wall time of one
// 5 ms control tick that contains an NMPC iteration, as the paper counts it: average, standard
// deviation, minimum, maximum, beside the paper's numbers; the stages of those ticks; the same
// over every tick; this machine's CPU and OS beside the paper's (analysis/chain_timing.hpp
// computes the numbers). Nothing is written but the optional JSON file. A speed claim is made
// with the Google Benchmark binaries (tests/benchmarks/), not with this table.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <sys/utsname.h>
#include <unistd.h>

#include "command_options.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "json_text.hpp"
#include "summary_printing.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/engine/control_chain_benchmark.hpp"
#include "wpg/engine/robot_models.hpp"
#include "wpg/engine/run_input_checks.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

// Labels and JSON keys of the chain's stages, in the order of analysis::ChainStage.
constexpr const char* kStageNames[analysis::kChainStageCount] = {"WPG", "IK", "multibody ZMP",
                                                                 "filter"};
constexpr const char* kStageKeys[analysis::kChainStageCount] = {"wpg", "ik", "multibody_zmp",
                                                                "filter"};

// One column of the table (the engine measures it, analysis/ computes the numbers).
using BenchRow = engine::ControlChainTiming;

// The paper's Sec. V-C table (HRP-2's CPU board, the complete control architecture of Fig. 3,
// ticks that contain an NMPC iteration only): experiments A and B.
struct PaperColumn {
  const char* name;
  double average, std_dev, min, max;  // [ms]
};
constexpr PaperColumn kPaper[2] = {{"paper A", 3.95, 0.14, 3.34, 4.34},
                                   {"paper B", 4.00, 0.18, 3.085, 5.19}};

// The first "model name" of /proc/cpuinfo; "unknown CPU" when there is none.
std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  }
  return "unknown CPU";
}

// PRETTY_NAME of /etc/os-release and the kernel release.
std::string operatingSystem() {
  std::string name = "unknown OS";
  std::ifstream release("/etc/os-release");
  std::string line;
  while (std::getline(release, line)) {
    if (line.rfind("PRETTY_NAME=", 0) == 0) {
      name = line.substr(12);
      name.erase(std::remove(name.begin(), name.end(), '"'), name.end());
    }
  }
  struct utsname system {};
  if (::uname(&system) == 0) name += std::string(", ") + system.sysname + " " + system.release;
  return name;
}

void printTable(std::ostream& out, const std::vector<BenchRow>& rows) {
  std::size_t width = 12;
  for (const BenchRow& row : rows) width = std::max(width, row.name.size() + 2);
  const int label = 36;
  const int paper_width = 10;
  // A row of the table; `paper` (may be null) gives the paper's two columns.
  const auto line = [&](const std::string& name, auto value, const double* paper = nullptr) {
    out << std::left << std::setw(label) << name << std::right;
    for (const BenchRow& row : rows) out << std::setw(static_cast<int>(width)) << value(row);
    if (paper) {
      for (int column = 0; column < 2; ++column) out << std::setw(paper_width) << fixed(paper[column], 3);
    }
    out << '\n';
  };
  out << "One 5 ms control tick that contains an NMPC iteration (paper Sec. V-C): the online loop "
         "of Fig. 3, WPG + dynamic filter (walking IK and multibody ZMP over the sampling period "
         "and its preview of one step, Sec. V-A) + walking IK of the corrected CoM\n";
  out << std::left << std::setw(label) << "[ms]" << std::right;
  for (const BenchRow& row : rows) out << std::setw(static_cast<int>(width)) << row.name;
  out << std::setw(paper_width) << kPaper[0].name << std::setw(paper_width) << kPaper[1].name << '\n';
  const double average[2] = {kPaper[0].average, kPaper[1].average};
  const double std_dev[2] = {kPaper[0].std_dev, kPaper[1].std_dev};
  const double minimum[2] = {kPaper[0].min, kPaper[1].min};
  const double maximum[2] = {kPaper[0].max, kPaper[1].max};
  line("Average", [](const BenchRow& r) { return fixed(1e3 * r.ticks.nmpc_ticks.mean, 3); }, average);
  line("Standard deviation",
       [](const BenchRow& r) { return fixed(1e3 * r.ticks.nmpc_ticks.std_dev, 3); }, std_dev);
  line("Minimum", [](const BenchRow& r) { return fixed(1e3 * r.ticks.nmpc_ticks.min, 3); }, minimum);
  line("Maximum", [](const BenchRow& r) { return fixed(1e3 * r.ticks.nmpc_ticks.max, 3); }, maximum);
  line("NMPC ticks over the control period",
       [](const BenchRow& r) { return std::to_string(r.ticks_over_period); });
  out << "Stages in the NMPC ticks, mean [ms]\n";
  for (std::size_t stage = 0; stage < analysis::kChainStageCount; ++stage) {
    line(std::string("  ") + kStageNames[stage], [stage](const BenchRow& r) {
      return fixed(1e3 * r.ticks.stage_nmpc_ticks[stage].mean, 3);
    });
  }
  out << "Every tick [ms]\n";
  line("  Average", [](const BenchRow& r) { return fixed(1e3 * r.ticks.all_ticks.mean, 3); });
  line("  Standard deviation",
       [](const BenchRow& r) { return fixed(1e3 * r.ticks.all_ticks.std_dev, 3); });
  line("  Minimum", [](const BenchRow& r) { return fixed(1e3 * r.ticks.all_ticks.min, 3); });
  line("  Maximum", [](const BenchRow& r) { return fixed(1e3 * r.ticks.all_ticks.max, 3); });
  line("NMPC ticks", [](const BenchRow& r) { return std::to_string(r.ticks.nmpc_ticks.count); });
  line("Ticks", [](const BenchRow& r) { return std::to_string(r.ticks.all_ticks.count); });
  line("Walk duration [s]", [](const BenchRow& r) { return fixed(r.walk_duration, 2); });
  line("Loop wall time [s]", [](const BenchRow& r) { return fixed(r.loop_wall_time, 3); });
  line("Loop real-time factor", [](const BenchRow& r) { return fixed(r.real_time_factor, 1) + "x"; });
  line("ZMP error RMS [mm] before -> after", [](const BenchRow& r) {
    return fixed(1e3 * r.zmp.before.rms, 1) + " -> " + fixed(1e3 * r.zmp.after.rms, 1);
  });
  line("ZMP error max [mm] before -> after", [](const BenchRow& r) {
    return fixed(1e3 * r.zmp.before.max, 1) + " -> " + fixed(1e3 * r.zmp.after.max, 1);
  });
  out << "(stages: " << kStageNames[0] << " = the generator's step, with the NMPC in these ticks, "
         "the interpolation and the preview of the plan; IK = the walking IK over the filter's "
         "preview window and of the corrected CoM; multibody ZMP = the momentum rate of the window's "
         "kinematics (Simbody's inverse dynamics within 1e-9 m); filter = the error, one preview-control step, the WPG re-initialisation. "
         "Real-time factor: walk duration / wall time of the whole loop, including the "
         "validation replay after it, Simbody's inverse dynamics)\n";
  out << "machine   this run: " << cpuModel() << ", " << operatingSystem()
      << ", one thread\n";
  out << "          paper: Intel Core2 Duo E7500, 2.8 GHz, 3 MB cache, one core, Ubuntu 10.04 LTS "
         "(HRP-2's CPU board)\n";
  out << "differs   the paper times the complete control architecture on the robot (its one "
         "tick over 5 ms came from the stabilizer); here no stabilizer nor robot, the multibody "
         "ZMP from the momentum rate and an analytic leg IK, the filter's window replayed whole "
         "at each NMPC tick, "
         "one process on a machine other jobs may share\n";
}

std::string jsonNumber(double value) { return cli::jsonNumber(value, 9); }

void writeJson(const std::string& path, const std::vector<BenchRow>& rows) {
  std::ostringstream json;
  json << "{\n  \"description\": \"one 5 ms control tick of the online loop (paper Sec. V-C), "
          "seconds\",\n"
       << "  \"paper\": [";
  for (int column = 0; column < 2; ++column) {
    const PaperColumn& p = kPaper[column];
    json << (column ? ", " : "") << "{\"name\": " << jsonString(p.name)
         << ", \"average\": " << jsonNumber(1e-3 * p.average)
         << ", \"std\": " << jsonNumber(1e-3 * p.std_dev) << ", \"min\": " << jsonNumber(1e-3 * p.min)
         << ", \"max\": " << jsonNumber(1e-3 * p.max) << "}";
  }
  json << "],\n  \"cpu\": " << jsonString(cpuModel()) << ", \"os\": " << jsonString(operatingSystem())
       << ",\n  \"scenarios\": [\n";
  const auto statistics = [](const analysis::SampleStatistics& s) {
    return "{\"count\": " + std::to_string(s.count) + ", \"average\": " + jsonNumber(s.mean) +
           ", \"std\": " + jsonNumber(s.std_dev) + ", \"min\": " + jsonNumber(s.min) +
           ", \"max\": " + jsonNumber(s.max) + "}";
  };
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BenchRow& r = rows[i];
    json << "    {\"name\": " << jsonString(r.name)
         << ", \"nmpc_tick_time\": " << statistics(r.ticks.nmpc_ticks)
         << ", \"tick_time\": " << statistics(r.ticks.all_ticks) << ", \"nmpc_tick_stage_mean\": {";
    for (std::size_t stage = 0; stage < analysis::kChainStageCount; ++stage) {
      json << (stage ? ", " : "") << "\"" << kStageKeys[stage]
           << "\": " << jsonNumber(r.ticks.stage_nmpc_ticks[stage].mean);
    }
    json << "}, \"nmpc_ticks_over_period\": " << r.ticks_over_period
         << ", \"walk_duration\": " << jsonNumber(r.walk_duration)
         << ", \"loop_wall_time\": " << jsonNumber(r.loop_wall_time)
         << ", \"real_time_factor\": " << jsonNumber(r.real_time_factor)
         << ", \"zmp_error\": {\"rms_before\": " << jsonNumber(r.zmp.before.rms)
         << ", \"rms_after\": " << jsonNumber(r.zmp.after.rms)
         << ", \"max_before\": " << jsonNumber(r.zmp.before.max)
         << ", \"max_after\": " << jsonNumber(r.zmp.after.max) << "}"
         << ", \"ik_failures\": " << r.ik_failures
         << ", \"walk_success\": " << (r.walk_success ? "true" : "false") << "}"
         << (i + 1 < rows.size() ? "," : "") << "\n";
  }
  json << "  ]\n}\n";
  // Atomic like the datasets: an exclusive temporary file in the same folder, then a rename.
  datasets::TemporaryOutput temporary(path);
  {
    std::ofstream stream(temporary.path());
    stream << json.str();
    if (!stream.flush()) throw std::runtime_error("cannot write " + path);
  }
  temporary.commit();
}

}  // namespace

int benchCommand(const BenchOptions& options) {
  if (options.scenarios.empty()) throw UsageError("no scenario to measure");
  // Every scenario, robot model and output checked before the first measurement.
  std::vector<datasets::Scenario> scenarios;
  for (const std::string& argument : options.scenarios) {
    const std::string path = resolveScenarioPath(argument);
    try {
      scenarios.push_back(datasets::loadScenario(path, {"filter=true"}, robotsDirectory()));
    } catch (const datasets::InputError& e) {
      throw UsageError(e.what());
    }
    engine::checkFilterSettings(scenarios.back(), path);
    printWarnings(scenarios.back().warnings);
  }
  if (!options.json.empty()) {
    std::vector<std::string> inputs;
    for (const std::string& argument : options.scenarios) inputs.push_back(resolveScenarioPath(argument));
    try {
      datasets::checkOutputPath(options.json, datasets::OutputKind::kJson, inputs);
    } catch (const datasets::InputError& e) {
      throw UsageError(std::string("--json ") + e.what());
    }
  }
  std::vector<robots::RobotModel> models;
  std::vector<std::string> robot_names;
  for (const datasets::Scenario& scenario : scenarios) {
    if (std::find(robot_names.begin(), robot_names.end(), scenario.robot) == robot_names.end()) {
      models.push_back(engine::loadRobotModel(robotsDirectory(), scenario.robot, scenario.multibody));
      robot_names.push_back(scenario.robot);
    }
  }

  std::vector<BenchRow> rows;
  bool every_walk_succeeded = true;
  for (const datasets::Scenario& scenario : scenarios) {
    const std::size_t robot = static_cast<std::size_t>(
        std::find(robot_names.begin(), robot_names.end(), scenario.robot) - robot_names.begin());
    rows.push_back(engine::measureControlChain(scenario, models[robot]));
    every_walk_succeeded = every_walk_succeeded && rows.back().walk_success;
  }
  printTable(std::cout, rows);
  if (!options.json.empty()) {
    writeJson(options.json, rows);
    std::cout << "json      " << options.json << '\n';
  }
  if (!every_walk_succeeded) {
    std::cout.flush();
    printError("a walk failed (an NMPC iteration fell back or hit its limit); its timings are "
               "above");
    return kExitRunFailed;
  }
  return kExitSuccess;
}

}  // namespace wpg::cli
