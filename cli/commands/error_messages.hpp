#pragma once
// The one-line messages of every subcommand on stderr: "wpg: error: <message>" and
// "wpg: warning: <message>" (control characters escaped: user text cannot split the line).
#include <string>

namespace wpg::cli {

void printError(const std::string& message);
void printWarning(const std::string& message);

}  // namespace wpg::cli
