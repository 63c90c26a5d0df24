// The online loop of the paper's Fig. 3 (robots/online_filter_loop.hpp), the unit of the
// paper's Sec. V-C table: one 5 ms control tick that contains an NMPC iteration.
//  * BM_OnlineLoopWalkForward: the whole loop on walk_forward (10 s, preview one step = 0.8 s as
//    the paper), counters: the NMPC ticks' median and mean wall time [ms], every tick's mean,
//    the real-time factor. The tick times are measured inside the loop, per stage.
//  * BM_FilterWindow: what dominates an NMPC tick, the filter's walking IK + multibody ZMP
//    (the momentum rate of the kinematics, momentum_zmp.hpp) over its window (the sampling
//    period + the 0.8 s preview + 1 = 181 samples at 5 ms), on a window of a steady forward
//    walk; BM_FilterWindowSimbody the same with Simbody's inverse dynamics (the previous
//    version's window, for comparison).
// Timings are quoted as medians of --benchmark_repetitions.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/robots/momentum_zmp.hpp"
#include "wpg/robots/multibody_replay.hpp"
#include "wpg/robots/online_filter_loop.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"
#include "wpg/walk_generator.hpp"
#include "../common/source_dir.hpp"

namespace {

double medianOf(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double meanOf(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

const std::string kSource = wpg_test::sourceDir();

wpg::datasets::Scenario walkForward() {
  return wpg::datasets::loadScenario(kSource + "/datasets/scenarios/walk_forward.yaml",
                                     {"filter=true", "filter_settings.preview_time=0.8"},
                                     kSource + "/robots");
}

void BM_OnlineLoopWalkForward(benchmark::State& state) {
  const wpg::datasets::Scenario scenario = walkForward();
  const wpg::robots::RobotModel model(kSource + "/robots/hrp2/hrp2.urdf");
  wpg::robots::OnlineFilterLoopSettings settings;
  settings.preview = scenario.filter_settings;
  std::vector<double> nmpc_ticks, every_tick;
  double walk_duration = 0.0;
  for (auto _ : state) {
    const wpg::robots::OnlineFilterRun run =
        wpg::robots::runOnlineFilterLoop(model, scenario.walking, scenario.request, settings);
    const wpg::MultibodyValidation& v = run.validation;
    for (Eigen::Index i = 0; i < v.tick_stage_time.rows(); ++i) {
      const double tick = v.tick_stage_time.row(i).sum();
      every_tick.push_back(tick);
      if (v.tick_nmpc[static_cast<std::size_t>(i)]) nmpc_ticks.push_back(tick);
    }
    walk_duration = run.walk.trajectory.time.back();
    if (!run.walk.success) state.SkipWithError("the walk failed");
  }
  state.counters["nmpc_tick_median_ms"] = 1e3 * medianOf(nmpc_ticks);
  state.counters["nmpc_tick_mean_ms"] = 1e3 * meanOf(nmpc_ticks);
  state.counters["nmpc_tick_max_ms"] =
      nmpc_ticks.empty() ? 0.0 : 1e3 * *std::max_element(nmpc_ticks.begin(), nmpc_ticks.end());
  state.counters["tick_mean_ms"] = 1e3 * meanOf(every_tick);
  state.counters["walk_s"] = walk_duration;
}
BENCHMARK(BM_OnlineLoopWalkForward)->Unit(benchmark::kMillisecond)->UseRealTime();

// The window of 181 samples from t = 5 s (steady walking).
wpg::WalkTrajectory steadyWindow(const wpg::datasets::Scenario& scenario) {
  const wpg::WalkResult walk = wpg::generateWalk(scenario.walking, scenario.request);
  const std::size_t first = 1000, count = 181;
  wpg::WalkTrajectory window;
  const wpg::WalkTrajectory& w = walk.trajectory;
  const auto slice = [&](const auto& from, auto& to) {
    to.assign(from.begin() + first, from.begin() + first + count);
  };
  slice(w.time, window.time);
  slice(w.com, window.com);
  slice(w.cop, window.cop);
  slice(w.left_foot, window.left_foot);
  slice(w.right_foot, window.right_foot);
  slice(w.free_flyer_yaw, window.free_flyer_yaw);
  return window;
}

void BM_FilterWindow(benchmark::State& state) {
  const wpg::datasets::Scenario scenario = walkForward();
  const wpg::WalkTrajectory window = steadyWindow(scenario);
  const wpg::robots::RobotModel model(kSource + "/robots/hrp2/hrp2.urdf");
  const wpg::robots::WalkingIk ik(model);
  wpg::robots::MomentumZmp momentum(model, scenario.walking.gravity);
  Eigen::MatrixXd com(static_cast<Eigen::Index>(window.size()), 3);
  for (std::size_t i = 0; i < window.size(); ++i)
    com.row(static_cast<Eigen::Index>(i)) = window.com[i].transpose();
  wpg::robots::WalkingIkTrajectory q;
  for (auto _ : state) {
    ik.solveTrajectory(window, com, q);
    const Eigen::MatrixXd& zmp = momentum.run(q.q, scenario.walking.control_period).zmp;
    benchmark::DoNotOptimize(zmp.data());
  }
  state.counters["samples"] = static_cast<double>(window.size());
}
BENCHMARK(BM_FilterWindow)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_FilterWindowSimbody(benchmark::State& state) {
  const wpg::datasets::Scenario scenario = walkForward();
  const wpg::WalkTrajectory window = steadyWindow(scenario);
  const wpg::robots::RobotModel model(kSource + "/robots/hrp2/hrp2.urdf");
  const wpg::robots::WalkingIk ik(model);
  wpg::robots::MultibodyReplaySettings replay_settings;
  replay_settings.joint_torques = false;
  wpg::robots::MultibodyReplay replay(model, replay_settings);
  for (auto _ : state) {
    const wpg::robots::WalkingIkTrajectory q = ik.solveTrajectory(window);
    const Eigen::MatrixXd& zmp = replay.run(q.q, scenario.walking.control_period).zmp;
    benchmark::DoNotOptimize(zmp.data());
  }
  state.counters["samples"] = static_cast<double>(window.size());
}
BENCHMARK(BM_FilterWindowSimbody)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
