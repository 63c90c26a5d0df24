#pragma once
// The one-line messages of every subcommand on stderr: "wpg: error: <message>" and
// "wpg: warning: <message>" (control characters escaped: user text cannot split the line).
#include <string>
#include <vector>

namespace wpg::cli {

void printError(const std::string& message);
void printWarning(const std::string& message);

// The scenario loader's warnings (a clamped command, an implausible value: Scenario::warnings),
// one line each; the same warning of several runs of a study once, at most `max_lines` lines
// and then how many more there are (every run's file records its own).
void printWarnings(const std::vector<std::string>& warnings, std::size_t max_lines = 20);

}  // namespace wpg::cli
