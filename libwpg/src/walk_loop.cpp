// The control loop of one recorded walk (walk_loop.hpp).
#include "wpg/walk_loop.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "value_checks.hpp"
#include "wpg/obstacles.hpp"
#include "wpg/online_walking_generator.hpp"
#include "wpg/progress_monitor.hpp"

namespace wpg {
namespace {

void appendControlSample(const ControlSample& s, WalkTrajectory& out) {
  out.time.push_back(s.time);
  out.com.push_back(s.com_position);
  out.com_vel.push_back(s.com_velocity);
  out.com_acc.push_back(s.com_acceleration);
  out.cop.push_back(s.cop);
  out.left_foot.push_back(s.left_foot);
  out.right_foot.push_back(s.right_foot);
  out.free_flyer_yaw.push_back(s.free_flyer_yaw);
  out.support.push_back(s.support);
}

// Relaxed obstacle rows (a robot enclosed or pushed into an obstacle) may let a step land in
// a margin: the walk is then recorded as failed.
void checkLandingsClear(const WalkingParameters& parameters, const WalkRequest& request,
                        const ObstacleDistanceOracle& distance, WalkResult& result) {
  for (const Footstep& step : result.trajectory.footsteps) {
    if (step.landing_time <= 0.0) continue;
    for (int o = 0; o < static_cast<int>(request.obstacles.size()); ++o) {
      const double clearance = stepCentreClearance(distance, o, request.obstacles[o],
                                                   parameters, step.pose.head<2>());
      if (clearance < -1e-6 && result.success) {
        result.success = false;
        result.message = "the step landing at t = " + std::to_string(step.landing_time) +
                         " s is " + std::to_string(-clearance) + " m inside obstacle " +
                         std::to_string(o) + "'s margin (" + stepCentreBoundName(parameters) +
                         "; its constraint had to be relaxed)";
      }
    }
  }
}

// The linear part of the command the generator tracks at the sample it just solved, in the
// world: clamped, turned by the heading it expressed the command in (progress_monitor.hpp).
Eigen::Vector2d commandedWorldVelocity(const PatternGenerator& generator) {
  const double heading = generator.commandFrameHeading();
  const Eigen::Vector3d& command = generator.clampedCommand();
  const double c = std::cos(heading), s = std::sin(heading);
  return {c * command.x() - s * command.y(), s * command.x() + c * command.y()};
}

}  // namespace

void checkWalkSize(const WalkingParameters& parameters, const WalkRequest& request) {
  // Both validated: duration <= kMaxWalkDuration, control_period >= 1e-6 s; the quotient is
  // compared as a double, before any conversion to an integer.
  // The walk has lround(duration / T) NMPC iterations: none below half a sampling period, and
  // a walk of one sample is no walk (nothing to replay, plot or check).
  if (!(request.duration >= 0.5 * parameters.sampling_period)) {
    throw std::invalid_argument(
        "'duration': expected at least half a sampling period (" +
        detail::formatValue(0.5 * parameters.sampling_period) +
        " s: one NMPC iteration), got " + detail::formatValue(request.duration));
  }
  const double periods = request.duration / parameters.control_period;
  if (!(periods <= kMaxControlPeriods)) {
    throw std::invalid_argument(
        "'duration': expected at most " + std::to_string(static_cast<long long>(kMaxControlPeriods)) +
        " control periods of " + detail::formatValue(parameters.control_period) +
        " s (the walk is kept in memory, ~0.3 kB a period), got " + detail::formatValue(periods));
  }
}

WalkResult runWalkLoop(OnlineWalkingGenerator& generator, const WalkRequest& request,
                       CommandSource& commands, ControlLoopObserver* observer) {
  const WalkingParameters& parameters = generator.parameters();
  const double T = parameters.sampling_period;
  const int sub_samples = static_cast<int>(std::lround(T / parameters.control_period));
  const int iterations = static_cast<int>(std::lround(request.duration / T));

  WalkResult result;
  WalkTrajectory& out = result.trajectory;
  out.reserve(static_cast<std::size_t>(iterations) * sub_samples + 1, iterations);
  // At most one landing per NMPC iteration (a sample ends at most one swing), after the two
  // initial feet: no allocation when a foot lands.
  out.footsteps.reserve(static_cast<std::size_t>(iterations) + 2);
  out.constraint_families = generator.patternGenerator().model().familyInfo();
  for (FootSide side : {FootSide::kLeft, FootSide::kRight})
    out.footsteps.push_back({0.0, generator.patternGenerator().footPose(side), side});

  // The plans, sized for the whole walk: recording one copies it, no allocation.
  const bool record_plan = request.generator.record_plan;
  NmpcPlan plan;
  if (record_plan) {
    const PatternGenerator& pattern = generator.patternGenerator();
    plan.resize(pattern.maxPreviewSamples(), pattern.model().layout().steps,
                pattern.model().familyCount());
    out.plans.reserve(pattern.maxPreviewSamples(), pattern.model().layout().steps,
                      pattern.model().familyCount(), T, iterations);
  }

  ProgressMonitor progress(parameters, request.generator);
  bool fallen = false, stopped_blocked = false;
  for (int k = 0; k < iterations && !fallen && !stopped_blocked; ++k) {
    Eigen::Vector3d command = Eigen::Vector3d::Zero();
    if (!commands.nextCommand(k, k * T, generator, command)) break;
    generator.setCommand(command);
    for (int i = 0; i < sub_samples; ++i) {
      generator.setPushAcceleration(request.pushAccelerationAt(generator.time()));
      if (observer) observer->beforeStep(generator);
      const ControlSample& sample = generator.step();
      if (generator.fallen()) {
        out.mpc.push_back(generator.lastIteration());
        out.mpc.back().command = command;
        if (record_plan) {  // no NMPC ran: an empty row
          plan.clear(generator.lastIteration().time);
          out.plans.append(plan);
        }
        result.success = false;
        result.message = "the robot fell at t = " + std::to_string(sample.time) +
                         " s: capture point " + std::to_string(generator.captureDistance()) +
                         " m from the nearest foot (limit " +
                         std::to_string(request.generator.fall_capture_distance) + " m)";
        appendControlSample(sample, out);  // the closing sample
        fallen = true;
        break;
      }
      if (sample.nmpc_sample) {
        const MpcIterationLog& log = generator.lastIteration();
        out.mpc.push_back(log);
        out.mpc.back().command = command;  // the metrics of a goal walk track it (METRICS.md)
        const Eigen::Vector2d velocity = commandedWorldVelocity(generator.patternGenerator());
        out.mpc.back().commanded_velocity = velocity;
        if (record_plan) {
          generator.patternGenerator().previewPlan(plan);
          out.plans.append(plan);
        }
        if (result.success && iterationStatusFailsWalk(log.status)) {
          result.success = false;
          result.message = std::string("NMPC iteration at t = ") + std::to_string(sample.time) +
                           " s ended with status '" + iterationStatusName(log.status) + "'";
        }
        progress.addSample(sample.time, sample.com_position.head<2>(), velocity);
      }
      if (observer) observer->afterStep(generator, sample);
      appendControlSample(sample, out);
      if (generator.landed()) out.footsteps.push_back(generator.lastLanding());
      // Found blocked: this sampling instant closes the walk (it is recorded, as a fall's).
      if (sample.nmpc_sample && request.generator.stop_when_blocked && progress.blocked()) {
        stopped_blocked = true;
        break;
      }
    }
  }
  if (result.success && generator.obstacleDistance())
    checkLandingsClear(parameters, request, *generator.obstacleDistance(), result);
  if (!fallen && !stopped_blocked) {
    // The sample at the end belongs to the last period: a swing foot still in the air is
    // where its polynomial puts it (not back at its lift-off pose).
    generator.setPushAcceleration(request.pushAccelerationAt(generator.time()));
    appendControlSample(generator.currentSample(), out);
  }
  progress.finish(out.time.back(), out.com.back().head<2>());
  result.progress_ratio = progress.progressRatio();
  // A fall ends the walk by itself (its outcome); a command source that reached its target
  // made its progress (CommandSource::reachedTarget).
  if (!fallen && progress.blocked() && !commands.reachedTarget()) {
    result.blocked = true;
    result.blocked_since = progress.blockedSince();
    result.blocked_position = progress.blockedPosition();
    result.stopped_blocked = stopped_blocked;
    result.blocked_description = progress.describeBlocked();
    if (result.success) {
      result.success = false;
      result.message = "the robot is blocked: " + result.blocked_description;
    }
  }
  return result;
}

}  // namespace wpg
