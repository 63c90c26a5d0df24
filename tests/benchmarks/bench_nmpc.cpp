// NMPC speed: one real-time iteration (build the problem, linearize,
// one QP) of HRP-2's NMPC, N = 16, nf = 2, in steady walking; and a whole 20 s walk
// (generation + 5 ms interpolation + HDF5 write). Per-iteration times are also reported as
// median / p99 counters (manual timing of each update()).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <unistd.h>

#include "wpg/datasets/storage/run_dataset.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "wpg/lipm_prediction.hpp"
#include "wpg/pattern_generator.hpp"
#include "wpg/walk_generator.hpp"
#include "../common/obstacle_fields.hpp"
#include "../common/source_dir.hpp"

namespace {

void reportPercentiles(benchmark::State& state, std::vector<double>& samples) {
  if (samples.empty()) return;
  std::sort(samples.begin(), samples.end());
  auto at = [&](double q) { return samples[static_cast<std::size_t>(q * (samples.size() - 1))]; };
  state.counters["median_us"] = at(0.5) * 1e6;
  state.counters["p99_us"] = at(0.99) * 1e6;
  state.counters["max_us"] = samples.back() * 1e6;
}

// BM_NmpcIterationThreeObstacles' corridor: 60 obstacles every 0.5 m along x; three stay
// within reach of the previewed steps up to x = 25 m.
constexpr int kCorridorObstacles = 60;
constexpr double kCorridorEnd = 25.0;

void runIterations(benchmark::State& state, const Eigen::Vector3d& command,
                   wpg::GeneratorAlgorithm algorithm, int sqp_iterations,
                   const std::vector<wpg::Obstacle>* world = nullptr) {
  wpg::WalkingParameters parameters;
  parameters.max_step_yaw_change = 0.17;  // turning at 0.2 rad/s needs it (docs/formulation.md)
  wpg::GeneratorSettings settings;
  settings.algorithm = algorithm;
  settings.sqp_iterations = sqp_iterations;
  if (world) settings.max_obstacles_in_qp = 3;
  wpg::PatternGenerator generator(parameters, settings);
  if (world) generator.setObstacles(*world);
  const double T = parameters.sampling_period, dt = parameters.control_period;
  Eigen::Vector3d com_x = generator.comX(), com_y = generator.comY();
  double t = 0.0;
  auto advance = [&]() {
    for (int i = 0; i < 20; ++i) {
      wpg::integrateJerk(com_x, generator.plan().jerk_x, dt);
      wpg::integrateJerk(com_y, generator.plan().jerk_y, dt);
    }
    generator.advance(com_x, com_y);
    t += T;
  };
  auto start_walking = [&]() {
    for (int k = 0; k < 40; ++k) {  // start and reach steady walking
      generator.update(t, command);
      advance();
    }
  };
  start_walking();
  std::vector<double> samples;
  samples.reserve(1 << 20);
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(generator.update(t, command));
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(elapsed);
    if (samples.size() < samples.capacity()) samples.push_back(elapsed);
    advance();
    if (generator.lastSolve().status != wpg::IterationStatus::kSolved)
      state.SkipWithError("an NMPC iteration was not solved");
    if (world && (generator.problem().obstacle_slot.array() < 0).any())
      state.SkipWithError("fewer than three obstacles within reach");
    if (world && com_x(0) > kCorridorEnd) {
      // The walk reaches the corridor's end (after ~1200 iterations): start it again, untimed
      // (manual time), rather than time iterations with fewer obstacles.
      generator.reset();
      com_x = generator.comX();
      com_y = generator.comY();
      t = 0.0;
      start_walking();
    }
  }
  reportPercentiles(state, samples);
}

void BM_NmpcIterationForward(benchmark::State& state) {
  runIterations(state, {0.2, 0.0, 0.0}, wpg::GeneratorAlgorithm::kNmpc, 1);
}
void BM_NmpcIterationCurve(benchmark::State& state) {
  runIterations(state, {0.2, 0.0, 0.2}, wpg::GeneratorAlgorithm::kNmpc, 1);
}
void BM_NmpcConvergedSqpForward(benchmark::State& state) {
  runIterations(state, {0.2, 0.0, 0.0}, wpg::GeneratorAlgorithm::kNmpc, 0);
}
void BM_LmpcIterationCurve(benchmark::State& state) {
  runIterations(state, {0.2, 0.0, 0.2}, wpg::GeneratorAlgorithm::kLmpc, 1);
}
// Issue acceptance: three obstacles within reach of the previewed steps at every iteration
// (a corridor of circles, boxes and polygons on both sides; libwpg's exact 2-D distances).
void BM_NmpcIterationThreeObstacles(benchmark::State& state) {
  const std::vector<wpg::Obstacle> obstacles =
      wpg_test::obstacleCorridor(kCorridorObstacles, 1.0);
  runIterations(state, {0.2, 0.0, 0.0}, wpg::GeneratorAlgorithm::kNmpc, 1, &obstacles);
}
BENCHMARK(BM_NmpcIterationThreeObstacles)->UseManualTime()->Unit(benchmark::kMicrosecond)->MinTime(1.0);

BENCHMARK(BM_NmpcIterationForward)->UseManualTime()->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_NmpcIterationCurve)->UseManualTime()->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_NmpcConvergedSqpForward)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LmpcIterationCurve)->UseManualTime()->Unit(benchmark::kMicrosecond);

// The warm start's worth in time: the same 80 steady-walking problems of a forward walk solved
// with the active set of the previous sample shifted (as the generator does) or from an empty
// one (time per solve = the benchmark's time / solves). Counters: working-set updates per solve
// (qp_iterations, the warm start's loading included) and the dual iterations alone.
void solveSequence(benchmark::State& state, bool warm) {
  const wpg::WalkingParameters parameters;
  const wpg::GeneratorSettings settings;
  wpg::PatternGenerator generator(parameters, settings);
  std::vector<wpg::NmpcProblem> problems;
  std::vector<Eigen::VectorXd> guesses;
  std::vector<bool> completes;
  Eigen::Vector3d com_x = generator.comX(), com_y = generator.comY();
  for (int k = 0; k < 110; ++k) {
    const Eigen::VectorXd guess = generator.solver().plan();
    generator.update(k * parameters.sampling_period, Eigen::Vector3d(0.2, 0.0, 0.0));
    const bool complete = generator.phaseSample() == parameters.stepSamples() - 1;
    if (k >= 30) {
      problems.push_back(generator.problem());
      guesses.push_back(guess);
      completes.push_back(complete);
    }
    for (int i = 0; i < 20; ++i) {
      wpg::integrateJerk(com_x, generator.plan().jerk_x, parameters.control_period);
      wpg::integrateJerk(com_y, generator.plan().jerk_y, parameters.control_period);
    }
    generator.advance(com_x, com_y);
  }
  wpg::NmpcSolver solver(generator.model());
  long updates = 0, dual = 0, solves = 0;
  for (auto _ : state) {
    solver.clearActiveSet();
    for (std::size_t i = 0; i < problems.size(); ++i) {
      solver.plan() = guesses[i];
      if (!warm) solver.clearActiveSet();
      const wpg::NmpcSolveResult result = solver.solve(problems[i], settings);
      if (result.status != wpg::IterationStatus::kSolved) state.SkipWithError("not solved");
      updates += result.qp_iterations;
      dual += result.qp_iterations - result.qp_warm_start_updates;
      ++solves;
      if (warm) solver.shiftActiveSet(completes[i]);
    }
  }
  state.counters["solves"] = static_cast<double>(problems.size());  // per benchmark iteration
  state.counters["qp_iterations"] = static_cast<double>(updates) / std::max(1L, solves);
  state.counters["dual_iterations"] = static_cast<double>(dual) / std::max(1L, solves);
}
void BM_NmpcSolveWarmStart(benchmark::State& state) { solveSequence(state, true); }
void BM_NmpcSolveColdStart(benchmark::State& state) { solveSequence(state, false); }
BENCHMARK(BM_NmpcSolveWarmStart)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NmpcSolveColdStart)->Unit(benchmark::kMicrosecond);

// A 20 s walk as `wpg run` does it, in one process: generation, interpolation at 5 ms and
// the HDF5 dataset (written to a temporary file, then renamed).
void BM_Walk20sWithDataset(benchmark::State& state) {
  const std::string source = wpg_test::sourceDir();
  const wpg::datasets::Scenario scenario = wpg::datasets::loadScenario(
      source + "/datasets/scenarios/walk_forward.yaml", {"duration=20"}, source + "/robots");
  const std::string path = "/tmp/wpg_bench_walk20_" + std::to_string(::getpid()) + ".h5";
  for (auto _ : state) {
    const wpg::WalkResult result = wpg::generateWalk(scenario.walking, scenario.request);
    wpg::datasets::writeRunDataset(path, scenario, result);
    benchmark::DoNotOptimize(result.trajectory.size());
  }
  std::remove(path.c_str());
}
BENCHMARK(BM_Walk20sWithDataset)->Unit(benchmark::kMillisecond);

}  // namespace
