#pragma once
// Whether the robot still makes progress along its velocity command. A robot stepping in
// place in front of a wall it cannot pass keeps every constraint of the NMPC (the obstacle
// rows hold its steps out of the margin, the paper's "blocked" of experiment B): nothing in
// the solver's statuses says that the walk has stopped getting anywhere. This monitor says
// it, from what the walk does, not from why.
//
// Definition, at each NMPC sample k (time t_k, every sampling period T):
//  - the commanded world-frame velocity v_k is the clamped robot-frame linear command (vx, vy)
//    turned by the heading the generator expresses the command in at that sample
//    (PatternGenerator::commandFrameHeading: the commanded heading, or the feet's mean yaw
//    with heading_reference: support_foot);
//  - a window is the last N samples, N T = W (default 3 gait cycles, 6 of the parameters'
//    nominal steps: 4.8 s for HRP-2); it counts only when the linear command is non-zero
//    (|v| > kMinLinearCommand) at every sample of it and of the gait cycle before it (from
//    rest the CoM needs about a cycle to reach the commanded speed, and the first steps' sway
//    is no periodic one that cancels: walk_sideways, whose sway lies along its command, walks
//    0.18 of its command in the window that starts with it, 0.41 at worst in the later ones),
//    and when its commanded displacement D = sum_j v_j T (j = k-N .. k-1) is at least half
//    its commanded path sum_j |v_j| T (a command that turns back on itself within a window
//    has no direction to progress along, and |D| near 0 would make the ratio noise);
//  - the walked displacement is the CoM's, c_k - c_{k-N}, at sampling instants: over a whole
//    number of gait cycles the lateral sway cancels;
//  - progress = (c_k - c_{k-N}) . D / |D|^2, the fraction of the commanded displacement walked
//    along its direction.
// A counted window with progress < threshold (default 0.25) opens a blocked stretch at the
// window's start (its time and CoM; a stretch already open keeps its earlier start); a counted
// window with progress >= threshold closes it (the robot resumed). A window that does not
// count neither opens nor closes. The walk ends blocked when a stretch is still open.
//
// A walk of steps longer than the nominal ones (walking.step_timing: adaptive shortens them
// for fast commands) leaves part of a cycle's sway in the window; 0.25 is far below what a
// walk that moves makes (datasets/SCENARIOS.md, "generator", has the measured numbers).
//
// Also the whole walk's progress ratio: sum_k (c_{k+1} - c_k) . v_k / |v_k| over the samples
// with a linear command, divided by sum_k |v_k| T (datasets/METRICS.md, progress_ratio).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/walk_request.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

class ProgressMonitor {
 public:
  // Below this linear command [m/s] a sample has no linear command (a robot standing, or
  // turning on the spot, is asked for no progress).
  static constexpr double kMinLinearCommand = 1e-3;

  // A window of `window_samples` (>= 1) NMPC samples of `sampling_period` [s], judged once
  // the linear command has been on for `settle_samples` (>= 0) before it; blocked below
  // `threshold`. Allocates the window once; nothing after.
  ProgressMonitor(double sampling_period, int window_samples, int settle_samples, double threshold);
  // The window of the settings: blocked_window_cycles gait cycles of the parameters' nominal
  // steps (2 stepSamples() each), settled one such cycle, and the threshold blocked_progress.
  ProgressMonitor(const WalkingParameters& parameters, const GeneratorSettings& settings);

  // NMPC sample at `time` [s]: the CoM's horizontal position at that instant [m] and the
  // commanded world-frame linear velocity held over the coming sampling period [m/s]. Samples
  // come every sampling period, in time order. Does not allocate.
  void addSample(double time, const Eigen::Vector2d& com,
                 const Eigen::Vector2d& commanded_velocity);
  // The walk's closing sample (time and CoM), which ends the last sample's period for the
  // whole walk's ratio; ignored when it is the instant of the last sample (a walk that
  // stopped there).
  void finish(double time, const Eigen::Vector2d& com);

  // A blocked stretch is open.
  bool blocked() const { return blocked_; }
  // Its start: the start of the earliest window of the stretch [s] and the CoM then [m].
  double blockedSince() const { return blocked_since_; }
  const Eigen::Vector2d& blockedPosition() const { return blocked_position_; }

  // The last counted window with progress below the threshold: what the message says.
  struct Window {
    double end_time = 0.0;   // [s] its last sample
    double duration = 0.0;   // [s] N T
    double walked = 0.0;     // [m] the CoM's displacement along D: (c_k - c_{k-N}) . D / |D|
    double commanded = 0.0;  // [m] |D|
    double progress = 0.0;   // walked / commanded
  };
  const Window& lastBlockedWindow() const { return last_blocked_; }
  // One line: "0.04 m walked of the 0.96 m commanded in the 4.8 s to t = 30.0 s, since t =
  // 12.3 s at (1.96, 0.02) m". Allocates (call it once, at the end).
  std::string describeBlocked() const;

  // The whole walk's progress ratio; NaN when no sample had a linear command (it does not
  // apply).
  double progressRatio() const;

  int windowSamples() const { return window_; }

 private:
  struct Entry {
    double time = 0.0;
    Eigen::Vector2d com = Eigen::Vector2d::Zero();
    Eigen::Vector2d displacement = Eigen::Vector2d::Zero();  // v T commanded after this sample
    bool linear = false;                                     // |v| > kMinLinearCommand
  };
  const Entry& ago(int samples) const;  // 0 = the newest sample
  void judgeWindow();

  double sampling_period_;
  int window_;
  int settle_;
  double threshold_;
  std::vector<Entry> ring_;  // the last window_ + 1 samples
  int newest_ = -1;          // slot of the newest sample in ring_
  long samples_ = 0;         // samples added
  int linear_run_ = 0;       // consecutive samples with a linear command, up to the newest
  bool blocked_ = false;
  double blocked_since_ = 0.0;
  Eigen::Vector2d blocked_position_ = Eigen::Vector2d::Zero();
  Window last_blocked_;
  // The whole walk's ratio: the walked part along the command and the commanded distance.
  double walked_along_ = 0.0, commanded_length_ = 0.0;
};

}  // namespace wpg
