#pragma once
// The options of each `wpg` subcommand, as the command line gives them (registration.cpp parses
// them with CLI11), and the function that runs it (commands/<name>_command.cpp): it returns the
// exit status (exit_codes.hpp) or throws UsageError / datasets::InputError for bad input.
#include <string>
#include <vector>

#include "data_paths.hpp"

namespace wpg::cli {

struct RunOptions {
  std::string scenario = kDefaultScenario;
  std::string output;                  // empty: out/<scenario name>.h5
  std::vector<std::string> overrides;  // "key=value", applied after the file
  bool plot = true;
  bool replay = false;  // --replay: replay on the multibody model (else the scenario's `replay:`)
  bool filter = false;  // --filter: replay and dynamic filter (else the scenario's `filter:`)
};
int runCommand(const RunOptions& options);

struct ReplayOptions {
  std::string input;   // a dataset written by `wpg run`
  std::string output;  // empty: overwrite the input (atomically)
  bool filter = true;  // --no-filter: replay only
  bool plot = true;
};
int replayCommand(const ReplayOptions& options);

// The shipped scenarios `wpg bench` measures by default: the walk and the paper's experiments.
inline const std::vector<std::string>& defaultBenchScenarios() {
  static const std::vector<std::string> names = {"walk_forward", "paper_experiment_a",
                                                 "paper_experiment_b"};
  return names;
}

struct BenchOptions {
  std::vector<std::string> scenarios = defaultBenchScenarios();
  std::string json;  // empty: no JSON file
};
int benchCommand(const BenchOptions& options);

struct BatchOptions {
  std::string study;   // STUDY.yaml
  std::string output;  // OUT.h5
  int threads = 1;     // -j
  bool resume = false;
  bool plot = true;
  std::string shard;           // --shard K/N, empty: the whole study
  bool threads_given = false;  // -j on the command line (under MPI the default is 1 per rank)
  std::string fields;          // --fields summary,footsteps; empty: the study's fields:
};
int batchCommand(const BatchOptions& options);

// `wpg merge OUT.h5 SHARD...` (batch_index.hpp): the index of shard files, or of every *.h5 of
// a folder given alone; of a comparison's shards (`wpg compare --shard`), with its table.
struct MergeOptions {
  std::string output;
  std::vector<std::string> shards;
  bool copy = false;  // one self-contained file instead of links
  bool plot = true;
};
int mergeCommand(const MergeOptions& options);

struct CompareOptions {
  std::string study;
  std::string output;  // the folder: study.h5, summary.csv, summary.md, figures
  int threads = 1;
  bool plot = true;
  bool threads_given = false;  // -j on the command line (under MPI the default is 1 per rank)
  std::string ompl_log;        // --ompl-log DIR: OMPL benchmark logs, one per world
  bool resume = false;         // finish DIR/study.h5 (or the slice's shard) of the same study
  std::string shard;           // --shard K/N, empty: the whole study
};
int compareCommand(const CompareOptions& options);

// `wpg robot check DIR` (wpg/engine/robot_check.hpp): DIR a robot folder, or the name of one of
// the robots directory.
struct RobotCheckOptions {
  std::string folder;
};
int robotCheckCommand(const RobotCheckOptions& options);

struct AnalyzeOptions {
  std::string input;               // a run or batch file
  std::string format = "table";    // table, csv or json
};
int analyzeCommand(const AnalyzeOptions& options);

// `wpg diff`: exit 0 when A and B agree within the tolerances, 1 when they differ, 2 bad input.
struct DiffOptions {
  std::string a, b;               // run or batch files
  double rtol = 1e-9;             // |a - b| <= atol + rtol * max(|a|, |b|)
  double atol = 1e-9;             // datasets/references/README.md says why
  bool ignore_wall_time = true;   // leave out mpc/solve_time, timing/, plans' planning times...
  std::vector<std::string> ignore_patterns;  // --ignore PATTERN (fnmatch on the field's path)
};
int diffCommand(const DiffOptions& options);

struct PushSweepOptions {
  std::string situation = "both";      // forward, on_spot or both
  int phases = 8;                      // K phases over one steady step
  int threads = 1;                     // -j
  std::string json;                    // empty: no JSON list
  std::string output = "out/push_sweep.h5";
  std::vector<std::string> overrides;  // --set, applied to each situation's base scenario
  double max_force = 600.0;            // [N] upper end of the bisection (above every force we found, 490 N)
  double tolerance = 2.5;              // [N] bracket width at which it stops
  double max_swing_speed = 2.0;        // [m/s] swing-foot limits of "recovered" (0: unchecked)
  double max_swing_acceleration = 50.0;  // [m/s^2]
  bool plot = true;
};
int pushSweepCommand(const PushSweepOptions& options);

struct PlotOptions {
  std::string input;
  std::string output;  // empty: the input with its extension replaced by .png (.RUN.png with --run)
  std::string run;     // --run NAME: that run of a file with several
  bool plan = false;   // --plan: predicted against executed (the NMPC's plans, mpc/plan/)
  std::vector<double> at;  // --at T...: with --plan, the iterations at these times [s]
};
int plotCommand(const PlotOptions& options);

// `wpg view FILE.h5 [--run NAME] [-o PAGE.html]` and `wpg view DIR`: an HTML page to watch a
// run (its robot, footsteps, obstacles, plots) or to explore a study (docs/viewer.md). Exit 0,
// or 2 on bad input (nothing written) and when the viewer bundle is missing.
struct ViewOptions {
  std::string input;   // a run file, a batch file, or the folder of `wpg compare`
  std::string run;     // --run NAME: one run of a batch file
  std::string output;  // -o PAGE.html; empty: beside the input
};
int viewCommand(const ViewOptions& options);

}  // namespace wpg::cli
