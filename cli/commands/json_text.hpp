#pragma once
// JSON text for the subcommands' --json / --format json outputs (`wpg bench`, `wpg analyze`):
// strings quoted, numbers with a chosen precision, non-finite numbers as null.
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace wpg::cli {

inline std::string jsonString(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

// `digits` significant digits (17: reads back to the same double); NaN and inf as null.
inline std::string jsonNumber(double value, int digits) {
  if (!std::isfinite(value)) return "null";
  std::ostringstream text;
  text << std::setprecision(digits) << value;
  return text.str();
}

}  // namespace wpg::cli
