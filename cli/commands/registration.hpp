#pragma once
// One function per subcommand that adds it to the command line (CLI11, in registration.cpp
// only): its options, parsed into its option struct (command_options.hpp), and the action that
// runs it once the command line is parsed.
#include <functional>

namespace CLI {
class App;
}

namespace wpg::cli {

// What runs once the command line is parsed: the chosen subcommand with its options; returns
// the exit status.
using CommandAction = std::function<int()>;

void registerRunCommand(CLI::App& app, CommandAction& action);
void registerReplayCommand(CLI::App& app, CommandAction& action);
void registerBenchCommand(CLI::App& app, CommandAction& action);
void registerBatchCommand(CLI::App& app, CommandAction& action);
void registerMergeCommand(CLI::App& app, CommandAction& action);
void registerCompareCommand(CLI::App& app, CommandAction& action);
void registerAnalyzeCommand(CLI::App& app, CommandAction& action);
void registerDiffCommand(CLI::App& app, CommandAction& action);
void registerPushSweepCommand(CLI::App& app, CommandAction& action);
void registerPlotCommand(CLI::App& app, CommandAction& action);
void registerViewCommand(CLI::App& app, CommandAction& action);
void registerRobotCommand(CLI::App& app, CommandAction& action);

}  // namespace wpg::cli
