// The NMPC hot loop does not allocate: a warmed-up PatternGenerator::update() + advance()
// cycle is run with (a) Eigen's runtime malloc guard when wpg_core is built with
// EIGEN_RUNTIME_NO_MALLOC and (b) a process-wide count of malloc / calloc / realloc calls.
//
// The same for OnlineWalkingGenerator::step(), the per-control-period API (NMPC every 20th
// period, CoM and feet interpolation, command and push set every period), without and with
// obstacles (circle, box, polygon measured by libwpg's AnalyticObstacleDistance).
//
// The walk loop's (test_walk_loop_allocation.cpp) counts with the counter of this file
// (allocation_counter.hpp).
//
// The counter interposes the C allocator of the executable with definitions forwarding to
// glibc's __libc_* entry points (malloc to __libc_memalign with malloc's own alignment) (operator new of libstdc++ and Eigen's aligned_malloc go
// through malloc). The definitions are weak because another test TU of the same executable
// may define its own malloc (test_dense_qp_solver.cpp does: a strong malloc forwarding to
// __libc_malloc), which then wins at link time. To still see every malloc in that case, this
// file also defines (weak) __libc_malloc, which such a forwarding malloc calls: it counts
// and forwards to glibc's __libc_memalign with the default alignment, the same allocator
// path (libc's internal calls never go through these symbols). CounterSeesAllocations checks
// that the counter sees a plain malloc and an Eigen allocation whichever malloc is linked.
//
// To find the caller of an unexpected allocation:
//   gdb -batch -ex 'break wpg_test_allocation_seen' -ex run -ex bt
//       --args build-ut/tests/wpg_libwpg_tests --gtest_filter='NmpcAllocation.*'
// (one command line).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "../common/obstacle_fields.hpp"
#include "../common/paper_gait.hpp"
#include "../common/sanitizer_malloc.hpp"
#include "allocation_counter.hpp"
#include "wpg/lipm_prediction.hpp"
#include "wpg/online_walking_generator.hpp"
#include "wpg/pattern_generator.hpp"
#include "wpg/walk_loop.hpp"

// Sanitizers replace the allocator themselves: no interposition there. Under AddressSanitizer
// and ThreadSanitizer the count comes from their allocation hook instead, which their
// allocator calls for every malloc, calloc, realloc, memalign and operator new
// (sanitizer_malloc.hpp).
#if defined(__GLIBC__) && !defined(WPG_TEST_SANITIZER_OWNS_MALLOC)
#define WPG_ALLOCATION_COUNTER 1
#define WPG_ALLOCATION_COUNTER_INTERPOSED 1
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
}
#elif defined(WPG_TEST_SANITIZER_OWNS_MALLOC)
#define WPG_ALLOCATION_COUNTER 1
#endif

#if WPG_ALLOCATION_COUNTER
namespace {
volatile bool g_counting = false;
volatile long g_allocations = 0;
}  // namespace

// Break here in a debugger to see who allocates inside a counted region.
extern "C" __attribute__((noinline, used)) void wpg_test_allocation_seen() {
  asm volatile("" ::: "memory");
}

namespace {
inline void countAllocation() {
  if (g_counting) {
    g_allocations = g_allocations + 1;
    wpg_test_allocation_seen();
  }
}
}  // namespace

#ifdef WPG_ALLOCATION_COUNTER_INTERPOSED
extern "C" __attribute__((weak)) void* malloc(std::size_t size) {
  countAllocation();
  return __libc_memalign(alignof(std::max_align_t), size);
}
extern "C" __attribute__((weak)) void* calloc(std::size_t count, std::size_t size) {
  countAllocation();
  return __libc_calloc(count, size);
}
extern "C" __attribute__((weak)) void* realloc(void* pointer, std::size_t size) {
  countAllocation();
  return __libc_realloc(pointer, size);
}
// Reached when another TU's malloc (forwarding to __libc_malloc) is the one linked.
extern "C" __attribute__((weak)) void* __libc_malloc(std::size_t size) {
  countAllocation();
  return __libc_memalign(alignof(std::max_align_t), size);
}
#else
namespace {
void countHookedAllocation(const volatile void*, std::size_t) { countAllocation(); }
void ignoreFree(const volatile void*) {}
const int g_hook_installed =
    __sanitizer_install_malloc_and_free_hooks(countHookedAllocation, ignoreFree);
}  // namespace
#endif
#endif

void wpg_test::startCounting() {
#ifdef EIGEN_RUNTIME_NO_MALLOC
  Eigen::internal::set_is_malloc_allowed(false);
#endif
#if WPG_ALLOCATION_COUNTER
  g_allocations = 0;
  g_counting = true;
#endif
}

wpg_test::Counts wpg_test::stopCounting() {
  Counts counts;
#if WPG_ALLOCATION_COUNTER
  g_counting = false;
  counts.allocations = g_allocations;
#endif
#ifdef EIGEN_RUNTIME_NO_MALLOC
  Eigen::internal::set_is_malloc_allowed(true);
#endif
  return counts;
}

bool wpg_test::counterAvailable() {
#if WPG_ALLOCATION_COUNTER && !defined(WPG_ALLOCATION_COUNTER_INTERPOSED)
  return g_hook_installed != 0;
#elif WPG_ALLOCATION_COUNTER
  return true;
#else
  return false;
#endif
}

namespace {

using Eigen::Vector3d;
using wpg::GeneratorAlgorithm;
using wpg::GeneratorSettings;
using wpg::PatternGenerator;
using wpg::WalkingParameters;
using wpg_test::Counts;
using wpg_test::counterAvailable;
using wpg_test::startCounting;
using wpg_test::stopCounting;

// One NMPC sample: solve, integrate the CoM over the sampling period at the control period
// with the planned jerk, end the period.
void runSample(PatternGenerator& generator, double t, const Vector3d& command) {
  generator.update(t, command);
  Vector3d com_x = generator.comX(), com_y = generator.comY();
  const auto& plan = generator.plan();
  for (int i = 0; i < 20; ++i) {
    wpg::integrateJerk(com_x, plan.jerk_x, 0.005);
    wpg::integrateJerk(com_y, plan.jerk_y, 0.005);
  }
  generator.advance(com_x, com_y);
}

struct Segment {
  int samples;
  Vector3d command;
};

struct LoopResult {
  Counts counts;
  int patterns_seen = 0;  // bit mask of Hessian patterns solved in the counted region
  int non_solved = 0;
  std::string where;      // samples that allocated: "sample (pattern, equality rows): count"
  int obstacles_in_qp = 0;  // bit mask of the obstacles that entered the QP (online loop)
};

long allocationsSoFar() {
#if WPG_ALLOCATION_COUNTER
  return g_allocations;
#else
  return 0;
#endif
}

// What one counted sample did.
struct SampleRecord {
  long allocations = 0;
  int status = 0;       // IterationStatus
  int pattern = 0;      // Hessian pattern
  int equalities = -1;  // equality rows of the QP (-1: not recorded)
};

// Counts allocations over the samples of `counted`: run(command) runs one NMPC sample,
// describe() says what it was (status, pattern, equalities) without allocating.
template <class Run, class Describe>
LoopResult countOverSamples(const std::vector<Segment>& counted, Run run, Describe describe) {
  constexpr int kMax = 512;
  SampleRecord records[kMax];
  int n = 0;
  startCounting();
  for (const Segment& s : counted) {
    for (int i = 0; i < s.samples; ++i, ++n) {
      const long before = allocationsSoFar();
      run(s.command);
      if (n < kMax) {
        const long allocations = allocationsSoFar() - before;
        records[n] = describe();
        records[n].allocations = allocations;
      }
    }
  }
  LoopResult result;
  result.counts = stopCounting();
  for (int i = 0; i < n && i < kMax; ++i) {
    const SampleRecord& r = records[i];
    result.patterns_seen |= 1 << r.pattern;
    if (r.status != 0) ++result.non_solved;
    if (r.allocations > 0 && result.where.size() < 400) {
      result.where += " " + std::to_string(i) + " (pattern " + std::to_string(r.pattern) +
                      ", me " + std::to_string(r.equalities) + "): " +
                      std::to_string(r.allocations) + ";";
    }
  }
  return result;
}

// Warms up with `warmup`, calls `before_counting` (e.g. to give new obstacles: that allocates),
// then counts allocations over `counted`; `statuses` (when given) gets the status of each
// counted sample.
template <class BeforeCounting>
LoopResult countOverLoop(const WalkingParameters& w, const GeneratorSettings& settings,
                         const std::vector<Segment>& warmup, const std::vector<Segment>& counted,
                         BeforeCounting before_counting, std::vector<int>* statuses = nullptr) {
  PatternGenerator generator(w, settings);
  int k = 0;
  for (const Segment& s : warmup)
    for (int i = 0; i < s.samples; ++i, ++k) runSample(generator, k * w.sampling_period, s.command);
  before_counting(generator, k);
  int status_seen[256] = {0};
  const LoopResult result = countOverSamples(
      counted,
      [&](const Vector3d& command) { runSample(generator, k++ * w.sampling_period, command); },
      [&] {
        SampleRecord r;
        r.status = static_cast<int>(generator.lastSolve().status);
        r.pattern = generator.problem().phase.pattern;
        r.equalities = static_cast<int>(
            generator.solver().workspace().solver.equalityMultipliers().size());
        ++status_seen[r.status];
        return r;
      });
  if (statuses) statuses->assign(status_seen, status_seen + 256);
  return result;
}

LoopResult countOverLoop(const WalkingParameters& w, GeneratorAlgorithm algorithm,
                         const std::vector<Segment>& warmup, const std::vector<Segment>& counted) {
  GeneratorSettings settings;
  settings.algorithm = algorithm;
  return countOverLoop(w, settings, warmup, counted, [](PatternGenerator&, int&) {});
}

void expectNoAllocation(const LoopResult& r, const char* what) {
  EXPECT_EQ(r.counts.allocations, 0) << what << ": malloc/calloc/realloc calls in the hot loop "
                                     << "(run under gdb, break wpg_test_allocation_seen); "
                                     << "samples that allocated:" << r.where;
  EXPECT_EQ(r.non_solved, 0) << what << ": some samples were not solved";
}

TEST(NmpcAllocation, CounterSeesAllocations) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  // Positive controls: the counter is live for a plain malloc, an Eigen heap object and a
  // std container, whichever malloc definition the executable links.
  void* (*volatile allocate)(std::size_t) = &std::malloc;
  startCounting();
  void* p = allocate(40);
  const Counts plain = stopCounting();
  std::free(p);
  EXPECT_GT(plain.allocations, 0);

  static Eigen::VectorXd* eigen_sink = nullptr;
  static std::vector<double>* std_sink = nullptr;
  eigen_sink = new Eigen::VectorXd;
  startCounting();
  eigen_sink->resize(1000);
  const Counts eigen = stopCounting();
  EXPECT_GT(eigen.allocations, 0);
  startCounting();
  std_sink = new std::vector<double>(100, 1.0);
  const Counts container = stopCounting();
  EXPECT_GT(container.allocations, 0);
  delete eigen_sink;
  delete std_sink;
}

const std::vector<int> kAllWalkingPatterns{0, 1, 2, 3, 4, 5, 6, 7};

int maskOf(const std::vector<int>& patterns) {
  int mask = 0;
  for (int p : patterns) mask |= 1 << p;
  return mask;
}

TEST(NmpcAllocation, NmpcWalkForward) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  const WalkingParameters w;
  const Vector3d forward(0.2, 0.0, 0.0);
  const LoopResult r =
      countOverLoop(w, GeneratorAlgorithm::kNmpc, {{30, forward}}, {{40, forward}});
  EXPECT_EQ(r.patterns_seen & maskOf(kAllWalkingPatterns), maskOf(kAllWalkingPatterns));
  expectNoAllocation(r, "NMPC, walk forward");
}

TEST(NmpcAllocation, NmpcCurve) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  const Vector3d curve(0.2, 0.0, 0.2);
  const LoopResult r = countOverLoop(w, GeneratorAlgorithm::kNmpc, {{30, curve}}, {{40, curve}});
  EXPECT_EQ(r.patterns_seen & maskOf(kAllWalkingPatterns), maskOf(kAllWalkingPatterns));
  expectNoAllocation(r, "NMPC, curve");
}

// The registered extensions (wpg/nmpc/extension_registry.hpp) in the loop: the corridor's rows
// and the look-at cost, whose Q + R'R is factored every QP in the workspace's storage.
TEST(NmpcAllocation, NmpcWithCorridorAndLookAt) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  GeneratorSettings settings;
  settings.constraints = {{"corridor", {{"left", 0.25}, {"right", -0.35}}}};
  settings.costs = {{"look_at", {{"x", 6.0}, {"y", 1.0}, {"weight", 50.0}}}};
  const Vector3d drift(0.2, 0.05, 0.0);
  const LoopResult r = countOverLoop(w, settings, {{30, drift}}, {{60, drift}},
                                     [](PatternGenerator&, int&) {});
  EXPECT_EQ(r.patterns_seen & maskOf(kAllWalkingPatterns), maskOf(kAllWalkingPatterns));
  expectNoAllocation(r, "NMPC with a corridor and a look-at cost");
}

TEST(NmpcAllocation, LmpcWalkForwardAndCurve) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  const Vector3d forward(0.2, 0.0, 0.0), curve(0.2, 0.0, 0.2);
  const LoopResult a = countOverLoop(w, GeneratorAlgorithm::kLmpc, {{30, forward}}, {{40, forward}});
  expectNoAllocation(a, "LMPC, walk forward");
  const LoopResult b = countOverLoop(w, GeneratorAlgorithm::kLmpc, {{30, curve}}, {{40, curve}});
  expectNoAllocation(b, "LMPC, curve");
  EXPECT_EQ(b.patterns_seen & maskOf(kAllWalkingPatterns), maskOf(kAllWalkingPatterns));
}

// Standing, starting, stopping and the standing pattern: the warm-up runs the same cycle once.
TEST(NmpcAllocation, StartStopCycle) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  const Vector3d zero = Vector3d::Zero(), forward(0.2, 0.0, 0.0), curve(0.2, 0.0, 0.2);
  const std::vector<Segment> cycle{{5, zero}, {25, forward}, {10, curve}, {30, zero}};
  for (GeneratorAlgorithm algorithm : {GeneratorAlgorithm::kNmpc, GeneratorAlgorithm::kLmpc}) {
    const LoopResult r = countOverLoop(w, algorithm, cycle, cycle);
    const int all = (1 << (w.stepSamples() + 1)) - 1;  // walking 0..S-1 and standing S
    EXPECT_EQ(r.patterns_seen, all);
    expectNoAllocation(r, algorithm == GeneratorAlgorithm::kNmpc ? "NMPC start/stop"
                                                                 : "LMPC start/stop");
  }
}

// Relaxed iterations: a large obstacle given on the landing spot of the swing foot makes the
// QP infeasible and the obstacle rows are relaxed (up to three relaxation stages are tried).
TEST(NmpcAllocation, RelaxedObstacleIterations) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  // The paper's gait, for which the wall below blocks the landing (the default gait's yaw
  // freedom steps round it).
  const WalkingParameters w = wpg_test::paperGait();
  GeneratorSettings settings;
  const Vector3d forward(0.2, 0.0, 0.0);
  auto block_the_landing = [&](PatternGenerator& generator) {
    std::vector<wpg::Obstacle> obstacles = wpg_test::obstacleCorridor(40, 0.9);
    wpg::Obstacle wall;
    wall.center = generator.plan().swing_target.head<2>() + Eigen::Vector2d(0.25, 0.0);
    wall.radius = 0.3;
    wall.margin = 0.05;
    obstacles.push_back(wall);
    generator.setObstacles(obstacles);
  };
  // The same situation once before counting (every buffer of the relaxed solves touched).
  std::vector<int> statuses;
  const LoopResult r = countOverLoop(
      w, settings, {{40, forward}}, {{30, forward}},
      [&](PatternGenerator& generator, int& k) {
        block_the_landing(generator);
        for (int i = 0; i < 30; ++i, ++k) runSample(generator, k * w.sampling_period, forward);
        block_the_landing(generator);
      },
      &statuses);
  EXPECT_GT(statuses[static_cast<int>(wpg::IterationStatus::kRelaxedObstacle)], 0)
      << "the test should force relaxed iterations";
  EXPECT_EQ(r.counts.allocations, 0) << "samples that allocated:" << r.where;
}

// --- OnlineWalkingGenerator: warmed-up control periods ----------------------------------

// Warms up with `warmup`, then counts allocations over `counted` (segments in NMPC samples of
// 20 control periods; the command is set at every period, a push in two of them, opposite).
LoopResult countOverOnlineLoop(const WalkingParameters& w, std::vector<wpg::Obstacle> obstacles,
                               const std::vector<Segment>& warmup,
                               const std::vector<Segment>& counted) {
  GeneratorSettings settings;
  if (!obstacles.empty()) settings.max_obstacles_in_qp = static_cast<int>(obstacles.size());
  wpg::OnlineWalkingGenerator generator(w, settings);
  generator.setObstacles(std::move(obstacles));
  const int periods = static_cast<int>(std::lround(w.sampling_period / w.control_period));
  const Eigen::Vector2d push(0.0, 0.3);
  auto sample = [&](const Vector3d& command) {
    for (int i = 0; i < periods; ++i) {
      generator.setCommand(command);
      if (i == 3 || i == 13) generator.setPushAcceleration(i == 3 ? push : Eigen::Vector2d(-push));
      generator.step();
    }
  };
  for (const Segment& s : warmup)
    for (int i = 0; i < s.samples; ++i) sample(s.command);
  int obstacles_in_qp = 0;
  LoopResult result = countOverSamples(counted, sample, [&] {
    SampleRecord r;
    r.status = static_cast<int>(generator.lastIteration().status);
    r.pattern = generator.patternGenerator().problem().phase.pattern;
    const Eigen::VectorXi& slots = generator.patternGenerator().problem().obstacle_slot;
    for (int k = 0; k < slots.size(); ++k)
      if (slots(k) >= 0) obstacles_in_qp |= 1 << slots(k);
    return r;
  });
  result.obstacles_in_qp = obstacles_in_qp;
  EXPECT_FALSE(generator.fallen());
  return result;
}

TEST(NmpcAllocation, OnlineStepStartStopCycle) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  const Vector3d zero = Vector3d::Zero(), forward(0.2, 0.0, 0.0), curve(0.2, 0.0, 0.2);
  const std::vector<Segment> cycle{{5, zero}, {25, forward}, {10, curve}, {30, zero}};
  const LoopResult r = countOverOnlineLoop(w, {}, cycle, cycle);
  EXPECT_EQ(r.patterns_seen, (1 << (w.stepSamples() + 1)) - 1);  // walking 0..S-1, standing S
  expectNoAllocation(r, "OnlineWalkingGenerator::step(), start/walk/curve/stop");
}

// The swing reach (robots/hrp2/walking.yaml's 2 m/s, 50 m/s^2): its bounds are computed from
// the swing foot at every sample, from the trajectory in force or a foot at rest.
TEST(NmpcAllocation, OnlineStepWithTheSwingReach) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  w.max_swing_speed = 2.0;
  w.max_swing_acceleration = 50.0;
  const Vector3d zero = Vector3d::Zero(), forward(0.2, 0.0, 0.0), curve(0.2, 0.0, 0.2);
  const std::vector<Segment> cycle{{5, zero}, {25, forward}, {10, curve}, {30, zero}};
  const LoopResult r = countOverOnlineLoop(w, {}, cycle, cycle);
  EXPECT_EQ(r.patterns_seen, (1 << (w.stepSamples() + 1)) - 1);
  expectNoAllocation(r, "OnlineWalkingGenerator::step() with the swing reach");
}

TEST(NmpcAllocation, OnlineStepWithCircleBoxAndPolygon) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  wpg::Obstacle circle;
  circle.center = Eigen::Vector2d(1.5, 0.9);
  circle.radius = 0.2;
  circle.margin = 0.1;
  wpg::Obstacle box;
  box.type = wpg::ObstacleType::kBox;
  box.center = Eigen::Vector2d(2.5, -0.9);
  box.size = Eigen::Vector2d(0.3, 0.4);
  box.yaw = 0.3;
  box.margin = 0.1;
  wpg::Obstacle polygon;
  polygon.type = wpg::ObstacleType::kPolygon;
  polygon.vertices = {{3.5, 0.7}, {4.0, 0.8}, {3.8, 1.2}, {3.4, 1.1}};
  polygon.margin = 0.05;
  const Vector3d forward(0.2, 0.0, 0.0);
  const LoopResult r =
      countOverOnlineLoop(w, {circle, box, polygon}, {{30, forward}}, {{100, forward}});
  EXPECT_EQ(r.patterns_seen & maskOf(kAllWalkingPatterns), maskOf(kAllWalkingPatterns));
  EXPECT_EQ(r.obstacles_in_qp, 7) << "each obstacle must enter the QP in the counted loop";
  expectNoAllocation(r, "OnlineWalkingGenerator::step() with a circle, a box and a polygon");
}

// obstacle_linearization: command_tangent (tangent normals, the selector's side and border
// memory, J1's reference turned along the border): a circle on the path, in the QP throughout.
TEST(NmpcAllocation, OnlineStepWithCommandTangentObstacleOnThePath) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  w.obstacle_linearization = wpg::ObstacleLinearization::kCommandTangent;
  wpg::Obstacle circle;
  circle.center = Eigen::Vector2d(1.4, 0.0);
  circle.radius = 0.25;
  circle.margin = 0.25;
  const Vector3d forward(0.2, 0.0, 0.0);
  const LoopResult r = countOverOnlineLoop(w, {circle}, {{30, forward}}, {{100, forward}});
  EXPECT_EQ(r.obstacles_in_qp, 1);
  expectNoAllocation(r, "OnlineWalkingGenerator::step() with a command_tangent circle");
}

}  // namespace
