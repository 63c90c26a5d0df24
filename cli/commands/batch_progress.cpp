// Progress of a batch on stderr (batch_progress.hpp).
#include "batch_progress.hpp"

#include <unistd.h>

#include <cmath>

namespace wpg::cli {
namespace {

constexpr double kPlainLinePeriod = 5.0;  // [s] between two plain lines (not a terminal)
constexpr int kBarWidth = 30;

std::string clock(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "--:--";
  const long total = std::lround(seconds);
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  } else {
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  }
  return text;
}

}  // namespace

BatchProgress::BatchProgress(std::string label, std::size_t total, std::FILE* stream)
    : label_(std::move(label)),
      total_(total),
      stream_(stream),
      terminal_(::isatty(::fileno(stream)) == 1),
      start_(std::chrono::steady_clock::now()),
      last_line_(start_) {}

double BatchProgress::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void BatchProgress::runFinished(bool failed) {
  ++done_;
  if (failed) ++failures_;
  const auto now = std::chrono::steady_clock::now();
  if (terminal_ || std::chrono::duration<double>(now - last_line_).count() >= kPlainLinePeriod) {
    last_line_ = now;
    draw(false);
  }
}

void BatchProgress::finish() { draw(true); }

void BatchProgress::draw(bool final_line) {
  const double elapsed = elapsedSeconds();
  const double rate = elapsed > 0.0 ? static_cast<double>(done_) / elapsed : 0.0;
  const double eta = rate > 0.0 ? static_cast<double>(total_ - done_) / rate : NAN;
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, "%zu/%zu runs, %.1f runs/s, %s %s, %zu failed",
                done_, total_, rate, final_line ? "took" : "ETA",
                clock(final_line ? elapsed : eta).c_str(), failures_);
  if (terminal_) {
    const int filled = total_ ? static_cast<int>(kBarWidth * done_ / total_) : kBarWidth;
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(kBarWidth, '.');
    std::fprintf(stream_, "\r%s [%s] %s\033[K%s", label_.c_str(), bar.c_str(), numbers,
                 final_line ? "\n" : "");
  } else {
    std::fprintf(stream_, "%s: %s\n", label_.c_str(), numbers);
  }
  std::fflush(stream_);
}

}  // namespace wpg::cli
