// Study files: parsing, sweep expansion and the runs' scenarios
// (wpg/datasets/study_design/study.hpp).
#include "wpg/datasets/study_design/study.hpp"
#include "wpg/datasets/input/input_limits.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <fstream>
#include <new>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "compiled_sweep.hpp"
#include "wpg/datasets/input/yaml_input.hpp"
#include "wpg/qp/hessian_factor_cache.hpp"

namespace wpg::datasets {
namespace {

namespace fs = std::filesystem;
using detail::Source;

// A sweep key with its values, one per point of its section.
struct KeyValues {
  std::string key;
  std::vector<SweptValue> values;
};

SweptValue sweptValue(const std::string& key, const YAML::Node& node) {
  SweptValue value;
  value.key = key;
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  value.value = detail::oneLine(out.c_str());
  if (node.IsScalar() && !detail::isQuoted(node)) {
    try {
      value.number = node.as<double>();
      value.numeric = std::isfinite(value.number);
    } catch (const YAML::Exception&) {
      value.numeric = false;
    }
  }
  return value;
}

SweptValue numberValue(const std::string& key, double number) {
  SweptValue value;
  value.key = key;
  value.value = detail::formatNumber(number);
  value.numeric = true;
  value.number = number;
  return value;
}

// The entries of a map in file order (readMap sorts them; the sweep's order matters).
std::vector<std::pair<std::string, YAML::Node>> orderedEntries(const YAML::Node& node,
                                                               const std::string& key,
                                                               const std::string& expected,
                                                               const Source& source) {
  if (!node.IsDefined() || !node.IsMap()) source.fail(key, expected, node);
  std::vector<std::pair<std::string, YAML::Node>> entries;
  for (const auto& item : node) {
    if (!item.first.IsScalar()) source.fail(key, "keys that are dotted paths", item.first);
    entries.emplace_back(item.first.Scalar(), item.second);
  }
  if (entries.empty()) source.failWith(key, "expected at least one swept key, got an empty map");
  return entries;
}

std::vector<KeyValues> readLists(const YAML::Node& node, const std::string& section,
                                 const Source& source) {
  std::vector<KeyValues> keys;
  for (const auto& [key, list] : orderedEntries(
           node, section, "a map of dotted scenario keys to lists of values", source)) {
    const std::string where = detail::childKey(section, "\"" + key + "\"");
    if (!list.IsSequence() || list.size() == 0) {
      source.fail(where, "a non-empty list of values", list);
    }
    KeyValues values{key, {}};
    for (const YAML::Node& item : list) values.values.push_back(sweptValue(key, item));
    keys.push_back(std::move(values));
  }
  return keys;
}

// `random:` -> its keys and ranges, sample count and seed. Sample s of key k is the
// generator's draw s * keys + k (uniformAt): the draws sample by sample in the keys' file order
// from one generator seeded with `seed`, each computed from its number alone.
struct RandomSweep {
  struct Range {
    std::string key;
    double low, high;
  };
  std::vector<Range> ranges;
  std::size_t samples = 0;
  std::uint64_t seed = 0;

  SweptValue value(std::size_t sample, std::size_t k) const {
    const double u = uniformAt(seed, static_cast<std::uint64_t>(sample) * ranges.size() + k);
    return numberValue(ranges[k].key, ranges[k].low + (ranges[k].high - ranges[k].low) * u);
  }
};

// `fields: [summary, footsteps]` (run_fields.hpp).
RunFields readFields(const YAML::Node& node, const std::string& path) {
  std::vector<std::string> names;
  if (!node.IsSequence()) {
    throw InputError(path + ": fields: expected a list of field names ([summary, footsteps]), got " +
                     (node.IsScalar() ? "'" + node.Scalar() + "'" : std::string("a map")));
  }
  for (const YAML::Node& name : node) {
    if (!name.IsScalar()) throw InputError(path + ": fields: expected field names, got a list or map");
    names.push_back(name.Scalar());
  }
  return parseRunFields(names, path + ": fields");
}

RandomSweep readRandom(const YAML::Node& node, const Source& source) {
  const detail::Entries entries =
      detail::readMap(node, "sweep.random", {"samples", "seed", "keys"},
                      "a map with samples, seed and keys", source);
  const int samples = detail::readInteger(detail::entry(entries, "samples"), "sweep.random.samples",
                                          1, "a number of samples from 1 to 2147483647 (2^31 - 1, "
                                          "the cap on a study's runs)", source);
  const int seed = detail::readInteger(detail::entry(entries, "seed"), "sweep.random.seed", 0,
                                       "a non-negative integer seed", source);
  RandomSweep random;
  random.samples = static_cast<std::size_t>(samples);
  random.seed = static_cast<std::uint64_t>(seed);
  for (const auto& [key, law] : orderedEntries(detail::entry(entries, "keys"), "sweep.random.keys",
                                               "a map of dotted scenario keys to {uniform: [low, high]}",
                                               source)) {
    const std::string where = detail::childKey("sweep.random.keys", "\"" + key + "\"");
    const detail::Entries spec =
        detail::readMap(law, where, {"uniform"}, "{uniform: [low, high]}", source);
    const Eigen::Vector2d range = detail::readVector<2>(
        detail::entry(spec, "uniform"), detail::childKey(where, "uniform"), "[low, high]", source);
    if (!(range[0] <= range[1])) {
      source.failWith(detail::childKey(where, "uniform"),
                      "expected [low, high] with low <= high, got [" +
                          detail::formatNumber(range[0]) + ", " + detail::formatNumber(range[1]) +
                          "]");
    }
    random.ranges.push_back({key, range[0], range[1]});
  }
  return random;
}

// What makes run i of a sweep from i alone (shared by every copy of the study's run list and
// read by any thread: nothing in it changes after loadStudy).
struct SweepExpansion {
  std::string path;  // the study file
  std::string name;
  std::string base_text, base_origin, robots_dir;
  std::vector<std::string> constants;  // set: (and plan: false), before the swept values
  std::vector<KeyValues> grid, zip;
  RandomSweep random;
  std::size_t zip_points = 1, random_points = 1;
  int digits = 1;
  std::shared_ptr<qp::HessianFactorCache> hessian_factors;

  CompiledSweep compiled;  // the fast way to a run's scenario (compiled_sweep.hpp)

  StudyRun make(std::size_t index, StudyRuns::Make what) const {
    StudyRun run;
    run.index = index;
    char number[32];
    std::snprintf(number, sizeof number, "%0*zu", digits, index);
    run.name = name + "_" + number;
    // Each key's value; with a scenario, also its position in its list (a random key: its
    // sample), for the compiled fields.
    const bool with_scenario = what != StudyRuns::Make::kDescription;
    std::vector<std::size_t> positions;
    const auto take = [&](const SweptValue& value, std::size_t position) {
      run.swept.push_back(value);
      if (with_scenario) positions.push_back(position);
    };
    run.swept.resize(grid.size());
    if (with_scenario) positions.resize(grid.size());
    std::size_t rest = index / (zip_points * random_points);
    for (std::size_t k = grid.size(); k-- > 0;) {
      const std::size_t position = rest % grid[k].values.size();
      run.swept[k] = grid[k].values[position];
      if (with_scenario) positions[k] = position;
      rest /= grid[k].values.size();
    }
    const std::size_t zip_index = (index / random_points) % zip_points;
    for (const KeyValues& key : zip) take(key.values[zip_index], zip_index);
    const std::size_t sample = index % random_points;
    for (std::size_t k = 0; k < random.ranges.size(); ++k) take(random.value(sample, k), sample);
    if (with_scenario) {
      run.from_fields = what == StudyRuns::Make::kScenario &&
                        compiled.make(run.swept, positions, run.name, &run.scenario);
      if (!run.from_fields) loadScenarioOf(&run);
      nameWarnings(&run);
      run.scenario.request.generator.hessian_factors = hessian_factors;
    }
    return run;
  }

  // "key=value, ..." of the run's swept values, as its messages quote them.
  static std::string describeValues(const StudyRun& run) {
    std::string described;
    for (const SweptValue& value : run.swept)
      described += (described.empty() ? "" : ", ") + value.key + "=" + value.value;
    return described;
  }

  // The base with the run's values, loaded and validated as `wpg run` does.
  void loadScenarioOf(StudyRun* run) const {
    std::vector<std::string> overrides = constants;
    for (const SweptValue& value : run->swept) overrides.push_back(value.key + "=" + value.value);
    overrides.push_back("name=" + run->name);
    try {
      run->scenario = loadScenarioText(base_text, base_origin, overrides, robots_dir);
    } catch (const std::exception& e) {  // InputError
      // The loader calls the swept values --set overrides; here they come from the sweep.
      throw InputError(path + ": run " + std::to_string(run->index) + " (" + describeValues(*run) +
                       "): " + detail::renameOverrides(detail::oneLine(e.what()), "sweep"));
    }
  }

  // Its warnings, as its errors would read: the study, the run, the sweep.
  void nameWarnings(StudyRun* run) const {
    if (run->scenario.warnings.empty()) return;
    const std::string described = describeValues(*run);
    for (std::string& warning : run->scenario.warnings) {
      warning = path + ": run " + std::to_string(run->index) + " (" + described +
                "): " + detail::renameOverrides(warning, "sweep");
    }
  }
};

// The swept keys in the order of Study::keys, for CompiledSweep.
std::vector<SweptKey> sweptKeys(const SweepExpansion& expansion) {
  std::vector<SweptKey> keys;
  for (const auto* section : {&expansion.grid, &expansion.zip})
    for (const KeyValues& key : *section)
      keys.push_back({key.key, key.values.front().value, key.values});
  for (std::size_t k = 0; k < expansion.random.ranges.size(); ++k) {
    const RandomSweep::Range& range = expansion.random.ranges[k];
    keys.push_back({range.key, expansion.random.value(0, k).value, {}, range.low, range.high});
  }
  return keys;
}

// FNV-1a, 64 bits: a stable digest of text (not for security, for "same study?").
std::uint64_t fnv1a(const std::string& text, std::uint64_t hash) {
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}


}  // namespace

double nextUniform(std::uint64_t* state) {
  // SplitMix64 (Steele, Lea, Flood 2014), then the top 53 bits as a double in [0, 1).
  std::uint64_t z = (*state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

double uniformAt(std::uint64_t seed, std::uint64_t n) {
  std::uint64_t state = seed + n * 0x9e3779b97f4a7c15ull;  // n steps of the counter, wrapping
  return nextUniform(&state);
}

std::vector<std::size_t> checkedRuns(const std::vector<std::size_t>& grid, std::size_t zip_points,
                                     std::size_t random_points) {
  std::size_t total = zip_points * random_points;
  for (const std::size_t values : grid) total *= values;
  std::vector<std::size_t> runs;
  if (total <= kCheckedStudyRuns) {
    for (std::size_t i = 0; i < total; ++i) runs.push_back(i);
    return runs;
  }
  // Run 0, then every value of each grid key with the others at their first (the stride of key
  // k is the product of the points after it), every zip entry, the first random samples.
  std::vector<std::size_t> candidates = {0};
  std::size_t stride = zip_points * random_points;
  for (std::size_t k = grid.size(); k-- > 0;) {
    for (std::size_t v = 1; v < grid[k] && candidates.size() < kCheckedStudyRuns; ++v)
      candidates.push_back(v * stride);
    stride *= grid[k];
  }
  for (std::size_t z = 1; z < zip_points && candidates.size() < kCheckedStudyRuns; ++z)
    candidates.push_back(z * random_points);
  for (std::size_t r = 1; r < random_points && candidates.size() < kCheckedStudyRuns; ++r)
    candidates.push_back(r);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  return candidates;
}

void checkStudyScenarios(Study* study, int threads) {
  const std::vector<std::size_t>& indices = study->checked_runs;
  const std::size_t total = indices.size();
  std::vector<std::string> errors(total);
  std::vector<std::string> digests(total);
  std::vector<std::vector<std::string>> warnings(total);
  std::vector<Study::CheckedRun> checked(total);
  std::atomic<bool> out_of_memory{false};
  const auto loadRun = [&](std::size_t position) {
    try {
      StudyRun run = study->runs[indices[position]];
      checked[position] = {run.index, run.scenario.robot, run.scenario.replay,
                           run.scenario.goal.enabled};
      digests[position] = resolvedScenarioText(run.scenario);
      warnings[position] = std::move(run.scenario.warnings);
    } catch (const std::bad_alloc&) {
      out_of_memory = true;  // not the input's fault: exit 3, as anywhere else
    } catch (const std::exception& e) {
      errors[position] = detail::oneLine(e.what());
    }
  };
  const std::size_t workers =
      std::max<std::size_t>(1, std::min<std::size_t>(threads < 1 ? 1 : static_cast<std::size_t>(threads), total));
  // Runs handed out one at a time: a thread the system refuses to start (a thread or memory
  // limit) leaves its share to the others, never std::terminate.
  std::atomic<std::size_t> next{0};
  const auto loadRuns = [&] {
    for (std::size_t i = next++; i < total; i = next++) loadRun(i);
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) {
    try {
      pool.emplace_back(loadRuns);
    } catch (const std::system_error&) {
      break;
    }
  }
  loadRuns();
  for (std::thread& thread : pool) thread.join();
  if (out_of_memory) throw std::bad_alloc();
  std::uint64_t hash = 14695981039346656037ull;
  study->warnings.clear();
  study->checked = std::move(checked);
  for (std::size_t i = 0; i < total; ++i) {
    if (!errors[i].empty()) throw InputError(errors[i]);
    hash = fnv1a(digests[i], hash);
    study->warnings.insert(study->warnings.end(), warnings[i].begin(), warnings[i].end());
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  study->fingerprint = hex;
}

Study loadStudy(const std::string& path, const BaseResolver& resolve_base,
                const std::string& robots_dir, int threads) {
  Study study;
  study.source_path = path;
  const Source source(path);
  const YAML::Node root = detail::readYamlFile(path, "study file");
  study.text = detail::readTextFile(path, "study file");
  const detail::Entries top =
      detail::readMap(root, "", {"name", "base", "set", "sweep", "plan", "fields"},
                      "a study: a map with name, base, sweep and optionally set, plan and fields",
                      source);
  // `plan: false`: the runs leave out what each NMPC iteration predicted (mpc/plan/), as
  // `--set generator.record_plan=false` would: a smaller batch file and less writing.
  const bool without_plans =
      detail::present(top, "plan") &&
      !detail::readBoolean(detail::entry(top, "plan"), "plan", "true or false", source);
  if (detail::present(top, "fields")) study.fields = readFields(detail::entry(top, "fields"), path);
  study.name = detail::readName(detail::entry(top, "name"), "name",
                                "a study name (at most 32 letters, digits, _ - .)", source,
                                kMaxStudyNameLength);

  // The base scenario's text and where it came from.
  const YAML::Node base = detail::entry(top, "base");
  std::string base_text, base_origin;
  if (base.IsDefined() && base.IsMap()) {
    base_text = YAML::Dump(base) + "\n";
    base_origin = path + ":base";
  } else if (base.IsDefined() && base.IsScalar() && !base.Scalar().empty()) {
    const fs::path beside = fs::path(path).parent_path() / base.Scalar();
    std::error_code ec;
    if (fs::path(base.Scalar()).is_relative() && fs::is_regular_file(beside, ec)) {
      base_origin = beside.string();
    } else {
      try {
        base_origin = resolve_base(base.Scalar());
      } catch (const std::exception& e) {
        source.failWith("base", e.what());
      }
    }
    base_text = detail::readTextFile(base_origin, "base scenario");
  } else {
    source.fail("base", "a shipped scenario name, a scenario file or an inline scenario map", base);
  }

  // `set:`: constant overrides of every run (not swept: no column), applied before the sweep's
  // values; checked alone first, so that an error in one of them is named as set, not swept.
  std::vector<std::string> constants;
  if (detail::present(top, "set")) {
    const YAML::Node set = detail::entry(top, "set");
    if (!set.IsMap() || set.size() == 0)
      source.fail("set", "a non-empty map of dotted scenario keys to values", set);
    for (const auto& item : set) {
      if (!item.first.IsScalar()) source.fail("set", "keys that are dotted paths", item.first);
      const SweptValue value = sweptValue(item.first.Scalar(), item.second);
      constants.push_back(value.key + "=" + value.value);
    }
    std::vector<std::string> overrides = constants;
    overrides.push_back("name=" + study.name + "_0");
    try {
      (void)loadScenarioText(base_text, base_origin, overrides, robots_dir);
    } catch (const std::exception& e) {
      throw InputError(path + ": " +
                       detail::renameOverrides(detail::oneLine(e.what()), "the study's set:"));
    }
  }

  // The sweep's sections, each a list of keys with one value per point of the section.
  const detail::Entries sweep = detail::readMap(
      detail::entry(top, "sweep"), "sweep", {"grid", "zip", "random"},
      "a map with grid, zip and/or random", source);
  if (sweep.empty()) source.failWith("sweep", "expected grid, zip and/or random, got an empty sweep");
  std::vector<KeyValues> grid, zip;
  RandomSweep random;
  if (detail::present(sweep, "grid")) grid = readLists(detail::entry(sweep, "grid"), "sweep.grid", source);
  if (detail::present(sweep, "zip")) {
    zip = readLists(detail::entry(sweep, "zip"), "sweep.zip", source);
    for (const KeyValues& key : zip) {
      if (key.values.size() != zip.front().values.size()) {
        source.failWith("sweep.zip", "expected lists of the same length, got " +
                                         std::to_string(zip.front().values.size()) + " for '" +
                                         zip.front().key + "' and " +
                                         std::to_string(key.values.size()) + " for '" + key.key + "'");
      }
    }
  }
  if (detail::present(sweep, "random")) random = readRandom(detail::entry(sweep, "random"), source);
  if (grid.empty() && zip.empty() && random.ranges.empty()) {
    source.failWith("sweep", "expected grid, zip and/or random with values, got an empty sweep");
  }
  // Every swept key with its first value (run 0's), in the order of Study::keys.
  std::vector<SweptValue> first_values;
  for (const auto* section : {&grid, &zip})
    for (const KeyValues& key : *section) first_values.push_back(key.values.front());
  for (std::size_t k = 0; k < random.ranges.size(); ++k) first_values.push_back(random.value(0, k));
  for (const SweptValue& value : first_values) {
    const std::string& key = value.key;
    for (const std::string& known : study.keys) {
      if (known == key) source.failWith("sweep", "key '" + key + "' is swept twice");
    }
    study.keys.push_back(key);
    for (const std::string& constant : constants) {
      if (constant.compare(0, key.size() + 1, key + "=") == 0)
        source.failWith("set", "key '" + key + "' is also swept: set it or sweep it");
    }
  }

  if (without_plans) constants.push_back("generator.record_plan=false");

  // The keys first, on the first value of each (a typo is named before any count or
  // expansion): the scenario must have them all.
  {
    std::vector<std::string> overrides = constants;
    for (const SweptValue& value : first_values) overrides.push_back(value.key + "=" + value.value);
    overrides.push_back("name=" + study.name + "_0");
    try {
      (void)loadScenarioText(base_text, base_origin, overrides, robots_dir);
    } catch (const std::exception& e) {
      std::string message = detail::oneLine(e.what());
      for (std::size_t at = message.find("--set '"); at != std::string::npos;
           at = message.find("--set '", at)) {
        message.replace(at, 5, "sweep");
      }
      throw InputError(path + ": run 0: " + message);
    }
  }

  // Points: grid (first key slowest), then zip, then random (fastest); counted against the
  // cap factor by factor, never wrapping.
  std::size_t total = 1;
  std::string factors;
  const auto multiply = [&](std::size_t factor, const std::string& what) {
    factors += (factors.empty() ? "" : " x ") + std::to_string(factor) + " " + what;
    if (factor != 0 && total > kMaxSweepRuns / factor) {
      source.failWith("sweep", "expected at most " + std::to_string(kMaxSweepRuns) +
                                   " runs (2^31 - 1), got more: " + factors + "...");
    }
    total *= factor;
  };
  auto expansion = std::make_shared<SweepExpansion>();
  std::vector<std::size_t> grid_sizes;
  for (const KeyValues& key : grid) {
    multiply(key.values.size(), "values of '" + key.key + "'");
    grid_sizes.push_back(key.values.size());
  }
  expansion->zip_points = zip.empty() ? 1 : zip.front().values.size();
  expansion->random_points = random.ranges.empty() ? 1 : random.samples;
  multiply(expansion->zip_points, "zip entries");
  multiply(expansion->random_points, "random samples");

  for (const auto* section : {&grid, &zip}) {
    for (const KeyValues& key : *section) {
      bool numeric = true;
      for (const SweptValue& value : key.values) numeric = numeric && value.numeric;
      study.key_numeric.push_back(numeric);
    }
  }
  study.key_numeric.resize(study.keys.size(), true);  // random values are numbers

  expansion->path = path;
  expansion->name = study.name;
  expansion->base_text = std::move(base_text);
  expansion->base_origin = std::move(base_origin);
  expansion->robots_dir = robots_dir;
  expansion->constants = std::move(constants);
  expansion->grid = std::move(grid);
  expansion->zip = std::move(zip);
  expansion->random = std::move(random);
  expansion->digits = static_cast<int>(std::to_string(total - 1).size());
  // One cache of Hessian factors for the study: its runs mostly sweep keys that leave the
  // NMPC's Hessians as they are (1200 factors computed for the 200 runs of
  // speeds_weights_heights.yaml instead of 6000), and the factors are the same bits shared or
  // not (qp/hessian_factor_cache.hpp); it holds at most its budget, whatever the runs.
  expansion->hessian_factors = std::make_shared<qp::HessianFactorCache>();
  expansion->compiled =
      CompiledSweep(expansion->base_text, expansion->base_origin, robots_dir, expansion->constants,
                    study.name + "_0", sweptKeys(*expansion));
  study.runs = StudyRuns(total, [expansion](std::size_t index, StudyRuns::Make what) {
    return expansion->make(index, what);
  });
  study.checked_runs = checkedRuns(grid_sizes, expansion->zip_points, expansion->random_points);
  checkStudyScenarios(&study, threads);
  return study;
}

}  // namespace wpg::datasets
