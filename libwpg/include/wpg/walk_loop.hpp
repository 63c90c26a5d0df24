#pragma once
// The control loop of one recorded walk, whoever commands it: every sampling period a command
// from a CommandSource (the request's velocity schedule, or planning/'s path follower), then
// one OnlineWalkingGenerator::step() per control period with the request's push, the fall
// check, and the recording of the samples, the NMPC logs and the landed steps (paper Fig. 3:
// the WPG every T, the interpolation every control period). generateWalk (walk_generator.hpp)
// and the walk to a goal (planning/goal_walk.hpp) are this loop with their command sources, so
// that their trajectories and verdicts are the same.
#include <string>

#include <Eigen/Core>

#include "wpg/walk_request.hpp"
#include "wpg/walk_trajectory.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

class OnlineWalkingGenerator;
struct ControlSample;

struct WalkResult {
  WalkTrajectory trajectory;
  // false when some NMPC iteration's status fails the walk (iterationStatusFailsWalk: anything
  // but solved or relaxed_obstacle), when the robot fell, when a step landed inside an
  // obstacle's margin, or when the walk ended blocked; the walk is still complete and recorded
  // (`wpg run` then exits 1).
  bool success = true;
  std::string message;  // one line: what went wrong first, empty on success
  // The robot stopped making progress along its command and had not resumed at the end
  // (progress_monitor.hpp; not judged for a walk that fell, nor for one whose command source
  // reached its target). Recorded whatever else failed the walk before; the message says so
  // when nothing did.
  bool blocked = false;
  double blocked_since = 0.0;  // [s] start of the blocked stretch (when blocked)
  Eigen::Vector2d blocked_position = Eigen::Vector2d::Zero();  // [m] the CoM then (when blocked)
  // ProgressMonitor::describeBlocked(), the message's text after "the robot is blocked: " (when
  // blocked; not stored in a dataset: the message is).
  std::string blocked_description;
  // The walk ended at the sample it was found blocked (generator.stop_when_blocked).
  bool stopped_blocked = false;
  // The whole walk's progress along its command (ProgressMonitor::progressRatio); NaN when no
  // sample had a linear command.
  double progress_ratio = 0.0;
};

// Where the walk's velocity command comes from: asked once per NMPC iteration, before its
// control periods (the command is used from that iteration's NMPC on).
class CommandSource {
 public:
  virtual ~CommandSource() = default;
  // The robot-frame command [vx m/s, vy m/s, omega rad/s] of NMPC iteration `iteration`,
  // which starts at `time` = iteration * sampling_period, into `command` (zero on entry).
  // Returns false to end the walk before this iteration (nothing more will happen, e.g. the
  // robot stands at its goal); the closing sample is then recorded at `time`.
  virtual bool nextCommand(int iteration, double time, OnlineWalkingGenerator& generator,
                           Eigen::Vector3d& command) = 0;
  // Whether the commands reached what they were for (a goal walk's goal): such a walk made its
  // progress, whatever the monitor's last windows say (the turn on the spot at a goal asks for
  // a little linear velocity that holds the robot where it stands). Asked once, at the end.
  virtual bool reachedTarget() const { return false; }
};

// The request's velocity reference schedule (WalkRequest::commandAt), for the whole duration.
class ScheduledCommands final : public CommandSource {
 public:
  explicit ScheduledCommands(const WalkRequest& request) : request_(request) {}
  bool nextCommand(int, double time, OnlineWalkingGenerator&, Eigen::Vector3d& command) override {
    command = request_.commandAt(time);
    return true;
  }

 private:
  const WalkRequest& request_;
};

// A controller around the WPG inside the loop (e.g. the dynamic filter's closed loop of the
// paper's Fig. 3, robots/online_filter_loop.hpp): called around every control period, it may
// re-initialise the generator's CoM at sampling instants.
class ControlLoopObserver {
 public:
  virtual ~ControlLoopObserver() = default;
  // Before the step() of each control period, command and push already set.
  virtual void beforeStep(OnlineWalkingGenerator& generator) = 0;
  // After each step() that did not end in a fall, with the sample it produced (recorded next).
  virtual void afterStep(OnlineWalkingGenerator& generator, const ControlSample& sample) = 0;
};

// Runs the walk of `request` (its duration, pushes and obstacles; validated by the caller, and
// its size by checkWalkSize) on `generator`, built from the same parameters and settings, its
// obstacles set, at its start. Stops early when the robot falls (the closing sample is the
// fall's) or when `commands` ends the walk. `observer` (not owned, may be null) is called
// around every control period. Records every control period's sample, the closing sample at
// the end, each NMPC iteration's log and the landed steps (the two initial feet first), and
// fails the walk (success, message) on a fall, on the first NMPC iteration whose status fails a
// walk, on a step landed inside an obstacle's margin, or when the robot ends blocked
// (progress_monitor.hpp, fed at every NMPC sample; with generator.stop_when_blocked the walk
// ends at the sample it is found blocked, that sample closing it). Allocates only before the
// first control period (the trajectory is reserved for the whole duration, the monitor's
// window made) and for the failure message; `commands` and `observer` may allocate in their
// own calls.
WalkResult runWalkLoop(OnlineWalkingGenerator& generator, const WalkRequest& request,
                       CommandSource& commands, ControlLoopObserver* observer = nullptr);

// At most this many control periods in one walk: ~0.3 kB each in memory, 3600 s at 5 ms.
constexpr double kMaxControlPeriods = 720000.0;
// Throws std::invalid_argument naming 'duration' when the walk would record more control
// periods than kMaxControlPeriods, or no NMPC iteration (duration below half a sampling
// period). Callers of runWalkLoop call it before any work.
void checkWalkSize(const WalkingParameters& parameters, const WalkRequest& request);

}  // namespace wpg
