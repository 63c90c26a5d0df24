// Multibody replay speed: replay + dynamic filter of a 20 s walk_forward walk on HRP-2 (walking
// IK, the multibody ZMP of the WPG's motion (the momentum rate, momentum_zmp.hpp), the preview
// filter, IK again and Simbody's inverse dynamics to validate the corrected motion), on one
// thread and with the validation's samples shared by two (WalkReplaySettings::threads, what
// `wpg run` does on a 2-core machine); without the filter, IK and Simbody. Reported: time per
// replay, and the real-time factor (walk duration / wall time) as a counter. Numbers:
// docs/performance.md.
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include "wpg/datasets/input/scenario.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walk_replay.hpp"
#include "wpg/walk_generator.hpp"
#include "../common/source_dir.hpp"

namespace {

void replay20sWalk(benchmark::State& state, bool filter, int threads = 1) {
  const std::string source = wpg_test::sourceDir();
  const wpg::datasets::Scenario scenario = wpg::datasets::loadScenario(
      source + "/datasets/scenarios/walk_forward.yaml", {"duration=20"}, source + "/robots");
  const wpg::WalkResult walk = wpg::generateWalk(scenario.walking, scenario.request);
  const wpg::robots::RobotModel model(source + "/robots/hrp2/hrp2.urdf");
  wpg::robots::WalkReplaySettings settings;
  settings.filter = filter;
  settings.preview = scenario.filter_settings;
  settings.threads = threads;
  const double walk_duration = walk.trajectory.time.back() - walk.trajectory.time.front();
  double wall_time = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const wpg::MultibodyValidation v = wpg::robots::replayWalk(
        model, scenario.walking, scenario.request, walk.trajectory, settings);
    wall_time += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(v.after.rms);
    if (v.ik_failures != 0) state.SkipWithError("the IK failed on some sample");
  }
  // Both per run: (iterations x 20 s) / (iterations x wall time per run).
  state.counters["real_time_factor"] =
      wall_time > 0.0 ? walk_duration * static_cast<double>(state.iterations()) / wall_time : 0.0;
  state.counters["walk_s"] = walk_duration;
}

void BM_Replay20sWalkWithFilter(benchmark::State& state) { replay20sWalk(state, true); }
void BM_Replay20sWalkWithoutFilter(benchmark::State& state) { replay20sWalk(state, false); }
void BM_Replay20sWalkWithFilterTwoThreads(benchmark::State& state) {
  replay20sWalk(state, true, 2);
}

BENCHMARK(BM_Replay20sWalkWithFilter)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Replay20sWalkWithoutFilter)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Replay20sWalkWithFilterTwoThreads)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
