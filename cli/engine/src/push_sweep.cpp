// The paper's push-recovery test (push_sweep.hpp).
#include "wpg/engine/push_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/engine/ordered_parallel.hpp"

namespace wpg::engine {
namespace {

// The swept step: this lift-off of the unpushed walk (0-based). Forward, the robot lifts its
// first foot at 1.8 s (after the start's double support), stepping in place at 0.8 s; two steps
// later (3.4 s, 2.4 s) the gait is periodic: the CoM velocity over the next two steps differs
// from that of the two after by less than 5 mm/s. In both situations the left foot swings in
// this step (the right one supports), as in the shipped `push` (90 N to +y at 3.8 s).
constexpr std::size_t kSweptLiftOff = 2;
constexpr double kAfterPushMargin = 2.0;  // [s] of walk at least after the last push

}  // namespace

std::string shortestNumber(double value) {
  for (int digits = 1; digits <= 17; ++digits) {
    std::ostringstream text;
    text << std::setprecision(digits) << value;
    if (std::stod(text.str()) == value) return text.str();
  }
  return "null";  // NaN, as JSON writes it: no text reads back as it
}

PushSituation preparePushSituation(const std::string& name, const std::string& scenario,
                                   const datasets::Scenario& base,
                                   const std::string& robots_directory) {
  PushSituation situation;
  situation.name = name;
  situation.scenario = scenario;
  situation.base = base;
  if (base.goal.enabled) {
    throw datasets::InputError(scenario + ": a push sweep needs a walk on a velocity command, not a goal");
  }
  situation.step_period = base.walking.stepDuration();
  datasets::Scenario unpushed = base;
  if (!unpushed.request.pushes.empty()) unpushed.request.pushes.erase(unpushed.request.pushes.begin());
  const RunResult result = runScenario(unpushed, RunSettings{robots_directory, nullptr});
  if (result.outcome != RunOutcome::kSucceeded) {
    throw datasets::InputError(scenario + " without its push fails (" + result.failure +
                               "): nothing to push");
  }
  const std::vector<double> lift_offs = liftOffTimes(result.walk.result.trajectory);
  if (lift_offs.size() <= kSweptLiftOff) {
    throw datasets::InputError(scenario + ": the walk takes fewer than " +
                               std::to_string(kSweptLiftOff + 1) + " steps (duration too short?)");
  }
  situation.lift_off = lift_offs[kSweptLiftOff];
  const double last_push_end = situation.lift_off + situation.step_period + 0.1;
  if (last_push_end + kAfterPushMargin > base.request.duration) {
    throw datasets::InputError(scenario + ": duration " + shortestNumber(base.request.duration) +
                               " s leaves less than " + shortestNumber(kAfterPushMargin) +
                               " s of walk after the swept step (lift-off " +
                               shortestNumber(situation.lift_off) + " s)");
  }
  return situation;
}

std::vector<datasets::PushSweepRow> runPushSweep(const std::vector<PushSituation>& situations,
                                                 int phases, const PushSearchSettings& settings,
                                                 int threads, const std::string& robots_directory,
                                                 const std::function<void()>& finished) {
  // Jobs: situation x direction x phase, in that order (the order of the table and files).
  struct Job {
    const PushSituation* situation;
    const PushDirection* direction;
    double phase, t;
  };
  std::vector<Job> jobs;
  for (const PushSituation& situation : situations) {
    for (const PushDirection& direction : pushDirections()) {
      for (int k = 0; k < phases; ++k) {
        const double phase = static_cast<double>(k) / phases;
        // Rounded to 1 ms: the push start reads back the same from the JSON's short text.
        const double t = std::round((situation.lift_off + phase * situation.step_period) * 1000.0) / 1000.0;
        jobs.push_back({&situation, &direction, phase, t});
      }
    }
  }

  // Never more workers than bisections (runOrdered): one robot model cache each.
  const int workers = static_cast<int>(std::max<std::size_t>(
      1, std::min<std::size_t>(threads < 1 ? 1 : static_cast<std::size_t>(threads), jobs.size())));
  std::vector<RobotModelCache> models;
  for (int worker = 0; worker < workers; ++worker) models.emplace_back(robots_directory);
  std::vector<datasets::PushSweepRow> rows;
  runOrdered<PushSearchResult>(
      jobs.size(), workers,
      [&](std::size_t index, int worker) {
        const Job& job = jobs[index];
        return searchLargestRecoveredPush(
            job.situation->base, job.t, job.direction->unit, settings,
            RunSettings{robots_directory, &models[static_cast<std::size_t>(worker)]});
      },
      [&](std::size_t index, PushSearchResult&& result) {
        const Job& job = jobs[index];
        datasets::PushSweepRow row;
        row.situation = job.situation->name;
        row.direction = job.direction->name;
        row.scenario = job.situation->scenario;
        row.phase = job.phase;
        row.t = job.t;
        row.fx = result.force * job.direction->unit.x();
        row.fy = result.force * job.direction->unit.y();
        row.force = result.force * (job.direction->unit.sum() < 0.0 ? -1.0 : 1.0);
        row.duration = settings.duration;
        row.impulse = row.force * row.duration;
        row.at_upper_bound = result.at_upper_bound;
        row.walks = result.walks;
        row.swing_speed_max = result.swing.speed;
        row.swing_acceleration_max = result.swing.acceleration;
        rows.push_back(row);
        if (finished) finished();
      });
  return rows;
}

}  // namespace wpg::engine
