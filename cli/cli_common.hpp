#pragma once
// Shared pieces of the `wpg` executable that do not need CLI11 (main.cpp is the only
// translation unit that includes CLI11: it is the slowest header of the project to compile).
#include <stdexcept>
#include <string>
#include <vector>

namespace wpg::cli {

// Exit codes of every subcommand.
constexpr int kExitSuccess = 0;
constexpr int kExitRunFailed = 1;  // the walk was generated but some NMPC iteration failed
constexpr int kExitBadInput = 2;   // bad scenario, option or file: nothing was written
// Could not complete for want of a resource or an I/O error (out of memory, disk full, a write
// that failed): nothing was written (the temporary output is removed).
constexpr int kExitIncomplete = 3;

// A user mistake detected by the CLI itself (bad option value, missing file): exit 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// --- where the data lives -----------------------------------------------------------------
// The folder holding robots/, datasets/scenarios/ and analysis/: $WPG_DATA_DIR when set and
// non-empty, else the source tree the executable was built from when it still exists, else
// the installed share/wpg.
std::string dataDirectory();
std::string robotsDirectory();
std::string scenariosDirectory();
std::string plotScriptPath();

// The name of the default scenario (datasets/scenarios/<name>.yaml).
constexpr const char* kDefaultScenario = "walk_forward";

// Names of the shipped scenarios (file stems of datasets/scenarios/*.yaml), sorted.
std::vector<std::string> shippedScenarioNames();

// A SCENARIO argument is an existing file path, or the name of a shipped scenario (with or
// without ".yaml"). Returns the file path; throws UsageError naming the argument otherwise.
std::string resolveScenarioPath(const std::string& argument);

// --- subcommands ------------------------------------------------------------------------------
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
};
int batchCommand(const BatchOptions& options);
// OUT.summary.csv/.md (and .png with `plot`) beside a batch file or index; prints "wrote ...";
// kExitRunFailed when a run failed.
int finishBatchFile(const std::string& batch_file, bool plot);

// `wpg merge OUT.h5 SHARD...` (batch_index.hpp): the index of shard files, or of every *.h5 of
// a folder given alone.
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
};
int compareCommand(const CompareOptions& options);

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
  bool plot = true;
};
int pushSweepCommand(const PushSweepOptions& options);

struct PlotOptions {
  std::string input;
  std::string output;  // empty: the input with its extension replaced by .png (.RUN.png with --run)
  std::string run;     // --run NAME: that run of a file with several
};
int plotCommand(const PlotOptions& options);

// Runs /usr/bin/python3 <plot script> run_file -o figure_file; returns its exit status
// (kExitBadInput with a message on stderr when Python or its modules are missing).
int drawFigure(const std::string& run_file, const std::string& figure_file,
               const std::string& run = "");
// Runs /usr/bin/python3 script arguments... (the same checks and messages as drawFigure).
int runAnalysisScript(const std::string& script, const std::vector<std::string>& arguments);

// The one-line error format of every subcommand: "wpg: error: <message>".
void printError(const std::string& message);
void printWarning(const std::string& message);

}  // namespace wpg::cli
