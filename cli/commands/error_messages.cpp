// The one-line messages on stderr (error_messages.hpp).
#include "error_messages.hpp"

#include <iostream>
#include <set>

#include "wpg/datasets/input/input_error.hpp"

namespace wpg::cli {
namespace {

// Messages are one line: line breaks become spaces, and any other control character (user
// text quoted in a usage error) is escaped.
std::string oneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return datasets::escapeControlCharacters(text);
}

}  // namespace

void printError(const std::string& message) { std::cerr << "wpg: error: " << oneLine(message) << '\n'; }

void printWarning(const std::string& message) {
  std::cerr << "wpg: warning: " << oneLine(message) << '\n';
}

void printWarnings(const std::vector<std::string>& warnings, std::size_t max_lines) {
  std::set<std::string> printed;
  std::size_t left_out = 0;
  for (const std::string& warning : warnings) {
    if (printed.count(warning)) continue;
    if (printed.size() == max_lines) {
      ++left_out;
      continue;
    }
    printed.insert(warning);
    printWarning(warning);
  }
  if (left_out > 0) {
    printWarning(std::to_string(left_out) +
                 " more different warnings (each run's `warnings` "
                 "attribute holds its own)");
  }
}

}  // namespace wpg::cli
