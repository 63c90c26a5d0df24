// `wpg push-sweep [--situation forward|on_spot] [--phases K] [-j N] [--json FILE] [-o OUT.h5]`:
// the paper's push-recovery test (Sec. V-B), run by the engine (wpg/engine/push_sweep.hpp) for
// the situations forward at 0.2 m/s (the shipped `push`) and stepping in place
// (`push_stepping_in_place`), each with its own push replaced: the same numbers for any -j.
// Prints our table beside the paper's, writes the HDF5 table, its figure and the --json list.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <system_error>

#include "analysis_scripts.hpp"
#include "batch_progress.hpp"
#include "command_options.hpp"
#include "error_messages.hpp"
#include "exit_codes.hpp"
#include "json_text.hpp"
#include "wpg/analysis/sample_statistics.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/input_limits.hpp"
#include "wpg/datasets/storage/output_file.hpp"
#include "wpg/datasets/storage/push_sweep_dataset.hpp"
#include "wpg/engine/push_sweep.hpp"

namespace fs = std::filesystem;

namespace wpg::cli {
namespace {

using engine::PushSituation;
using engine::shortestNumber;

// The situations and the shipped scenario that holds each (pushes[0] is replaced).
struct SituationSource {
  const char* name;
  const char* scenario;
};
constexpr SituationSource kSituations[] = {{"forward", "push"},
                                           {"on_spot", "push_stepping_in_place"}};

// The paper's Sec. V-B numbers [N] per situation and direction (NaN: not given). It does not
// define its axes; "smaller in the forward direction" gives sagittal+ = forward = +x; its
// coronal +90 / -45 N are read as +y (left) / -y, the same for both situations.
double paperForce(const std::string& situation, const std::string& direction) {
  if (direction == "coronal+") return 90.0;
  if (direction == "coronal-") return -45.0;
  if (situation == "on_spot") return direction == "sagittal+" ? 115.0 : -115.0;
  return direction == "sagittal+" ? 70.0 : -160.0;
}

double median(const std::vector<double>& values) {
  return analysis::median(Eigen::Map<const Eigen::VectorXd>(values.data(),
                                                            static_cast<Eigen::Index>(values.size())));
}

void checkWritable(const std::string& path, const char* option, datasets::OutputKind kind) {
  std::error_code ec;
  // Never over a device, a folder or a file of another kind (output_file.hpp).
  try {
    datasets::checkOutputPath(path, kind);
  } catch (const datasets::InputError& e) {
    throw UsageError(std::string(option) + " " + e.what());
  }
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && fs::exists(parent, ec) && !fs::is_directory(parent, ec)) {
    throw UsageError(std::string(option) + ": '" + parent.string() + "' is not a directory");
  }
}

// OUT.h5 -> OUT.<suffix>
std::string besideOutput(const std::string& output, const std::string& suffix) {
  fs::path path = output;
  path.replace_extension("." + suffix);
  return path.string();
}

void checkOptions(const PushSweepOptions& options) {
  if (options.situation != "both" && options.situation != "forward" && options.situation != "on_spot") {
    throw UsageError("--situation: expected forward, on_spot or both, got '" + options.situation + "'");
  }
  if (options.phases < 1 || options.phases > 1000) {
    throw UsageError("--phases: expected a number of phases in [1, 1000], got " + std::to_string(options.phases));
  }
  if (options.threads < 1) throw UsageError("-j: expected a number of worker threads >= 1");
  // The scenarios' bound on push forces (SCENARIOS.md, "Limits") holds for the sweep's pushes.
  if (!std::isfinite(options.max_force) || options.max_force <= 0.0 ||
      options.max_force > datasets::kMaxPushForce) {
    throw UsageError("--max-force: expected a force > 0 N and at most 1e5 N");
  }
  if (!std::isfinite(options.tolerance) || options.tolerance <= 0.0 ||
      options.tolerance >= options.max_force) {
    throw UsageError("--tolerance: expected a force > 0 N and below --max-force");
  }
  if (!std::isfinite(options.max_swing_speed) || options.max_swing_speed < 0.0)
    throw UsageError("--max-swing-speed: expected a speed >= 0 m/s (0: not checked), got " +
                     shortestNumber(options.max_swing_speed));
  if (!std::isfinite(options.max_swing_acceleration) || options.max_swing_acceleration < 0.0)
    throw UsageError("--max-swing-acceleration: expected an acceleration >= 0 m/s^2 (0: not "
                     "checked), got " + shortestNumber(options.max_swing_acceleration));
  // Below ~1e-12 of the bracket, doubles no longer resolve it (2^-52 relative): a tolerance
  // the bisection could never reach is bad input, printed as given.
  const double finest = 1e-12 * options.max_force;
  if (options.tolerance < finest) {
    throw UsageError("--tolerance: expected a force of at least " + shortestNumber(finest) +
                     " N (1e-12 of --max-force: doubles resolve no finer), got " +
                     shortestNumber(options.tolerance));
  }
  if (options.output.empty()) throw UsageError("-o: expected the HDF5 file to write (OUT.h5)");
  checkWritable(options.output, "-o", datasets::OutputKind::kHdf5);
  if (!options.json.empty()) checkWritable(options.json, "--json", datasets::OutputKind::kJson);
  // Every other file beside OUT.h5, held to the same rules (output_file.hpp) before any work.
  std::vector<datasets::PlannedOutput> outputs = {{options.output, datasets::OutputKind::kHdf5}};
  if (!options.json.empty()) outputs.push_back({options.json, datasets::OutputKind::kJson});
  if (options.plot) outputs.push_back({besideOutput(options.output, "png"), datasets::OutputKind::kPng});
  if (!options.overrides.empty()) {
    for (const SituationSource& source : kSituations) {
      if (options.situation == "both" || options.situation == source.name)
        outputs.push_back({besideOutput(options.output, std::string(source.name) + ".yaml"),
                           datasets::OutputKind::kText});
    }
  }
  datasets::checkOutputPaths(outputs);
}

// The situation's base scenario with the overrides, and its swept step (the engine runs the
// unpushed walk).
PushSituation loadSituation(const SituationSource& source, const PushSweepOptions& options) {
  const datasets::Scenario base = datasets::loadScenario(
      resolveScenarioPath(source.scenario), options.overrides, robotsDirectory());
  printWarnings(base.warnings);
  PushSituation situation =
      engine::preparePushSituation(source.name, source.scenario, base, robotsDirectory());
  // Written with the outputs (writeSituationScenario), after everything is checked.
  if (!options.overrides.empty()) situation.scenario = besideOutput(options.output, situation.name + ".yaml");
  return situation;
}

// With --set, the situation's scenario is OUT.<situation>.yaml: the base scenario resolved
// with the overrides (its pushes[0] is what the JSON's push replaces).
void writeSituationScenario(const PushSituation& situation, const SituationSource& source,
                            const std::vector<std::string>& overrides) {
  std::string text = "# " + std::string(source.scenario) + " with --set";
  for (const std::string& o : overrides) text += " " + o;
  text += " (wpg push-sweep)\n" + resolvedScenarioText(situation.base);
  datasets::writeFileAtomically(situation.scenario, text);  // never through a link
}

void printTable(const std::vector<datasets::PushSweepRow>& rows, int phases) {
  std::cout << "Push recovery (paper Sec. V-B): largest recovered force of a 100 ms push, over "
            << phases << " phase" << (phases > 1 ? "s" : "") << " of one step\n";
  std::cout << std::left << std::setw(10) << "situation" << std::setw(11) << "direction"
            << std::right << std::setw(26) << "ours |F| min/median/max" << std::setw(22)
            << "impulse F x 0.1 s" << std::setw(12) << "paper F" << std::setw(17)
            << "paper F x 0.1 s" << "\n";
  std::cout << std::left << std::setw(21) << "" << std::right << std::setw(26) << "[N]"
            << std::setw(22) << "[N s]" << std::setw(12) << "[N]" << std::setw(17) << "[N s]"
            << "\n";
  for (std::size_t begin = 0; begin < rows.size(); begin += static_cast<std::size_t>(phases)) {
    std::vector<double> forces, impulses;
    bool bound = false;
    for (std::size_t i = begin; i < begin + static_cast<std::size_t>(phases); ++i) {
      forces.push_back(std::abs(rows[i].force));
      impulses.push_back(std::abs(rows[i].impulse));
      bound = bound || rows[i].at_upper_bound;
    }
    const auto triple = [](const std::vector<double>& v, int precision) {
      std::ostringstream text;
      text << std::fixed << std::setprecision(precision)
           << *std::min_element(v.begin(), v.end()) << " / " << median(v) << " / "
           << *std::max_element(v.begin(), v.end());
      return text.str();
    };
    const double paper = paperForce(rows[begin].situation, rows[begin].direction);
    std::ostringstream paper_force, paper_impulse;
    paper_force << std::showpos << std::fixed << std::setprecision(0) << paper;
    paper_impulse << std::showpos << std::fixed << std::setprecision(1) << paper * 0.1;
    std::cout << std::left << std::setw(10) << rows[begin].situation << std::setw(11)
              << rows[begin].direction << std::right << std::setw(26)
              << triple(forces, 1) + (bound ? "*" : "") << std::setw(22) << triple(impulses, 2)
              << std::setw(12) << paper_force.str() << std::setw(17) << paper_impulse.str() << "\n";
  }
  std::cout << "(sagittal+ = +x, forward; coronal+ = +y, left; * = the upper bound --max-force "
               "was recovered at some phase)\n";
}

void writeJson(const std::string& path, const std::vector<datasets::PushSweepRow>& rows) {
  datasets::TemporaryOutput temporary(path);  // atomic: an exclusive file, then a rename
  std::ofstream out(temporary.path());
  out << "[\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const datasets::PushSweepRow& row = rows[i];
    out << "  {\"situation\": " << jsonString(row.situation)
        << ", \"direction\": " << jsonString(row.direction)
        << ", \"phase\": " << shortestNumber(row.phase)
        << ", \"scenario\": " << jsonString(row.scenario) << ", \"t\": " << shortestNumber(row.t)
        << ", \"duration\": " << shortestNumber(row.duration) << ", \"force\": ["
        << shortestNumber(row.fx) << ", " << shortestNumber(row.fy)
        << "], \"swing_speed_max\": " << shortestNumber(row.swing_speed_max)
        << ", \"swing_acceleration_max\": " << shortestNumber(row.swing_acceleration_max) << "}"
        << (i + 1 < rows.size() ? "," : "") << "\n";
  }
  out << "]\n";
  if (!out.flush()) throw std::runtime_error("cannot write " + path);
  out.close();
  temporary.commit();
}

}  // namespace

int pushSweepCommand(const PushSweepOptions& options) {
  checkOptions(options);
  std::vector<PushSituation> situations;
  for (const SituationSource& source : kSituations) {
    if (options.situation == "both" || options.situation == source.name) {
      situations.push_back(loadSituation(source, options));
    }
  }
  engine::PushSearchSettings settings;
  settings.max_force = options.max_force;
  settings.tolerance = options.tolerance;
  settings.max_swing_speed = options.max_swing_speed;
  settings.max_swing_acceleration = options.max_swing_acceleration;
  BatchProgress progress("push-sweep",
                         situations.size() * engine::pushDirections().size() *
                             static_cast<std::size_t>(options.phases),
                         stderr);
  const std::vector<datasets::PushSweepRow> rows =
      engine::runPushSweep(situations, options.phases, settings, options.threads,
                           robotsDirectory(), [&] { progress.runFinished(false); });
  progress.finish();

  printTable(rows, options.phases);
  datasets::PushSweepFile file;
  file.rows = rows;
  for (const PushSituation& situation : situations) {
    file.situations.push_back(situation.name);
    file.scenarios.push_back(resolvedScenarioText(situation.base));
    file.step_lift_off.push_back(situation.lift_off);
  }
  file.overrides = options.overrides;
  file.max_force = settings.max_force;
  file.tolerance = settings.tolerance;
  file.stronger_factor = settings.stronger_factor;
  file.max_swing_speed = settings.max_swing_speed;
  file.max_swing_acceleration = settings.max_swing_acceleration;
  datasets::writePushSweepFile(options.output, file);
  std::cout << "wrote " << options.output;
  if (!options.overrides.empty()) {
    for (const PushSituation& situation : situations) {
      for (const SituationSource& source : kSituations) {
        if (situation.name != source.name) continue;
        writeSituationScenario(situation, source, options.overrides);
        std::cout << ", " << situation.scenario;
      }
    }
  }
  if (!options.json.empty()) {
    writeJson(options.json, rows);
    std::cout << ", " << options.json;
  }
  if (options.plot) {
    const std::string figure = besideOutput(options.output, "png");
    const std::string script = (fs::path(dataDirectory()) / "analysis" / "plot_push_sweep.py").string();
    if (runAnalysisScript(script, {options.output, "-o", figure}) == 0) {
      std::cout << ", " << figure;
    } else {
      std::cout.flush();
      printWarning("the figure could not be drawn (Python with h5py and matplotlib?)");
    }
  }
  std::cout << "\n";
  return kExitSuccess;
}

}  // namespace wpg::cli
