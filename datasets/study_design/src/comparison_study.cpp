// Comparison study files: worlds x variants x seeds expanded into a Study
// (wpg/datasets/study_design/comparison_study.hpp).
#include "wpg/datasets/study_design/comparison_study.hpp"
#include "wpg/datasets/input/input_limits.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "world_generators.hpp"
#include "wpg/datasets/input/yaml_input.hpp"
#include "wpg/nearest_name.hpp"
#include "wpg/qp/hessian_factor_cache.hpp"

namespace wpg::datasets {
namespace {

namespace fs = std::filesystem;
using detail::Source;


std::string flowText(const YAML::Node& node) {
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  return detail::oneLine(out.c_str());
}

// A scenario given by name or path: next to the study first, then the shipped ones.
std::string findScenario(const YAML::Node& node, const std::string& key, const std::string& path,
                         const BaseResolver& resolve, const Source& source) {
  if (!node.IsDefined() || !node.IsScalar() || node.Scalar().empty()) {
    source.fail(key, "a shipped scenario name or a scenario file", node);
  }
  const fs::path beside = fs::path(path).parent_path() / node.Scalar();
  std::error_code ec;
  if (fs::path(node.Scalar()).is_relative() && fs::is_regular_file(beside, ec)) {
    return beside.string();
  }
  try {
    return resolve(node.Scalar());
  } catch (const std::exception& e) {
    source.failWith(key, e.what());
  }
}

// "key=value" overrides from a map of dotted keys to values, in file order.
std::vector<std::string> overridesOf(const YAML::Node& node, const std::string& key,
                                     const Source& source) {
  std::vector<std::string> overrides;
  if (!node.IsDefined() || node.IsNull()) return overrides;
  if (!node.IsMap()) source.fail(key, "a map of dotted scenario keys to values", node);
  for (const auto& item : node) {
    if (!item.first.IsScalar() || item.first.Scalar().empty()) {
      source.fail(key, "keys that are dotted scenario paths", item.first);
    }
    overrides.push_back(item.first.Scalar() + "=" + flowText(item.second));
  }
  return overrides;
}

// A world as the file gives it: its name, and a scenario file or a generator with parameters.
struct WorldSpec {
  std::string name;
  std::string key;              // "worlds[i]"
  std::string scenario_path;    // a scenario world, else empty
  std::string generator;        // a generated world, else empty
  YAML::Node parameters;
  YAML::Node goal;              // entries replacing the goal's (may be undefined)
};

// What makes comparison run i from i alone (shared by every copy of the study's run list).
struct ComparisonExpansion {
  std::string path, robots_dir;
  std::vector<WorldSpec> worlds;
  std::vector<std::string> variants;
  std::vector<std::vector<std::string>> variant_overrides;
  std::vector<std::string> common;  // set:
  std::vector<int> seeds;
  YAML::Node base;  // of the generated worlds
  int digits = 1;
  std::shared_ptr<qp::HessianFactorCache> hessian_factors;
  // yaml-cpp nodes are not thread-safe, not even to read or to assign from: the base, the
  // worlds' parameters and goals are shared by every run, so a scenario's text is built under
  // this lock (cheap); parsing and checking it (loadScenarioText) run in parallel.
  mutable std::mutex shared_nodes;

  // Worlds slowest, then variants, then seeds.
  ComparisonRun cell(std::size_t index) const {
    const std::size_t per_world = variants.size() * seeds.size();
    return {index / per_world, (index / seeds.size()) % variants.size(), seeds[index % seeds.size()]};
  }

  StudyRun make(std::size_t index, bool with_scenario) const {
    const ComparisonRun c = cell(index);
    StudyRun run;
    run.index = index;
    char number[32];
    std::snprintf(number, sizeof number, "%0*d", digits, c.seed);
    run.name = worlds[c.world].name + "." + variants[c.variant] + "." + number;
    SweptValue world_value, variant_value, seed_value;
    world_value.key = "world";
    world_value.value = worlds[c.world].name;
    variant_value.key = "variant";
    variant_value.value = variants[c.variant];
    seed_value.key = "seed";
    seed_value.value = std::to_string(c.seed);
    seed_value.numeric = true;
    seed_value.number = c.seed;
    run.swept = {world_value, variant_value, seed_value};
    if (with_scenario) loadScenarioOf(&run, c);
    return run;
  }

  void loadScenarioOf(StudyRun* run, const ComparisonRun& c) const {
    const Source source(path);
    const WorldSpec& world = worlds[c.world];
    const std::string described = "world '" + world.name + "', variant '" + variants[c.variant] +
                                  "', seed " + std::to_string(c.seed);
    try {
      YAML::Node scenario;
      std::string origin, text;
      std::unique_lock<std::mutex> lock(shared_nodes);
      if (world.generator.empty()) {
        origin = world.scenario_path;
        scenario = detail::parseYamlText(detail::readTextFile(origin, "scenario file"), origin);
      } else {
        origin = path + ":" + world.key;
        scenario = YAML::Clone(base);
        const detail::GeneratedWorld generated =
            detail::generateWorld(world.generator, world.parameters,
                                  detail::childKey(world.key, world.generator), c.seed, source);
        scenario["obstacles"] = generated.obstacles;
        YAML::Node goal = scenario["goal"].IsMap() ? scenario["goal"] : YAML::Node();
        goal["position"] = YAML::Node(YAML::NodeType::Sequence);
        goal["position"].push_back(generated.goal.x());
        goal["position"].push_back(generated.goal.y());
        goal["position"].SetStyle(YAML::EmitterStyle::Flow);
        scenario["goal"] = goal;
      }
      if (world.goal.IsDefined()) {
        for (const auto& item : world.goal)
          scenario["goal"][item.first.Scalar()] = YAML::Clone(item.second);
      }
      text = YAML::Dump(scenario) + "\n";
      scenario = YAML::Node();  // released under the lock: its memory is shared with the base
      lock.unlock();
      std::vector<std::string> overrides = common;
      for (const std::string& entry : variant_overrides[c.variant]) overrides.push_back(entry);
      overrides.push_back("planner.seed=" + std::to_string(c.seed));
      overrides.push_back("name=" + run->name);
      run->scenario = loadScenarioText(text, origin, overrides, robots_dir);
      run->scenario.walking.validate();
      run->scenario.request.validate();
      for (std::string& warning : run->scenario.warnings) {
        warning = path + ": " + described + ": " + detail::renameOverrides(warning, "override");
      }
    } catch (const std::exception& e) {
      // The loader calls the variant's and `set`'s keys --set overrides.
      throw InputError(path + ": " + described + ": " +
                       detail::renameOverrides(detail::oneLine(e.what()), "override"));
    }
    run->scenario.request.generator.hessian_factors = hessian_factors;
  }
};

WorldSpec readWorld(const YAML::Node& node, std::size_t index, const std::string& path,
                    const BaseResolver& resolve, const Source& source) {
  WorldSpec world;
  world.key = detail::indexKey("worlds", index);
  std::vector<std::string> known = {"name", "scenario", "goal"};
  for (const std::string& generator : detail::worldGeneratorNames()) known.push_back(generator);
  if (node.IsMap()) {
    // An unknown key that is not a world's name, scenario or goal: most likely a generator.
    for (const auto& item : node) {
      const std::string name = item.first.IsScalar() ? item.first.Scalar() : "";
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        source.failWith(detail::childKey(world.key, name),
                        "unknown world generator or key '" + name + "'" +
                            wpg::didYouMean(name, known) +
                            "; expected name, goal, and scenario or one of the generators " +
                            detail::joinNames(detail::worldGeneratorNames()));
      }
    }
  }
  const detail::Entries entries =
      detail::readMap(node, world.key, known,
                      "a world: a map with name, and scenario or a generator", source);
  world.name = detail::readName(detail::entry(entries, "name"), detail::childKey(world.key, "name"),
                                "a world name (at most 32 letters, digits, _ - .)", source,
                                kMaxStudyNameLength);
  std::vector<std::string> kinds;
  if (detail::present(entries, "scenario")) kinds.push_back("scenario");
  for (const std::string& generator : detail::worldGeneratorNames()) {
    if (entries.count(generator)) kinds.push_back(generator);
  }
  if (kinds.size() != 1) {
    source.failWith(world.key, "expected one of scenario, " +
                                   detail::joinNames(detail::worldGeneratorNames()) + ", got " +
                                   (kinds.empty() ? std::string("none") : detail::joinNames(kinds)));
  }
  if (kinds.front() == "scenario") {
    world.scenario_path = findScenario(detail::entry(entries, "scenario"),
                                       detail::childKey(world.key, "scenario"), path, resolve, source);
  } else {
    world.generator = kinds.front();
    world.parameters = detail::entry(entries, world.generator);
  }
  world.goal = detail::entry(entries, "goal");
  if (world.goal.IsDefined() && !world.goal.IsMap()) {
    source.fail(detail::childKey(world.key, "goal"), "a goal map (datasets/SCENARIOS.md)", world.goal);
  }
  return world;
}

std::vector<int> readSeeds(const YAML::Node& node, const Source& source) {
  std::vector<int> seeds;
  if (node.IsDefined() && node.IsSequence()) {
    std::set<int> seen;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const int seed = detail::readInteger(node[i], detail::indexKey("seeds", i), 0,
                                           "a seed: an integer >= 0", source);
      if (!seen.insert(seed).second) {
        source.failWith(detail::indexKey("seeds", i), "seed " + std::to_string(seed) + " is given twice");
      }
      seeds.push_back(seed);
    }
    if (seeds.empty()) source.failWith("seeds", "expected a positive count or a non-empty list of seeds");
    return seeds;
  }
  const int count = detail::readInteger(node, "seeds", 1,
                                        "a positive count (seeds 1..count) or a list of seeds", source);
  if (static_cast<std::size_t>(count) > kMaxStudyRuns) {
    source.failWith("seeds", "expected at most " + std::to_string(kMaxStudyRuns) +
                                 " seeds (the most runs of a study), got " + std::to_string(count));
  }
  for (int seed = 1; seed <= count; ++seed) seeds.push_back(seed);
  return seeds;
}

}  // namespace

ComparisonStudy loadComparisonStudy(const std::string& path, const BaseResolver& resolve_base,
                                    const std::string& robots_dir, int threads) {
  ComparisonStudy comparison;
  Study& study = comparison.study;
  study.source_path = path;
  study.created_by = "wpg compare";
  study.slices_hold_every_row = true;
  const Source source(path);
  const YAML::Node root = detail::readYamlFile(path, "study file");
  study.text = detail::readTextFile(path, "study file");
  const detail::Entries top = detail::readMap(
      root, "", {"name", "base", "seeds", "set", "worlds", "variants"},
      "a comparison study: a map with name, base, seeds, set, worlds and variants", source);
  study.name = detail::readName(detail::entry(top, "name"), "name",
                                "a study name (at most 32 letters, digits, _ - .)", source,
                                kMaxStudyNameLength);
  comparison.seeds = readSeeds(detail::entry(top, "seeds"), source);
  const std::vector<std::string> common = overridesOf(detail::entry(top, "set"), "set", source);

  const YAML::Node worlds_node = detail::entry(top, "worlds");
  if (!worlds_node.IsDefined() || !worlds_node.IsSequence() || worlds_node.size() == 0) {
    source.fail("worlds", "a non-empty list of worlds", worlds_node);
  }
  std::vector<WorldSpec> worlds;
  for (std::size_t i = 0; i < worlds_node.size(); ++i) {
    worlds.push_back(readWorld(worlds_node[i], i, path, resolve_base, source));
    for (std::size_t j = 0; j < i; ++j) {
      if (worlds[j].name == worlds[i].name) {
        source.failWith(detail::childKey(worlds[i].key, "name"),
                        "world '" + worlds[i].name + "' is named twice");
      }
    }
    comparison.worlds.push_back(worlds[i].name);
  }

  // The base of the generated worlds (their obstacles and goal replace its own).
  YAML::Node base;
  bool has_base = true;
  std::string base_origin;
  const YAML::Node base_node = detail::entry(top, "base");
  if (base_node.IsDefined() && base_node.IsMap()) {
    base = YAML::Clone(base_node);
    base_origin = path + ":base";
  } else if (base_node.IsDefined()) {
    base_origin = findScenario(base_node, "base", path, resolve_base, source);
    base = detail::parseYamlText(detail::readTextFile(base_origin, "base scenario"), base_origin);
  } else {
    has_base = false;
  }
  for (const WorldSpec& world : worlds) {
    if (!world.generator.empty() && !has_base) {
      source.failWith("base", "expected the scenario the generated worlds start from (world '" +
                                  world.name + "' is generated), got none");
    }
  }

  const YAML::Node variants_node = detail::entry(top, "variants");
  if (!variants_node.IsDefined() || !variants_node.IsMap() || variants_node.size() == 0) {
    source.fail("variants", "a non-empty map of variant names to maps of scenario keys", variants_node);
  }
  std::vector<std::vector<std::string>> variant_overrides;
  for (const auto& item : variants_node) {
    const std::string name = detail::readName(item.first, "variants",
                                              "a variant name (at most 32 letters, digits, _ - .)",
                                              source, kMaxStudyNameLength);
    for (const std::string& known : comparison.variants) {
      if (known == name) source.failWith("variants", "variant '" + name + "' is named twice");
    }
    comparison.variants.push_back(name);
    variant_overrides.push_back(
        overridesOf(item.second, detail::childKey("variants", name), source));
  }
  // Generator parameters are checked once, before any scenario is loaded.
  for (const WorldSpec& world : worlds) {
    if (!world.generator.empty()) {
      (void)detail::generateWorld(world.generator, world.parameters,
                                  detail::childKey(world.key, world.generator),
                                  comparison.seeds.front(), source);
    }
  }

  // worlds x variants x seeds, within the cap (each factor is at most the cap: no wrap).
  const std::size_t cells = worlds.size() * comparison.variants.size();
  if (cells > kMaxStudyRuns / comparison.seeds.size()) {
    source.failWith("seeds", "expected at most " + std::to_string(kMaxStudyRuns) + " runs, got " +
                                 std::to_string(worlds.size()) + " worlds x " +
                                 std::to_string(comparison.variants.size()) + " variants x " +
                                 std::to_string(comparison.seeds.size()) + " seeds");
  }
  study.keys = {"world", "variant", "seed"};
  study.key_numeric = {false, false, true};
  auto expansion = std::make_shared<ComparisonExpansion>();
  int widest_seed = 0;
  for (const int seed : comparison.seeds) widest_seed = std::max(widest_seed, seed);
  expansion->digits = static_cast<int>(std::to_string(widest_seed).size());
  expansion->path = path;
  expansion->robots_dir = robots_dir;
  expansion->worlds = worlds;
  expansion->variants = comparison.variants;
  expansion->variant_overrides = variant_overrides;
  expansion->common = common;
  expansion->seeds = comparison.seeds;
  expansion->base = base;
  expansion->hessian_factors = std::make_shared<qp::HessianFactorCache>();
  const std::size_t total = cells * comparison.seeds.size();
  std::set<std::string> run_names;
  for (std::size_t i = 0; i < total; ++i) {
    const ComparisonRun cell = expansion->cell(i);
    comparison.runs.push_back(cell);
    // Names join world, variant and seed with '.', which names may hold too: two cells
    // that give one name ('a.b' x 'c', 'a' x 'b.c') are refused before any walk.
    const std::string name = expansion->make(i, false).name;
    if (!run_names.insert(name).second) {
      source.failWith("variants", "world '" + worlds[cell.world].name + "' x variant '" +
                                      comparison.variants[cell.variant] + "' gives the run name '" +
                                      name + "' of another world x variant (rename one)");
    }
  }
  study.runs = StudyRuns(total, [expansion](std::size_t index, StudyRuns::Make what) {
    const bool scenario = what != StudyRuns::Make::kDescription;
    return expansion->make(index, scenario);
  });
  // Every run checked before any walk: a comparison is at most kMaxStudyRuns runs.
  for (std::size_t i = 0; i < total; ++i) study.checked_runs.push_back(i);
  checkStudyScenarios(&study, threads);
  return comparison;
}

}  // namespace wpg::datasets
