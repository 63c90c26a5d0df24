// The subcommands' options on the command line (registration.hpp). The one file besides
// main.cpp that includes CLI11, the slowest header of the project to compile.
#include "registration.hpp"

#include <algorithm>
#include <memory>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "command_options.hpp"
#include "data_paths.hpp"

namespace wpg::cli {
namespace {

// An option struct with the flags that negate one of its fields (--no-plot, --no-filter).
template <typename Options>
struct Parsed {
  Options options;
  bool no_plot = false;
  bool no_filter = false;
};

// `command(options)` once `sub` is parsed, with `finish(parsed)` applied first.
template <typename Options, typename Finish>
void runWhenParsed(CLI::App* sub, CommandAction& action, std::shared_ptr<Parsed<Options>> parsed,
                   int (*command)(const Options&), Finish finish) {
  sub->callback([sub, &action, parsed, command, finish] {
    finish(*parsed, *sub);
    action = [parsed, command] { return command(parsed->options); };
  });
}

// The footer of a subcommand's --help: the exit codes that subcommand returns (read from its
// code paths; docs/commands.md, "Exit codes", has the same table), then where the data is.
// Items are "N meaning", separated by ", ": tests/cli/help_exit_codes.sh reads them.
void setExitCodes(CLI::App* sub, const std::string& codes) {
  sub->footer("Exit codes: " + codes + ".\nData (robots, scenarios, plot script): " +
              dataDirectory() + " (set WPG_DATA_DIR to use another).");
}

// The meaning of exit 3 for a subcommand that writes files, and for one that only reads.
const char* const kIncompleteWriting =
    "3 could not complete (out of memory, I/O error; no output file written)";
const char* const kIncompleteReading = "3 could not complete (out of memory)";

int defaultThreads() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

}  // namespace

void registerRunCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<RunOptions>>();
  RunOptions& run = parsed->options;
  CLI::App* run_app = app.add_subcommand(
      "run", "Generate one walk from a scenario (default: walk_forward); write the HDF5 dataset and its figure.");
  std::string shipped;
  for (const std::string& name : shippedScenarioNames()) shipped += (shipped.empty() ? "" : ", ") + name;
  run_app
      ->add_option("scenario", run.scenario,
                   "Scenario file, or the name of a shipped scenario (" +
                       (shipped.empty() ? std::string("none found") : shipped) + ")")
      ->type_name("SCENARIO");
  run_app->add_option("-o,--output", run.output, "HDF5 dataset to write; the figure goes next to it (.png)")
      ->default_str("out/<scenario name>.h5")
      ->type_name("OUT.h5");
  run_app->add_option("--set", run.overrides,
                      "Override a scenario field after loading, key=value (repeatable), e.g. "
                      "--set duration=5")
      ->type_name("KEY=VALUE")
      ->default_str("");
  run_app->add_flag("--no-plot", parsed->no_plot, "Do not draw the figure");
  run_app->add_flag("--replay", run.replay,
                    "Replay the walk on the robot's multibody model (the URDF of its walking.yaml's multibody: "
                    "walking IK, Simbody inverse dynamics, multibody ZMP). Default: the "
                    "scenario's `replay:` key (false)");
  run_app->add_flag("--filter", run.filter,
                    "Replay and run the dynamic filter (Kajita preview control on the ZMP error, "
                    "paper Sec. IV) with the scenario's filter_settings; implies --replay. "
                    "Default: the scenario's `filter:` key (false)");
  setExitCodes(run_app,
               "0 success, 1 the walk failed or ended blocked (dataset still written), 2 bad input "
               "(nothing written), " +
                   std::string(kIncompleteWriting));
  runWhenParsed(run_app, action, parsed, &runCommand,
                [](Parsed<RunOptions>& p, CLI::App&) { p.options.plot = !p.no_plot; });
}

void registerReplayCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<ReplayOptions>>();
  ReplayOptions& replay = parsed->options;
  CLI::App* replay_app = app.add_subcommand(
      "replay",
      "Replay an existing run dataset on the robot's multibody model with the dynamic filter; "
      "write it again with the multibody fields (q, zmp_multibody, com_filtered, ...).");
  replay_app->add_option("run_file", replay.input, "HDF5 dataset written by `wpg run`")
      ->required()
      ->type_name("RUN.h5");
  replay_app->add_option("-o,--output", replay.output, "HDF5 dataset to write; the figure goes next to it (.png)")
      ->default_str("RUN.h5, overwritten atomically")
      ->type_name("OUT.h5");
  replay_app->add_flag("--no-filter", parsed->no_filter,
                       "Replay only: the multibody ZMP of the walk as generated, no dynamic filter");
  replay_app->add_flag("--no-plot", parsed->no_plot, "Do not draw the figure");
  setExitCodes(replay_app,
               "0 success (a walk that had failed is replayed as it walked), 2 bad input, a walk "
               "the multibody replay cannot follow included (nothing written), " +
                   std::string(kIncompleteWriting));
  runWhenParsed(replay_app, action, parsed, &replayCommand,
                [](Parsed<ReplayOptions>& p, CLI::App&) {
                  p.options.filter = !p.no_filter;
                  p.options.plot = !p.no_plot;
                });
}

void registerBenchCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<BenchOptions>>();
  BenchOptions& bench = parsed->options;
  CLI::App* bench_app = app.add_subcommand(
      "bench",
      "Time the control chain (NMPC + IK + multibody ZMP + dynamic filter) per NMPC iteration "
      "on scenarios, as the paper's Sec. V-C table; writes nothing but --json.");
  std::string default_bench;
  for (const std::string& name : defaultBenchScenarios()) {
    default_bench += (default_bench.empty() ? "" : " ") + name;
  }
  bench_app->add_option("scenarios", bench.scenarios, "Scenario files or shipped scenario names")
      ->default_str(default_bench)
      ->type_name("SCENARIO...");
  bench_app->add_option("--json", bench.json, "Also write the numbers to this JSON file")
      ->default_str("none")
      ->type_name("FILE");
  setExitCodes(
      bench_app,
      "0 every walk succeeded, 1 a walk failed (its timings are still printed), 2 bad input "
      "(nothing measured), " +
          std::string(kIncompleteWriting));
  runWhenParsed(bench_app, action, parsed, &benchCommand, [](Parsed<BenchOptions>&, CLI::App&) {});
}

void registerBatchCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<BatchOptions>>();
  BatchOptions& batch = parsed->options;
  batch.threads = defaultThreads();
  CLI::App* batch_app = app.add_subcommand(
      "batch",
      "Run a study (a base scenario and a sweep of its keys, datasets/SCENARIOS.md) on worker "
      "threads into one HDF5 file, with OUT.summary.csv/.md/.png beside it.");
  batch_app->add_option("study", batch.study, "Study file (YAML)")->required()->type_name("STUDY.yaml");
  batch_app->add_option("-o,--output", batch.output, "Batch file to write (or to finish with --resume)")
      ->required()
      ->type_name("OUT.h5");
  batch_app->add_option("-j,--jobs", batch.threads, "Worker threads (per rank under MPI)")
      ->default_str("the number of cores; 1 per rank under MPI")
      ->type_name("N");
  batch_app->add_flag("--resume", batch.resume,
                      "Finish OUT.h5 of the same study: run only the runs it does not hold yet "
                      "(refused, exit 2, when it holds another study; a missing OUT.h5 is "
                      "started)");
  batch_app->add_flag("--no-plot", parsed->no_plot, "Do not draw the summary figure");
  batch_app->add_option("--shard", batch.shard,
                        "Run only slice K of N (runs i with i mod N = K, 0 <= K < N) into OUT.h5, "
                        "a shard file; join the shards with `wpg merge` (README, \"Running on a "
                        "cluster\")")
      ->type_name("K/N");
  batch_app->add_option("--fields", batch.fields,
                        "What each run stores, instead of the study's fields: (summary, com, cop, "
                        "feet, footsteps, mpc, plan, obstacles, goal, multibody or all; "
                        "datasets/SCHEMA.md, \"Lean runs\")")
      ->type_name("F1,F2,...");
  setExitCodes(
      batch_app,
      "0 every run succeeded, 1 some walk failed (exit_status in the file says which), 2 bad "
      "input (nothing written), " +
          std::string(kIncompleteWriting));
  runWhenParsed(batch_app, action, parsed, &batchCommand,
                [](Parsed<BatchOptions>& p, CLI::App& sub) {
                  p.options.plot = !p.no_plot;
                  p.options.threads_given = sub.count("--jobs") > 0;
                });
}

void registerMergeCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<MergeOptions>>();
  MergeOptions& merge = parsed->options;
  CLI::App* merge_app = app.add_subcommand(
      "merge",
      "Join the shard files of a study (`wpg batch --shard K/N`, or the OUT.shards/ folder of an "
      "MPI batch) into OUT.h5, a batch file whose runs link into the shards (relative HDF5 "
      "external links), with OUT.summary.csv/.md/.png; the shards of a comparison (`wpg compare "
      "--shard K/N`) into its study file, with /compare/summary and the files of `wpg compare` "
      "beside it (exit status as `wpg compare`).");
  merge_app->add_option("output", merge.output, "Index file to write")->required()->type_name("OUT.h5");
  merge_app->add_option("shards", merge.shards, "Shard files, or a folder of them")
      ->required()
      ->type_name("SHARD...");
  merge_app->add_flag("--copy", merge.copy, "Copy the runs into OUT.h5 (one self-contained file) instead of linking them");
  merge_app->add_flag("--no-plot", parsed->no_plot, "Do not draw the summary figure");
  setExitCodes(merge_app,
               "0 every run succeeded, 1 some walk in the shards failed, 2 bad input (a run in no "
               "shard, shards of another study: nothing written), " +
                   std::string(kIncompleteWriting));
  runWhenParsed(merge_app, action, parsed, &mergeCommand,
                [](Parsed<MergeOptions>& p, CLI::App&) { p.options.plot = !p.no_plot; });
}

void registerCompareCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<CompareOptions>>();
  CompareOptions& compare = parsed->options;
  compare.threads = defaultThreads();
  CLI::App* compare_app = app.add_subcommand(
      "compare",
      "Run a comparison study (worlds x variants x seeds of walks to a goal, "
      "datasets/SCENARIOS.md) on worker threads: DIR/study.h5, DIR/summary.csv/.md (one row per "
      "world x variant) and figures.");
  compare_app->add_option("study", compare.study, "Comparison study file (YAML)")
      ->required()
      ->type_name("STUDY.yaml");
  compare_app->add_option("-o,--output", compare.output, "Folder to write")
      ->required()
      ->type_name("DIR");
  compare_app->add_option("-j,--jobs", compare.threads, "Worker threads (per rank under MPI)")
      ->default_str("the number of cores; 1 per rank under MPI")
      ->type_name("N");
  compare_app->add_flag("--resume", compare.resume,
                        "Finish DIR/study.h5 of the same study: run only the runs it does not "
                        "hold yet (refused, exit 2, when it holds another study; a missing file is "
                        "started)");
  compare_app->add_option("--shard", compare.shard,
                          "Run only slice K of N (runs i with i mod N = K, 0 <= K < N) into "
                          "DIR/study.shards/slice-K-of-N.h5; join the slices with `wpg merge "
                          "DIR/study.h5 DIR/study.shards` (docs/studies.md)")
      ->type_name("K/N");
  compare_app->add_flag("--no-plot", parsed->no_plot, "Do not draw the figures");
  compare_app->add_option("--ompl-log", compare.ompl_log,
                          "Also write OMPL benchmark logs into DIR, one per world (OMPL's "
                          "ompl_benchmark_statistics.py and Planner Arena read them)")
      ->type_name("DIR");
  setExitCodes(compare_app,
               "0 the study ran (runs that miss the goal are its results), 2 bad input (nothing "
               "written), " +
                   std::string(kIncompleteWriting));
  runWhenParsed(compare_app, action, parsed, &compareCommand,
                [](Parsed<CompareOptions>& p, CLI::App& sub) {
                  p.options.plot = !p.no_plot;
                  p.options.threads_given = sub.count("--jobs") > 0;
                });
}

void registerAnalyzeCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<AnalyzeOptions>>();
  AnalyzeOptions& analyze = parsed->options;
  CLI::App* analyze_app = app.add_subcommand(
      "analyze", "Print the metrics (datasets/METRICS.md) of every run of a run or batch file.");
  analyze_app->add_option("file", analyze.input, "HDF5 file written by `wpg run` or `wpg batch`")
      ->required()
      ->type_name("FILE.h5");
  analyze_app->add_option("--format", analyze.format, "table, csv or json (one object per run)")
      ->type_name("FORMAT");
  setExitCodes(
      analyze_app,
      "0 the metrics are printed, 2 bad input (not a run or batch file, a bad --format), " +
          std::string(kIncompleteReading));
  runWhenParsed(analyze_app, action, parsed, &analyzeCommand,
                [](Parsed<AnalyzeOptions>&, CLI::App&) {});
}

void registerDiffCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<DiffOptions>>();
  DiffOptions& diff = parsed->options;
  CLI::App* diff_app = app.add_subcommand(
      "diff",
      "Compare two run or batch files field by field (every dataset and attribute): print the "
      "first sample beyond the tolerance and each field that differs.");
  diff_app->add_option("a", diff.a, "Reference file (e.g. datasets/references/<scenario>.h5)")
      ->required()
      ->type_name("A.h5");
  diff_app->add_option("b", diff.b, "File to compare with it")->required()->type_name("B.h5");
  diff_app->add_option("--rtol", diff.rtol, "Relative tolerance: |a - b| <= atol + rtol max(|a|, |b|)")
      ->type_name("R");
  diff_app->add_option("--atol", diff.atol, "Absolute tolerance")->type_name("A");
  diff_app->add_flag("--ignore-wall-time,!--compare-wall-time", diff.ignore_wall_time,
                     "Leave out the wall-time fields (mpc/solve_time, timing/, plans/"
                     "planning_time and simplification_time, the batch summary's nmpc_time_*); "
                     "on by default")
      ->default_str("");
  diff_app->add_option("--ignore", diff.ignore_patterns,
                       "Also leave out the fields whose path matches this shell pattern "
                       "(repeatable; `*` matches `/` too), e.g. '*/checks@*_violation_time'")
      ->type_name("PATTERN")
      ->default_str("");
  setExitCodes(diff_app,
               "0 same within the tolerance, 1 different, 2 bad input (a file that is not a run or "
               "batch file), " +
                   std::string(kIncompleteReading));
  runWhenParsed(diff_app, action, parsed, &diffCommand, [](Parsed<DiffOptions>&, CLI::App&) {});
}

void registerPushSweepCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<PushSweepOptions>>();
  PushSweepOptions& push_sweep = parsed->options;
  push_sweep.threads = defaultThreads();
  CLI::App* push_sweep_app = app.add_subcommand(
      "push-sweep",
      "The paper's push-recovery table (Sec. V-B): for each situation (forward: `push`, on_spot: "
      "`push_stepping_in_place`, each without its push) and direction (sagittal/coronal +/-), "
      "the largest recovered force of a 100 ms push at K phases of one step (bisection); prints "
      "it beside the paper's, writes OUT.h5 and OUT.png.");
  push_sweep_app->add_option("--situation", push_sweep.situation, "forward, on_spot or both")
      ->type_name("SITUATION");
  push_sweep_app->add_option("--phases", push_sweep.phases, "Phases spread over one step (from the lift-off)")
      ->type_name("K");
  push_sweep_app->add_option("-j,--jobs", push_sweep.threads, "Worker threads (same result for any N)")
      ->default_str("the number of cores")
      ->type_name("N");
  push_sweep_app->add_option("--json", push_sweep.json,
                             "Also write one object per situation x direction x phase: the push "
                             "that `wpg run <scenario> --set 'pushes[0]={...}'` replays")
      ->default_str("none")
      ->type_name("FILE");
  push_sweep_app->add_option("-o,--output", push_sweep.output, "HDF5 table to write; the figure goes next to it (.png)")
      ->type_name("OUT.h5");
  push_sweep_app->add_option("--set", push_sweep.overrides,
                             "Override a field of both base scenarios, key=value (repeatable), e.g. "
                             "--set walking.max_landing_speed=0.4")
      ->type_name("KEY=VALUE")
      ->default_str("");
  push_sweep_app->add_option("--max-force", push_sweep.max_force, "Upper end of the bisection [N]")
      ->type_name("N");
  push_sweep_app->add_option("--tolerance", push_sweep.tolerance, "Bracket width at which the bisection stops [N]")
      ->type_name("N");
  push_sweep_app->add_option("--max-swing-speed", push_sweep.max_swing_speed,
                             "A walk whose swing foot moves faster is not recovered [m/s]; 0: not checked")
      ->type_name("V");
  push_sweep_app->add_option("--max-swing-acceleration", push_sweep.max_swing_acceleration,
                             "The same for its acceleration [m/s^2]; 0: not checked")
      ->type_name("A");
  push_sweep_app->add_flag("--no-plot", parsed->no_plot, "Do not draw the figure");
  setExitCodes(push_sweep_app, "0 the table is written, 2 bad input (nothing written), " +
                                   std::string(kIncompleteWriting));
  runWhenParsed(push_sweep_app, action, parsed, &pushSweepCommand,
                [](Parsed<PushSweepOptions>& p, CLI::App&) { p.options.plot = !p.no_plot; });
}

void registerPlotCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<PlotOptions>>();
  PlotOptions& plot = parsed->options;
  CLI::App* plot_app = app.add_subcommand("plot", "Draw the figure of a run dataset (PNG).");
  plot_app->add_option("run_file", plot.input, "Run or batch file (`wpg run`, `wpg batch`)")
      ->required()
      ->type_name("RUN.h5");
  plot_app->add_option("-o,--output", plot.output, "PNG to write")
      ->default_str("RUN.png next to RUN.h5 (RUN.NAME.png with --run)")
      ->type_name("FIG.png");
  plot_app->add_option("--run", plot.run, "Draw only this run of the file (a batch file holds many)")
      ->type_name("NAME");
  plot_app->add_flag("--plan", plot.plan,
                     "Draw what the NMPC previewed (mpc/plan/) against what the robot did, and "
                     "the prediction error against the look-ahead (default PNG: RUN.plan.png)");
  plot_app->add_option("--at", plot.at,
                       "With --plan: the previews of the iterations at these times (default: "
                       "four spread over the walk)")
      ->type_name("T [s]")
      ->expected(1, 16);
  setExitCodes(plot_app,
               "0 the figure is drawn, 2 bad input or the plot script failed (no figure), " +
                   std::string(kIncompleteReading));
  runWhenParsed(plot_app, action, parsed, &plotCommand, [](Parsed<PlotOptions>&, CLI::App&) {});
}

void registerViewCommand(CLI::App& app, CommandAction& action) {
  auto parsed = std::make_shared<Parsed<ViewOptions>>();
  ViewOptions& view = parsed->options;
  CLI::App* view_app = app.add_subcommand(
      "view", "Write an HTML page to watch a run (robot, footsteps, obstacles, plots) or to explore "
              "a study (a batch file, or the folder of `wpg compare`); docs/viewer.md.");
  view_app->add_option("input", view.input, "Run or batch file, or the folder of `wpg compare`")
      ->required()
      ->type_name("FILE.h5|DIR");
  view_app->add_option("--run", view.run, "One run of a batch file (its page instead of the dashboard)")
      ->type_name("NAME");
  view_app->add_option("-o,--output", view.output, "Page to write")
      ->default_str("FILE.html beside FILE.h5, DIR/view.html")
      ->type_name("PAGE.html");
  setExitCodes(view_app, "0 the page is written, 2 bad input (nothing written), " +
                             std::string(kIncompleteWriting));
  runWhenParsed(view_app, action, parsed, &viewCommand, [](Parsed<ViewOptions>&, CLI::App&) {});
}

void registerRobotCommand(CLI::App& app, CommandAction& action) {
  CLI::App* robot_app =
      app.add_subcommand("robot", "Robot folders (docs/robots.md): `wpg robot check DIR`.");
  robot_app->require_subcommand(1);
  auto parsed = std::make_shared<Parsed<RobotCheckOptions>>();
  CLI::App* check_app = robot_app->add_subcommand(
      "check",
      "Check a robot folder (walking.yaml, its URDF and SRDF) as a run would read it, and print "
      "what the walking IK derives: leg length, walkable CoM heights, the step polygon it "
      "reaches beside the declared one. Writes nothing.");
  check_app->add_option("folder", parsed->options.folder,
                        "A robot folder, or the name of a robot of the data directory")
      ->required()
      ->type_name("DIR");
  const std::string codes = "0 the folder is fine, 2 a problem (one line naming the file), " +
                            std::string(kIncompleteReading);
  setExitCodes(robot_app, codes);
  setExitCodes(check_app, codes);
  runWhenParsed(check_app, action, parsed, &robotCheckCommand,
                [](Parsed<RobotCheckOptions>&, CLI::App&) {});
}

}  // namespace wpg::cli
