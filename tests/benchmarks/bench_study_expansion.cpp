// A lazy study's runs (study_runs.hpp), made from their index in a study of 10^7 runs (a grid
// of 100 x 100 crossed with 1000 random samples): the description (name and swept values: the
// index arithmetic over the grid and the random generator's draw) and the whole run (its
// scenario loaded and validated as `wpg run` does: what a worker does before a walk). Also
// loading the study itself, which checks kCheckedStudyRuns runs whatever its size. Numbers:
// docs/studies.md.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>

#include "wpg/datasets/study_design/study.hpp"
#include "../common/source_dir.hpp"

namespace {

const std::string kSource = wpg_test::sourceDir();

// A study file of 10^7 runs in the temporary folder: its path.
std::string tenMillionRunStudy() {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "wpg_bench_study_expansion.yaml";
  std::ofstream file(path);
  file << "name: ten_million\nbase: walk_forward\nsweep:\n  grid:\n"
       << "    walking.weight_cop: [";
  for (int i = 0; i < 100; ++i) file << (i ? ", " : "") << 300 + 10 * i;
  file << "]\n    \"reference[1].v\": [";
  for (int i = 0; i < 100; ++i) file << (i ? ", " : "") << "[" << 0.1 + 0.002 * i << ", 0, 0]";
  file << "]\n  random:\n    samples: 1000\n    seed: 1\n"
       << "    keys: {walking.com_height: {uniform: [0.78, 0.84]}}\n";
  return path.string();
}

wpg::datasets::Study loadTenMillion() {
  return wpg::datasets::loadStudy(
      tenMillionRunStudy(),
      [](const std::string& base) { return kSource + "/datasets/scenarios/" + base + ".yaml"; },
      kSource + "/robots");
}

void BM_StudyLoad(benchmark::State& state) {
  for (auto _ : state) {
    const wpg::datasets::Study study = loadTenMillion();
    benchmark::DoNotOptimize(study.runs.size());
  }
}
BENCHMARK(BM_StudyLoad)->Unit(benchmark::kMillisecond);

void BM_RunDescription(benchmark::State& state) {
  const wpg::datasets::Study study = loadTenMillion();
  std::size_t index = 0;
  for (auto _ : state) {
    const wpg::datasets::StudyRun run = study.runs.describe(index);
    benchmark::DoNotOptimize(run.swept.data());
    index = (index + 7919) % study.runs.size();  // any run: a prime stride over the grid
  }
}
BENCHMARK(BM_RunDescription)->Unit(benchmark::kMicrosecond);

void BM_RunScenario(benchmark::State& state) {
  const wpg::datasets::Study study = loadTenMillion();
  std::size_t index = 0;
  for (auto _ : state) {
    const wpg::datasets::StudyRun run = study.runs[index];
    benchmark::DoNotOptimize(run.scenario.walking.com_height);
    index = (index + 7919) % study.runs.size();
  }
}
BENCHMARK(BM_RunScenario)->Unit(benchmark::kMicrosecond);

}  // namespace
