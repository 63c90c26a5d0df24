// A comparison study file as OMPL benchmark experiments (ompl_benchmark_log.hpp): one per
// world, one planner per variant, one run per seed, OMPL's run properties taken from the walk's
// first plan (the plan from the start, what one ompl::tools::Benchmark run would time) and the
// walk's own (time to goal, steps, least clearance, replans, reached).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include <H5Cpp.h>
#include <yaml-cpp/yaml.h>

#include "hdf5_bounded_reading.hpp"
#include "wpg/datasets/storage/batch_dataset.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/storage/ompl_benchmark_log.hpp"
#include "wpg/datasets/storage/provenance.hpp"
#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/storage/run_scene_reader.hpp"

namespace wpg::datasets {
namespace {

// The columns of /batch/summary read here (`wpg compare` writes them all).
const char* const kNeeded[] = {"name", "sweep.world", "sweep.variant", "sweep.seed", "done",
                               "goal_reached", "time_to_goal", "steps", "path_length",
                               "step_centre_clearance_min", "replans"};

// plans/status codes (datasets/SCHEMA.md) -> ompl::base::PlannerStatus values:
// exact 6, approximate 5, no solution 8 (abort: "no solution for some other reason"),
// timeout 4, invalid start 1, invalid goal 2.
int omplStatus(int code) {
  switch (code) {
    case 0: return 6;
    case 1: return 5;
    case 2: return 8;
    case 3: return 4;
    case 4: return 1;
    case 5: return 2;
  }
  return 0;
}

std::string number(double value) { return benchmarkNumber(value); }

std::string integer(double value) {
  return std::isfinite(value) ? std::to_string(static_cast<long long>(std::llround(value))) : "";
}

// Root attributes and the scenario of each run, read under the HDF5 lock.
struct FileFacts {
  std::string study_text, created_on, created_at;
  std::map<std::string, std::string> scenarios;  // run name -> resolved scenario YAML
};

FileFacts readFacts(const std::string& path, const std::vector<std::string>& runs) {
  std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5::Exception::dontPrint();
  FileFacts facts;
  try {
    const H5::H5File file = detail::openFileForReading(path);
    const auto optional = [&](const char* name) {
      return file.attrExists(name) ? detail::readStringAttribute(file, name, path, "/:") : std::string();
    };
    facts.study_text = optional("study");
    facts.created_on = optional("created_on");
    facts.created_at = optional("created_at");
    const H5::Group group = file.openGroup("runs");
    for (const std::string& run : runs) {
      const H5::Group g = group.openGroup(run);
      facts.scenarios[run] = detail::readStringAttribute(g, "scenario", path, "/runs/" + run + ":");
    }
  } catch (const H5::Exception& error) {
    throw InputError(path + ": cannot read the study file (" + error.getDetailMsg() + ")");
  }
  return facts;
}

// The scenario's `planner:` settings as "planner.<key>" = value lines, sorted.
std::vector<BenchmarkValue> plannerSettings(const std::string& scenario, const std::string& where) {
  std::vector<BenchmarkValue> settings;
  YAML::Node root;
  try {
    root = YAML::Load(scenario);
  } catch (const YAML::Exception& error) {
    throw InputError(where + ": the stored scenario is not YAML (" + error.what() + ")");
  }
  const YAML::Node planner = root["planner"];
  if (!planner || !planner.IsMap()) return settings;
  for (const auto& entry : planner) {
    std::string value;
    if (entry.second.IsScalar()) {
      value = entry.second.as<std::string>();
    } else {
      YAML::Emitter flow;
      flow << YAML::Flow << entry.second;
      value = flow.c_str();
    }
    settings.emplace_back("planner." + entry.first.as<std::string>(), value);
  }
  std::sort(settings.begin(), settings.end());
  return settings;
}

std::string cpuInfo() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model;
  int processors = 0;
  while (std::getline(in, line)) {
    if (line.rfind("processor", 0) == 0) ++processors;
    if (model.empty() && line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') == std::string::npos ? 0 : line.find(':') + 2);
    }
  }
  if (processors == 0) processors = static_cast<int>(std::thread::hardware_concurrency());
  return (model.empty() ? std::string("unknown CPU") : model) + "\n" + std::to_string(processors) +
         " logical processors\n";
}

}  // namespace

std::vector<BenchmarkExperiment> comparisonBenchmarkExperiments(const std::string& study_file,
                                                                double total_time) {
  const BatchSummaryTable table = readBatchSummary(study_file);
  std::map<std::string, const std::vector<std::string>*> column;
  for (std::size_t c = 0; c < table.column_names.size(); ++c) column[table.column_names[c]] = &table.cells[c];
  for (const char* name : kNeeded) {
    if (!column.count(name)) {
      throw InputError(study_file + ": /batch/summary has no column '" + name +
                       "': expected the study file of `wpg compare`");
    }
  }
  const auto cell = [&](const char* name, std::size_t row) { return (*column[name])[row]; };
  const auto value = [&](const char* name, std::size_t row) {
    return std::strtod(cell(name, row).c_str(), nullptr);  // "nan" reads as NaN
  };
  std::vector<std::string> worlds, variants, done_runs;
  for (std::size_t row = 0; row < table.rows; ++row) {
    if (std::find(worlds.begin(), worlds.end(), cell("sweep.world", row)) == worlds.end()) worlds.push_back(cell("sweep.world", row));
    if (std::find(variants.begin(), variants.end(), cell("sweep.variant", row)) == variants.end()) variants.push_back(cell("sweep.variant", row));
    if (cell("done", row) == "1") done_runs.push_back(cell("name", row));
  }
  const FileFacts facts = readFacts(study_file, done_runs);
  const Provenance now = currentProvenance();

  std::vector<std::string> properties = {
      "approximate solution BOOLEAN", "graph motions INTEGER", "graph states INTEGER",
      "least clearance REAL", "memory REAL", "planning time total REAL", "reached BOOLEAN",
      "replans INTEGER", "route length REAL", "seed INTEGER", "simplification time REAL",
      "simplified solution length REAL", "solution clearance REAL", "solution length REAL",
      "solution segments INTEGER", "solved BOOLEAN", "status ENUM", "steps INTEGER",
      "time REAL", "time to goal REAL", "walked length REAL"};
  std::sort(properties.begin(), properties.end());  // as OMPL writes them

  std::vector<BenchmarkExperiment> experiments;
  for (const std::string& world : worlds) {
    BenchmarkExperiment e;
    e.version = now.version;
    e.name = world;
    e.host = facts.created_on.empty() ? now.machine : facts.created_on;
    e.date = facts.created_at.empty() ? now.date : facts.created_at;
    e.cpu_info = cpuInfo();
    e.memory_limit = 0.0;  // wpg sets no memory limit
    std::size_t world_runs = 0;
    bool first_seed = true;
    for (const std::string& variant : variants) {
      BenchmarkPlanner planner;
      planner.name = variant;
      planner.properties = properties;
      for (std::size_t row = 0; row < table.rows; ++row) {
        if (cell("sweep.world", row) != world || cell("sweep.variant", row) != variant) continue;
        ++world_runs;
        if (cell("done", row) != "1") continue;
        const std::string run = cell("name", row);
        const std::string where = study_file + ":/runs/" + run;
        const std::string& scenario = facts.scenarios.at(run);
        if (planner.common.empty()) planner.common = plannerSettings(scenario, where);
        const std::vector<StoredRoutePlan> plans = readRoutePlans(study_file, run);
        const YAML::Node planner_node = YAML::Load(scenario)["planner"];
        const bool ompl = planner_node && planner_node["algorithm"] &&
                          planner_node["algorithm"].as<std::string>() != "none";
        if (first_seed) {
          e.seed = static_cast<long long>(value("sweep.seed", row));
          if (ompl && planner_node["time_limit"]) e.time_limit = planner_node["time_limit"].as<double>();
          first_seed = false;
        } else if (ompl && planner_node["time_limit"]) {
          e.time_limit = std::max(e.time_limit, planner_node["time_limit"].as<double>());
        }
        double planning_total = 0.0;
        for (const StoredRoutePlan& plan : plans) planning_total += plan.planning_time;
        std::map<std::string, std::string> v;
        const StoredRoutePlan* first = plans.empty() ? nullptr : &plans.front();
        // OMPL's own statistics exist for a planner's solve() only (not the straight line of
        // planner.algorithm: none): left empty there, as OMPL leaves what a planner did not report.
        const auto stat = [&](double x) { return ompl && first ? number(x) : std::string(); };
        v["approximate solution BOOLEAN"] = first ? (first->status == 1 ? "1" : "0") : "";
        v["graph motions INTEGER"] = ompl && first && first->graph_motions >= 0 ? std::to_string(first->graph_motions) : "";
        v["graph states INTEGER"] = ompl && first && first->graph_states >= 0 ? std::to_string(first->graph_states) : "";
        v["least clearance REAL"] = number(value("step_centre_clearance_min", row));
        v["memory REAL"] = "";  // not measured
        v["planning time total REAL"] = number(planning_total);
        v["reached BOOLEAN"] = value("goal_reached", row) == 1.0 ? "1" : "0";
        v["replans INTEGER"] = integer(value("replans", row));
        v["route length REAL"] = first ? number(first->route_length) : "";
        v["seed INTEGER"] = integer(value("sweep.seed", row));
        v["simplification time REAL"] = stat(first ? first->simplification_time : 0.0);
        v["simplified solution length REAL"] = stat(first ? first->simplified_solution_length : 0.0);
        v["solution clearance REAL"] = stat(first ? first->solution_clearance : 0.0);
        v["solution length REAL"] = stat(first ? first->solution_length : 0.0);
        v["solution segments INTEGER"] = first && !first->route.empty() ? std::to_string(first->route.size() - 1) : "";
        v["solved BOOLEAN"] = first ? (first->status == 0 ? "1" : "0") : "0";
        v["status ENUM"] = first ? std::to_string(omplStatus(first->status)) : "0";
        v["steps INTEGER"] = integer(value("steps", row));
        v["time REAL"] = first ? number(first->planning_time) : "";
        v["time to goal REAL"] = number(value("time_to_goal", row));
        v["walked length REAL"] = number(value("path_length", row));
        std::vector<std::string> values;
        for (const std::string& property : properties) values.push_back(v.at(property));
        planner.runs.push_back(std::move(values));
      }
      e.runs_per_planner = std::max<long long>(e.runs_per_planner, static_cast<long long>(planner.runs.size()));
      e.planners.push_back(std::move(planner));
    }
    e.total_time = table.rows ? total_time * static_cast<double>(world_runs) / static_cast<double>(table.rows) : 0.0;
    e.properties = {{"seeds INTEGER", std::to_string(e.runs_per_planner)},
                    {"variants INTEGER", std::to_string(variants.size())}};
    e.setup = "wpg comparison study '" + table.study + "', world '" + world +
              "': walks of the NMPC walking pattern generator (Naveau et al., RA-L 2017) to a goal, "
              "one run per seed; a planner is a variant of the study (its settings: the common "
              "properties). OMPL's run properties come from the walk's first plan (from the start); "
              "'reached', 'time to goal', 'steps', 'least clearance' (step centres to the margins), "
              "'replans' and 'walked length' from the walk. 'seconds spent' is the study's wall time "
              "shared among its worlds by their runs.\n"
              "written by wpg " + now.version + " (commit " + now.commit + ") on " + now.machine +
              " at " + now.date + " from " + study_file + "\n" +
              "the study file:\n" + facts.study_text;
    experiments.push_back(std::move(e));
  }
  return experiments;
}

}  // namespace wpg::datasets
