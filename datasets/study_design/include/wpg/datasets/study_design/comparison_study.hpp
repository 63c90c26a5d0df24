#pragma once
// A comparison study (`wpg compare STUDY.yaml`): worlds x variants x seeds, every combination a
// walk to a goal, expanded into a Study (study.hpp) so that the batch writer and runner serve
// it as they serve `wpg batch`. File format: datasets/SCENARIOS.md, "Comparison studies".
//
//   name: planners
//   base: {robot: hrp2, duration: 90, generator: {algorithm: nmpc}}   # for generated worlds
//   seeds: 10                                  # 1..10, or a list of integers
//   set: {planner.time_limit: 1.0}             # optional, applied to every run
//   worlds:
//     - {name: cluttered, scenario: goal_cluttered}
//     - {name: field, random_field: {count: 10, seed: 1, area: [1, 5, -1.5, 1.5],
//                                    radius: [0.15, 0.3], margin: 0.15}}
//     - {name: trap, u_trap: {}}
//   variants:
//     rrtconnect_nmpc: {planner.algorithm: rrtconnect}
//     nmpc_only: {planner.algorithm: none}
//
// Runs: worlds slowest, then variants, then seeds. The seed goes to planner.seed and to the
// random worlds (a random_field is drawn from its own seed + the run's seed). Each run's
// swept values are world (name), variant (name) and seed.
#include <string>
#include <vector>

#include "wpg/datasets/study_design/study.hpp"

namespace wpg::datasets {

struct ComparisonRun {
  std::size_t world = 0;    // index into ComparisonStudy::worlds
  std::size_t variant = 0;  // index into ComparisonStudy::variants
  int seed = 0;
};

struct ComparisonStudy {
  Study study;                        // runs in the order of `runs`, created_by "wpg compare"
  std::vector<std::string> worlds;    // names, file order
  std::vector<std::string> variants;  // names, file order
  std::vector<int> seeds;
  std::vector<ComparisonRun> runs;    // one per study.runs entry
};

// Reads, expands and loads the study at `path` (each run validated as `wpg run` does, on
// `threads` threads; the result does not depend on them). A `scenario:` world or `base:` given
// by name is looked up next to the study file first, then by `resolve_base`.
//
// Throws InputError (one line naming the file and the key) on: unreadable file, syntax error,
// unknown or missing keys, no worlds or no variants, repeated names, an unknown world
// generator, generator parameters out of range (count >= 1, radius low <= high, area
// x_min < x_max...), a random field that cannot place its obstacles clear of start and goal,
// a generated world without `base`, seeds not a positive count or a list of integers >= 0,
// and a variant key or value the scenario rejects (the message names the world, variant and
// seed).
ComparisonStudy loadComparisonStudy(const std::string& path, const BaseResolver& resolve_base,
                                    const std::string& robots_dir, int threads = 1);

}  // namespace wpg::datasets
