// The NMPC real-time iterations of bench_nmpc.cpp's BM_NmpcIteration* with a fixed count, for
// an instruction count that a loaded machine cannot disturb (docs/testing.md, "Benchmarks"):
//   valgrind --tool=callgrind --toggle-collect='*measuredUpdate*' \
//       build/tests/wpg_nmpc_instruction_count forward 400
// counts the instructions of the 400 iterations alone (callgrind's "Collected"); divided by the
// count, the instructions per iteration. It also prints a digest of every plan the iterations
// produced (the bits of U): two builds that print the same digest walked the same, bit for bit.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "wpg/lipm_prediction.hpp"
#include "wpg/pattern_generator.hpp"
#include "../common/obstacle_fields.hpp"

namespace {

// Kept out of line so that callgrind's --toggle-collect can find it by name.
__attribute__((noinline)) const wpg::MpcIterationLog& measuredUpdate(
    wpg::PatternGenerator& generator, double time, const Eigen::Vector3d& command) {
  return generator.update(time, command);
}

// FNV-1a over the bytes of the plan.
std::uint64_t digest(std::uint64_t hash, const Eigen::VectorXd& plan) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(plan.data());
  for (std::size_t i = 0; i < static_cast<std::size_t>(plan.size()) * sizeof(double); ++i) {
    hash ^= bytes[i];
    hash *= 1099511628211ULL;
  }
  return hash;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "forward";
  const int count = argc > 2 ? std::atoi(argv[2]) : 400;
  Eigen::Vector3d command(0.2, 0.0, 0.0);
  wpg::GeneratorSettings settings;
  settings.algorithm = wpg::GeneratorAlgorithm::kNmpc;
  settings.sqp_iterations = 1;
  const std::vector<wpg::Obstacle> corridor = wpg_test::obstacleCorridor(60, 1.0);
  const bool obstacles = which == "obstacles";
  if (which == "curve") {
    command.z() = 0.2;
  } else if (which == "lmpc") {
    command.z() = 0.2;
    settings.algorithm = wpg::GeneratorAlgorithm::kLmpc;
  } else if (which != "forward" && !obstacles) {
    std::fprintf(stderr, "usage: %s forward|curve|obstacles|lmpc [iterations]\n", argv[0]);
    return 2;
  }
  if (obstacles) settings.max_obstacles_in_qp = 3;
  wpg::WalkingParameters parameters;
  parameters.max_step_yaw_change = 0.17;  // as bench_nmpc.cpp
  wpg::PatternGenerator generator(parameters, settings);
  if (obstacles) generator.setObstacles(corridor);
  const double T = parameters.sampling_period, dt = parameters.control_period;
  Eigen::Vector3d com_x = generator.comX(), com_y = generator.comY();
  double t = 0.0;
  std::uint64_t hash = 1469598103934665603ULL;
  int qp_iterations = 0, unsolved = 0;
  for (int k = 0; k < 40 + count; ++k) {
    const wpg::MpcIterationLog& log = k < 40 ? generator.update(t, command)
                                             : measuredUpdate(generator, t, command);
    if (k >= 40) {
      qp_iterations += log.qp_iterations;
      if (generator.lastSolve().status != wpg::IterationStatus::kSolved) ++unsolved;
    }
    hash = digest(hash, generator.solver().plan());
    for (int i = 0; i < 20; ++i) {
      wpg::integrateJerk(com_x, generator.plan().jerk_x, dt);
      wpg::integrateJerk(com_y, generator.plan().jerk_y, dt);
    }
    generator.advance(com_x, com_y);
    t += T;
  }
  std::printf("%s: %d iterations, %.2f QP updates per iteration, %d not solved, digest %016llx\n",
              which.c_str(), count, static_cast<double>(qp_iterations) / count, unsolved,
              static_cast<unsigned long long>(hash));
  return 0;
}
