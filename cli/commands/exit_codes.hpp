#pragma once
// The exit codes of every `wpg` subcommand, and the error that ends one for bad usage.
#include <stdexcept>

namespace wpg::cli {

constexpr int kExitSuccess = 0;
// The walk was generated but failed: an NMPC iteration, a fall, a step in a margin, or the
// robot ended blocked (it stopped making progress along its command).
constexpr int kExitRunFailed = 1;
constexpr int kExitBadInput = 2;   // bad scenario, option or file: nothing was written
// Could not complete for want of a resource or an I/O error (out of memory, disk full, a write
// that failed): nothing was written (the temporary output is removed).
constexpr int kExitIncomplete = 3;

// A user mistake detected by the CLI itself (bad option value, missing file): exit 2, like the
// engine's datasets::InputError.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace wpg::cli
