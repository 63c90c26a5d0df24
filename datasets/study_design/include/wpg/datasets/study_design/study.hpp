#pragma once
// A study (`wpg batch STUDY.yaml`): a base scenario and a sweep of its keys, expanded into one
// resolved scenario per run. Keys are the dotted paths of `wpg run --set` (scenario.hpp), so
// anything a scenario holds can be swept. File format: datasets/SCENARIOS.md, section "Studies".
//
//   name: speeds                      # runs are named <name>_<index>
//   base: walk_forward                # a shipped name, a scenario file, or an inline map
//   sweep:
//     grid: {"reference[1].v": [[0.1, 0, 0], [0.2, 0, 0]], walking.weight_cop: [100.0, 1e3]}
//     zip: {"pushes[0]": [{t: 3.0, force: [0, 40]}, {t: 3.4, force: [0, -40]}]}
//     random: {samples: 5, seed: 1, keys: {"pushes[0].duration": {uniform: [0.05, 0.15]}}}
//
// Runs: every combination of the grid (its first key varies slowest), crossed with the zip's
// entries (walked together), crossed with the random samples (fastest). A missing section
// counts as one point.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"

namespace wpg::datasets {

struct SweptValue {
  std::string key;    // dotted path, e.g. "reference[1].v"
  std::string value;  // the value as one line of YAML (flow style), e.g. "[0.1, 0, 0]"
  bool numeric = false;  // a plain number: `number` holds it
  double number = 0.0;
};

struct StudyRun {
  std::size_t index = 0;
  std::string name;                // <study>_<index>, zero-padded so that names sort by index
  std::vector<SweptValue> swept;   // one per Study::keys, same order
  Scenario scenario;               // base + swept values + name, loaded and validated
};

struct Study {
  std::string name;
  std::string source_path;
  std::string text;               // the study file as read
  std::vector<std::string> keys;  // swept keys: grid, then zip, then random, in file order
  std::vector<StudyRun> runs;
  // A digest of every run's resolved scenario (FNV-1a 64, hex): two studies with the same name
  // and digest run the same scenarios (`wpg batch --resume` checks it).
  std::string fingerprint;
  std::string created_by = "wpg batch";  // the command that expands it (root attribute)
};

// Finds a base given by name or path (`base: walk_forward`): returns a scenario file path;
// throws InputError when there is none. The CLI passes its shipped-scenario lookup.
using BaseResolver = std::function<std::string(const std::string& base)>;

// Reads the study at `path`, expands its sweep and loads every run's scenario (robots from
// `robots_dir`), each validated as `wpg run` does, on `threads` threads (the result does not
// depend on them). A relative `base:` path is looked up next to the study file first, then by
// `resolve_base`.
//
// Throws InputError (one line naming the study file and the key) on: unreadable file, syntax
// error, unknown or missing keys, an empty sweep (no section, or a section or list without
// entries), zip lists of different lengths, a random range that is not [low, high] with
// low <= high, a sweep key the scenario does not have, and a swept value the scenario rejects
// (the message names the run's values).
Study loadStudy(const std::string& path, const BaseResolver& resolve_base,
                const std::string& robots_dir, int threads = 1);

// Loads every run's scenario with `load(run)` on `threads` threads (each run on its own), then
// sets study->fingerprint. `load` throws an exception whose message is the whole error line;
// the one rethrown (as InputError) is the first failing run's, whatever the threads. Shared by
// loadStudy and the comparison studies of `wpg compare` (comparison_study.hpp).
void loadStudyScenarios(Study* study, int threads, const std::function<void(StudyRun& run)>& load);

// The study's seeded generator (SplitMix64, fixed across platforms and compilers, unlike the
// distributions of <random>): a uniform double in [0, 1) from `state`, which it advances.
double nextUniform(std::uint64_t* state);

}  // namespace wpg::datasets
