#pragma once
// Progress of a batch on stderr: runs done / total, runs per second, ETA, failures so far. On a
// terminal a bar redrawn in place; otherwise (a log, a pipe) a plain line every few seconds and
// one at the end, so logs stay readable.
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace wpg::cli {

class BatchProgress {
 public:
  // `total` runs to do in this invocation (runs already in a resumed file not counted);
  // `label` prefixes every line (the study's name).
  BatchProgress(std::string label, std::size_t total, std::FILE* stream);

  // One more run finished; `failed` when its walk failed.
  void runFinished(bool failed);
  // The last line (a newline after the bar on a terminal).
  void finish();

  std::size_t done() const { return done_; }
  std::size_t failures() const { return failures_; }
  double elapsedSeconds() const;

 private:
  void draw(bool final_line);

  std::string label_;
  std::size_t total_;
  std::FILE* stream_;
  bool terminal_;
  std::size_t done_ = 0, failures_ = 0;
  std::chrono::steady_clock::time_point start_, last_line_;
};

}  // namespace wpg::cli
