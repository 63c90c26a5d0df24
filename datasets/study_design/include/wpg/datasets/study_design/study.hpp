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
// counts as one point. The runs are not listed: run i is computed from i when it is asked for
// (study_runs.hpp).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/datasets/study_design/run_fields.hpp"
#include "wpg/datasets/study_design/study_runs.hpp"

namespace wpg::datasets {

struct Study {
  std::string name;
  std::string source_path;
  std::string text;               // the study file as read
  std::vector<std::string> keys;  // swept keys: grid, then zip, then random, in file order
  // Per key: every value it takes is a plain number (its summary column holds numbers).
  std::vector<bool> key_numeric;
  StudyRuns runs;  // computed one at a time from their index
  // The runs whose scenarios were loaded and checked before any work (checkedRuns), in order,
  // what the engine checks further of them, and their warnings.
  std::vector<std::size_t> checked_runs;
  struct CheckedRun {
    std::size_t index = 0;
    std::string robot;
    bool replay = false;  // replayed on the multibody model (its robot model is loaded)
    bool goal = false;    // a walk to a goal
  };
  std::vector<CheckedRun> checked;
  std::vector<std::string> warnings;
  // A digest of the checked runs' resolved scenarios (FNV-1a 64, hex): two studies with the
  // same name and digest run the same scenarios (`wpg batch --resume` checks it). When every
  // run is checked it is the digest of every run's scenario.
  std::string fingerprint;
  std::string created_by = "wpg batch";
  // What each run stores (`fields:`; run_fields.hpp): every field unless the study names some.
  // Not part of the fingerprint: a batch file records it (root attribute `fields`), and
  // `--resume` and `wpg merge` compare it.
  RunFields fields = RunFields::all();
  // A slice's shard holds a row of every run (else its runs' rows only): a comparison's, so
  // that `wpg merge` reads the worlds, variants and seeds from any one shard.
  bool slices_hold_every_row = false;  // the command that expands it (root attribute)
};

// Finds a base given by name or path (`base: walk_forward`): returns a scenario file path;
// throws InputError when there is none. The CLI passes its shipped-scenario lookup.
using BaseResolver = std::function<std::string(const std::string& base)>;

// Reads the study at `path`, parses its base scenario once and checks its runs' scenarios
// (robots from `robots_dir`), each validated as `wpg run` does, on `threads` threads (the
// result does not depend on them): every run of a study of at most kCheckedStudyRuns runs; of
// a larger one, run 0, the runs that take each grid value and each zip entry once, and the
// first random samples, kCheckedStudyRuns in all (checkedRuns). A relative `base:` path is
// looked up next to the study file first, then by `resolve_base`.
//
// Throws InputError (one line naming the study file and the key) on: unreadable file, syntax
// error, unknown or missing keys, an empty sweep (no section, or a section or list without
// entries), zip lists of different lengths, a random range that is not [low, high] with
// low <= high, a sweep key the scenario does not have, more than kMaxSweepRuns runs, and a
// swept value the scenario rejects in a checked run (the message names the run's values); a
// run not checked throws it when study.runs[i] loads it.
Study loadStudy(const std::string& path, const BaseResolver& resolve_base,
                const std::string& robots_dir, int threads = 1);

// The runs checked before any work: how many at most, and which (in order) for a sweep of
// `grid` (values per key, first key slowest), `zip_points` entries and `random_points` samples.
constexpr std::size_t kCheckedStudyRuns = 256;
std::vector<std::size_t> checkedRuns(const std::vector<std::size_t>& grid, std::size_t zip_points,
                                     std::size_t random_points);

// Loads the scenarios of `study->checked_runs` (study->runs[i]) on `threads` threads, then sets
// study->warnings and study->fingerprint. The error rethrown (as InputError) is the first
// failing run's, whatever the threads. Shared by loadStudy and the comparison studies of
// `wpg compare` (comparison_study.hpp).
void checkStudyScenarios(Study* study, int threads);

// The study's seeded generator (SplitMix64, fixed across platforms and compilers, unlike the
// distributions of <random>): a uniform double in [0, 1) from `state`, which it advances.
double nextUniform(std::uint64_t* state);
// Draw `n` (from 0) of the generator seeded with `seed`, computed from n alone: the value the
// (n + 1)-th nextUniform call from state `seed` returns (SplitMix64 is a counter, mixed).
double uniformAt(std::uint64_t seed, std::uint64_t n);

}  // namespace wpg::datasets
