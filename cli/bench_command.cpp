// `wpg bench [SCENARIO...]`: the timing profile of the paper's Sec. V-C table. For each
// scenario: generate the walk, replay it with the dynamic filter (pipeline_stages.hpp), and
// print the wall time of the whole control chain per NMPC iteration (NMPC + IK + multibody ZMP
// + filter): average, standard deviation, minimum, maximum; the stage medians; the real-time
// factor of the replay + filter (computed by analysis/chain_timing.hpp). Nothing is written but
// the optional JSON file.
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

#include <unistd.h>

#include "cli_common.hpp"
#include "json_text.hpp"
#include "pipeline_stages.hpp"
#include "summary_printing.hpp"
#include "wpg/analysis/chain_timing.hpp"
#include "wpg/analysis/zmp_error.hpp"
#include "wpg/datasets/input_error.hpp"
#include "wpg/datasets/scenario.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

// Labels and JSON keys of the chain's stages, in the order of analysis::ChainStage.
constexpr const char* kStageNames[analysis::kChainStageCount] = {"NMPC", "IK", "multibody ZMP",
                                                                 "filter"};
constexpr const char* kStageKeys[analysis::kChainStageCount] = {"nmpc", "ik", "multibody_zmp",
                                                                "filter"};

// One column of the table: the numbers come from analysis/ (chain_timing.hpp, zmp_error.hpp).
struct BenchRow {
  std::string name;
  analysis::ChainTiming timing;         // [s] per NMPC iteration
  double walk_duration = 0.0;           // [s]
  double replay_wall_time = 0.0;        // [s]
  double real_time_factor = 0.0;
  analysis::ZmpErrorComparison zmp;     // [m]
  int ik_failures = 0;
  bool walk_success = true;
};

BenchRow measure(const datasets::Scenario& scenario, const robots::RobotModel& model) {
  const WalkResult walk = generateWalk(scenario.walking, scenario.request);
  const ReplayOutcome replay = replayScenarioWalk(model, scenario, walk.trajectory, true);
  BenchRow row;
  row.name = scenario.name;
  row.walk_success = walk.success;
  row.timing = analysis::chainTiming(replay.validation);
  row.walk_duration = replay.walk_duration;
  row.replay_wall_time = replay.wall_time;
  row.real_time_factor = replay.realTimeFactor();
  row.zmp = analysis::compareZmpError(replay.validation);
  row.ik_failures = replay.validation.ik_failures;
  return row;
}

void printTable(std::ostream& out, const std::vector<BenchRow>& rows) {
  std::size_t width = 12;
  for (const BenchRow& row : rows) width = std::max(width, row.name.size() + 2);
  const int label = 34;
  const auto line = [&](const std::string& name, auto value) {
    out << std::left << std::setw(label) << name << std::right;
    for (const BenchRow& row : rows) out << std::setw(static_cast<int>(width)) << value(row);
    out << '\n';
  };
  out << "Control chain per NMPC iteration (paper Sec. V-C): NMPC + IK + multibody ZMP + dynamic "
         "filter\n";
  line("[ms]", [](const BenchRow& r) { return r.name; });
  line("Average", [](const BenchRow& r) { return fixed(1e3 * r.timing.per_iteration.mean, 3); });
  line("Standard deviation",
       [](const BenchRow& r) { return fixed(1e3 * r.timing.per_iteration.std_dev, 3); });
  line("Minimum", [](const BenchRow& r) { return fixed(1e3 * r.timing.per_iteration.min, 3); });
  line("Maximum", [](const BenchRow& r) { return fixed(1e3 * r.timing.per_iteration.max, 3); });
  out << "Stage medians [ms]\n";
  for (std::size_t stage = 0; stage < analysis::kChainStageCount; ++stage) {
    line(std::string("  ") + kStageNames[stage],
         [stage](const BenchRow& r) { return fixed(1e3 * r.timing.stage_median[stage], 3); });
  }
  line("NMPC iterations",
       [](const BenchRow& r) { return std::to_string(r.timing.per_iteration.count); });
  line("Walk duration [s]", [](const BenchRow& r) { return fixed(r.walk_duration, 2); });
  line("Replay + filter wall time [s]", [](const BenchRow& r) { return fixed(r.replay_wall_time, 3); });
  line("Replay + filter real-time factor", [](const BenchRow& r) {
    return fixed(r.real_time_factor, 0) + "x";
  });
  line("ZMP error RMS [mm] before -> after", [](const BenchRow& r) {
    return fixed(1e3 * r.zmp.before.rms, 1) + " -> " + fixed(1e3 * r.zmp.after.rms, 1);
  });
  line("ZMP error max [mm] before -> after", [](const BenchRow& r) {
    return fixed(1e3 * r.zmp.before.max, 1) + " -> " + fixed(1e3 * r.zmp.after.max, 1);
  });
  out << "(chain: NMPC = the iteration's wall time; IK per sample summed over the iteration; "
         "multibody ZMP and filter over the whole walk, spread evenly over the iterations; "
         "real-time factor: walk duration / wall time of the whole replay, including the "
         "validation replay after the filter)\n";
}

std::string jsonNumber(double value) { return cli::jsonNumber(value, 9); }

void writeJson(const std::string& path, const std::vector<BenchRow>& rows) {
  std::ostringstream json;
  json << "{\n  \"description\": \"control chain per NMPC iteration (paper Sec. V-C), seconds\",\n"
       << "  \"scenarios\": [\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BenchRow& r = rows[i];
    const analysis::SampleStatistics& chain = r.timing.per_iteration;
    json << "    {\"name\": " << jsonString(r.name) << ", \"nmpc_iterations\": " << chain.count
         << ", \"chain_time\": {\"average\": " << jsonNumber(chain.mean)
         << ", \"std\": " << jsonNumber(chain.std_dev) << ", \"min\": " << jsonNumber(chain.min)
         << ", \"max\": " << jsonNumber(chain.max) << "}, \"stage_median\": {";
    for (std::size_t stage = 0; stage < analysis::kChainStageCount; ++stage) {
      json << (stage ? ", " : "") << "\"" << kStageKeys[stage]
           << "\": " << jsonNumber(r.timing.stage_median[stage]);
    }
    json << "}, \"walk_duration\": " << jsonNumber(r.walk_duration)
         << ", \"replay_wall_time\": " << jsonNumber(r.replay_wall_time)
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
  // Atomic like the datasets: a temporary file in the same folder, then a rename.
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream stream(temporary);
    stream << json.str();
    if (!stream.flush()) {
      std::remove(temporary.c_str());
      throw std::runtime_error("cannot write " + path);
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write " + path);
  }
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
    checkFilterSettings(scenarios.back(), path);
  }
  std::error_code ec;
  if (!options.json.empty() && fs::is_directory(options.json, ec)) {
    throw UsageError("--json '" + options.json + "' is a directory");
  }
  std::vector<robots::RobotModel> models;
  std::vector<std::string> robot_names;
  for (const datasets::Scenario& scenario : scenarios) {
    if (std::find(robot_names.begin(), robot_names.end(), scenario.robot) == robot_names.end()) {
      models.push_back(loadRobotModel(scenario.robot));
      robot_names.push_back(scenario.robot);
    }
  }

  std::vector<BenchRow> rows;
  bool every_walk_succeeded = true;
  for (const datasets::Scenario& scenario : scenarios) {
    const std::size_t robot = static_cast<std::size_t>(
        std::find(robot_names.begin(), robot_names.end(), scenario.robot) - robot_names.begin());
    rows.push_back(measure(scenario, models[robot]));
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
