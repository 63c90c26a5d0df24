// `wpg bench [SCENARIO...]`: the timing profile of the paper's Sec. V-C table. For each
// scenario: generate the walk, replay it with the dynamic filter, and report the wall time of
// the whole control chain per NMPC iteration (NMPC + IK + multibody ZMP + filter): average,
// standard deviation, minimum, maximum; the stage medians; the real-time factor of the
// replay + filter. Nothing is written but the optional JSON file.
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
#include "walk_pipeline.hpp"
#include "wpg/datasets/input_error.hpp"
#include "wpg/datasets/scenario.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

constexpr const char* kStageNames[4] = {"NMPC", "IK", "multibody ZMP", "filter"};
constexpr const char* kStageKeys[4] = {"nmpc", "ik", "multibody_zmp", "filter"};

struct BenchRow {
  std::string name;
  int iterations = 0;
  double average = 0.0, std_dev = 0.0, min = 0.0, max = 0.0;  // [s] per NMPC iteration
  double stage_median[4] = {0.0, 0.0, 0.0, 0.0};               // [s]
  double walk_duration = 0.0;                                  // [s]
  double replay_wall_time = 0.0;                               // [s]
  double real_time_factor = 0.0;
  double rms_before = 0.0, rms_after = 0.0, max_before = 0.0, max_after = 0.0;  // [m]
  int ik_failures = 0;
  bool walk_success = true;
};

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + middle, values.end());
  const double upper = values[middle];
  if (values.size() % 2) return upper;
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + middle));
}

BenchRow measure(const datasets::Scenario& scenario, const robots::RobotModel& model) {
  const WalkResult walk = generateScenarioWalk(scenario);
  const ReplayOutcome replay = replayScenarioWalk(model, scenario, walk.trajectory, true);
  const MultibodyValidation& v = replay.validation;
  BenchRow row;
  row.name = scenario.name;
  row.walk_success = walk.success;
  const Eigen::VectorXd& chain = v.chain_time;
  row.iterations = static_cast<int>(chain.size());
  if (chain.size() > 0) {
    row.average = chain.mean();
    row.std_dev = chain.size() > 1 ? std::sqrt((chain.array() - row.average).square().sum() /
                                               static_cast<double>(chain.size() - 1))
                                   : 0.0;
    row.min = chain.minCoeff();
    row.max = chain.maxCoeff();
  }
  for (int stage = 0; stage < 4; ++stage) {
    const Eigen::VectorXd column = v.chain_stage_time.col(stage);
    row.stage_median[stage] = median(std::vector<double>(column.data(), column.data() + column.size()));
  }
  row.walk_duration = replay.walk_duration;
  row.replay_wall_time = replay.wall_time;
  row.real_time_factor = replay.realTimeFactor();
  row.rms_before = v.before.rms;
  row.rms_after = v.after.rms;
  row.max_before = v.before.max;
  row.max_after = v.after.max;
  row.ik_failures = v.ik_failures;
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
  line("Average", [](const BenchRow& r) { return fixed(1e3 * r.average, 3); });
  line("Standard deviation", [](const BenchRow& r) { return fixed(1e3 * r.std_dev, 3); });
  line("Minimum", [](const BenchRow& r) { return fixed(1e3 * r.min, 3); });
  line("Maximum", [](const BenchRow& r) { return fixed(1e3 * r.max, 3); });
  out << "Stage medians [ms]\n";
  for (int stage = 0; stage < 4; ++stage) {
    line(std::string("  ") + kStageNames[stage],
         [stage](const BenchRow& r) { return fixed(1e3 * r.stage_median[stage], 3); });
  }
  line("NMPC iterations", [](const BenchRow& r) { return std::to_string(r.iterations); });
  line("Walk duration [s]", [](const BenchRow& r) { return fixed(r.walk_duration, 2); });
  line("Replay + filter wall time [s]", [](const BenchRow& r) { return fixed(r.replay_wall_time, 3); });
  line("Replay + filter real-time factor", [](const BenchRow& r) {
    return fixed(r.real_time_factor, 0) + "x";
  });
  line("ZMP error RMS [mm] before -> after", [](const BenchRow& r) {
    return fixed(1e3 * r.rms_before, 1) + " -> " + fixed(1e3 * r.rms_after, 1);
  });
  line("ZMP error max [mm] before -> after", [](const BenchRow& r) {
    return fixed(1e3 * r.max_before, 1) + " -> " + fixed(1e3 * r.max_after, 1);
  });
  out << "(chain: NMPC = the iteration's wall time; IK per sample summed over the iteration; "
         "multibody ZMP and filter over the whole walk, spread evenly over the iterations; "
         "real-time factor: walk duration / wall time of the whole replay, including the "
         "validation replay after the filter)\n";
}

std::string jsonString(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

std::string jsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  std::ostringstream text;
  text << std::setprecision(9) << value;
  return text.str();
}

void writeJson(const std::string& path, const std::vector<BenchRow>& rows) {
  std::ostringstream json;
  json << "{\n  \"description\": \"control chain per NMPC iteration (paper Sec. V-C), seconds\",\n"
       << "  \"scenarios\": [\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const BenchRow& r = rows[i];
    json << "    {\"name\": " << jsonString(r.name) << ", \"nmpc_iterations\": " << r.iterations
         << ", \"chain_time\": {\"average\": " << jsonNumber(r.average)
         << ", \"std\": " << jsonNumber(r.std_dev) << ", \"min\": " << jsonNumber(r.min)
         << ", \"max\": " << jsonNumber(r.max) << "}, \"stage_median\": {";
    for (int stage = 0; stage < 4; ++stage) {
      json << (stage ? ", " : "") << "\"" << kStageKeys[stage]
           << "\": " << jsonNumber(r.stage_median[stage]);
    }
    json << "}, \"walk_duration\": " << jsonNumber(r.walk_duration)
         << ", \"replay_wall_time\": " << jsonNumber(r.replay_wall_time)
         << ", \"real_time_factor\": " << jsonNumber(r.real_time_factor)
         << ", \"zmp_error\": {\"rms_before\": " << jsonNumber(r.rms_before)
         << ", \"rms_after\": " << jsonNumber(r.rms_after)
         << ", \"max_before\": " << jsonNumber(r.max_before)
         << ", \"max_after\": " << jsonNumber(r.max_after) << "}"
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
