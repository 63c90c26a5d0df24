#pragma once
// The one-line errors of libwpg's public validators (entry points check always, invariants are
// asserts): what was
// expected and what came, naming the key as the scenario file spells it. Not installed.
#include <sstream>
#include <stdexcept>
#include <string>

namespace wpg::detail {

// "<what>'<key>': expected <expected>, got <got>", e.g. what = "walking parameter ".
[[noreturn]] inline void failValue(const std::string& what, const std::string& key,
                                   const std::string& expected, const std::string& got) {
  throw std::invalid_argument(what + "'" + key + "': expected " + expected + ", got " + got);
}

// The shortest text that reads back as `value` (1e-320 stays "1e-320", 0.1 "0.1"): a message
// shows the value given, never a rounding of it ("0.000000").
inline std::string formatValue(double value) {
  std::ostringstream os;
  for (int digits = 1; digits <= 17; ++digits) {
    os.str("");
    os.precision(digits);
    os << value;
    std::istringstream back(os.str());
    double parsed = 0.0;
    if (back >> parsed && (parsed == value || value != value)) break;
  }
  return os.str();
}

inline void requireValue(bool ok, const std::string& what, const std::string& key,
                         const std::string& expected, double got) {
  if (!ok) failValue(what, key, expected, formatValue(got));
}

}  // namespace wpg::detail
