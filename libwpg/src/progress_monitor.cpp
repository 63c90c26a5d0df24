// Progress along the velocity command (progress_monitor.hpp).
#include "wpg/progress_monitor.hpp"

#include <cassert>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace wpg {

ProgressMonitor::ProgressMonitor(double sampling_period, int window_samples, int settle_samples,
                                 double threshold)
    : sampling_period_(sampling_period),
      window_(window_samples),
      settle_(settle_samples),
      threshold_(threshold) {
  if (!(sampling_period > 0.0) || window_samples < 1 || settle_samples < 0 ||
      !(threshold > 0.0 && threshold < 1.0)) {
    throw std::invalid_argument(
        "ProgressMonitor: expected a positive sampling period, a window of at least one sample, "
        "a settling time of at least none and a threshold in (0, 1)");
  }
  ring_.resize(static_cast<std::size_t>(window_samples) + 1);
}

ProgressMonitor::ProgressMonitor(const WalkingParameters& parameters,
                                 const GeneratorSettings& settings)
    : ProgressMonitor(parameters.sampling_period,
                      settings.blocked_window_cycles * 2 * parameters.stepSamples(),
                      2 * parameters.stepSamples(), settings.blocked_progress) {}

const ProgressMonitor::Entry& ProgressMonitor::ago(int samples) const {
  const int size = static_cast<int>(ring_.size());
  return ring_[static_cast<std::size_t>((newest_ - samples + size) % size)];
}

void ProgressMonitor::addSample(double time, const Eigen::Vector2d& com,
                                const Eigen::Vector2d& commanded_velocity) {
  // The previous sample's period ends here: its part of the whole walk's ratio.
  if (samples_ > 0) {
    const Entry& previous = ago(0);
    if (previous.linear) {
      const double length = previous.displacement.norm();
      walked_along_ += (com - previous.com).dot(previous.displacement) / length;
      commanded_length_ += length;
    }
  }
  const int size = static_cast<int>(ring_.size());
  newest_ = (newest_ + 1) % size;
  Entry& entry = ring_[static_cast<std::size_t>(newest_)];
  // The window ending here covers the periods of the samples before this one: judged with
  // the run of linear commands up to the previous sample.
  const int run_before = linear_run_;
  entry.time = time;
  entry.com = com;
  entry.displacement = commanded_velocity * sampling_period_;
  entry.linear = commanded_velocity.norm() > kMinLinearCommand;
  linear_run_ = entry.linear ? linear_run_ + 1 : 0;
  ++samples_;
  if (run_before >= window_ + settle_) judgeWindow();
}

void ProgressMonitor::judgeWindow() {
  const Entry& start = ago(window_);
  const Entry& end = ago(0);
  Eigen::Vector2d commanded = Eigen::Vector2d::Zero();
  double path = 0.0;
  for (int j = 1; j <= window_; ++j) {
    commanded += ago(j).displacement;
    path += ago(j).displacement.norm();
  }
  const double length = commanded.norm();
  if (!(length >= 0.5 * path)) return;  // turns back on itself: no direction (the header)
  const double walked = (end.com - start.com).dot(commanded) / length;
  const double progress = walked / length;
  if (progress >= threshold_) {
    blocked_ = false;  // resumed
    return;
  }
  if (!blocked_) {
    blocked_ = true;
    blocked_since_ = start.time;
    blocked_position_ = start.com;
  }
  last_blocked_ = {end.time, end.time - start.time, walked, length, progress};
}

void ProgressMonitor::finish(double time, const Eigen::Vector2d& com) {
  if (samples_ == 0) return;
  const Entry& last = ago(0);
  // A walk that stopped at its last sample (a fall, stop_when_blocked) has no period after it.
  if (!(time > last.time + 0.5 * sampling_period_) || !last.linear) return;
  const double length = last.displacement.norm();
  walked_along_ += (com - last.com).dot(last.displacement) / length;
  commanded_length_ += length;
}

double ProgressMonitor::progressRatio() const {
  if (!(commanded_length_ > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return walked_along_ / commanded_length_;
}

std::string ProgressMonitor::describeBlocked() const {
  const Window& w = last_blocked_;
  // A CoM that came back to where it was prints 0.00, not -0.00 (a sign that says nothing).
  const double walked = std::abs(w.walked) < 0.005 ? 0.0 : w.walked;
  char text[256];
  std::snprintf(text, sizeof(text),
                "%.2f m walked of the %.2f m commanded in the %.1f s to t = %.1f s, since t = "
                "%.1f s at (%.2f, %.2f) m",
                walked, w.commanded, w.duration, w.end_time, blocked_since_, blocked_position_.x(),
                blocked_position_.y());
  return text;
}

}  // namespace wpg
