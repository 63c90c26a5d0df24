// The measurement behind `wpg bench` (control_chain_benchmark.hpp).
#include "wpg/engine/control_chain_benchmark.hpp"

#include <stdexcept>

#include "wpg/engine/pipeline_stages.hpp"

namespace wpg::engine {

ControlChainTiming measureControlChain(const datasets::Scenario& scenario,
                                       const robots::RobotModel& model) {
  datasets::Scenario online = scenario;
  online.filter_loop.mode = DynamicFilterMode::kOnline;
  // The paper's preview: one step (Sec. V-A, "in order to insure real time feasibility on
  // HRP-2"), 0.8 s for HRP-2; the window the NMPC ticks replay scales with it.
  online.filter_settings.preview_time = scenario.walking.stepDuration();
  const WalkAndReplay run = runWalkAndReplay(&model, online);
  if (!run.replay) throw std::runtime_error(run.replay_failure);
  const ReplayOutcome& replay = *run.replay;
  ControlChainTiming timing;
  timing.name = scenario.name;
  timing.walk_success = run.walk.result.success;
  timing.ticks = analysis::tickTiming(replay.validation);
  timing.walk_duration = replay.walk_duration;
  timing.loop_wall_time = replay.wall_time;
  timing.real_time_factor = replay.realTimeFactor();
  timing.control_period = scenario.walking.control_period;
  const MultibodyValidation& v = replay.validation;
  for (Eigen::Index i = 0; i < v.tick_stage_time.rows(); ++i) {
    if (v.tick_nmpc[static_cast<std::size_t>(i)] &&
        v.tick_stage_time.row(i).sum() > timing.control_period) {
      ++timing.ticks_over_period;
    }
  }
  timing.zmp = analysis::compareZmpError(v);
  timing.ik_failures = v.ik_failures;
  return timing;
}

}  // namespace wpg::engine
