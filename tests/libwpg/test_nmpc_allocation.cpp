// The NMPC hot loop does not allocate: a warmed-up PatternGenerator::update() + advance()
// cycle is run with (a) Eigen's runtime malloc guard when wpg_core is built with
// EIGEN_RUNTIME_NO_MALLOC and (b) a process-wide count of malloc / calloc / realloc calls.
//
// The same for OnlineWalkingGenerator::step(), the per-control-period API (NMPC every 20th
// period, CoM and feet interpolation, command and push set every period), without and with
// obstacles (circle, box, polygon measured by libwpg's AnalyticObstacleDistance).
//
// And for the walk loop (runWalkLoop, walk_loop.hpp) that generateWalk and the walk to a goal
// run: whole warmed-up NMPC iterations with their control periods, a push, obstacles, the fall
// check, and the recording of the samples, logs and landed steps.
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
#include "wpg/lipm_prediction.hpp"
#include "wpg/online_walking_generator.hpp"
#include "wpg/pattern_generator.hpp"
#include "wpg/walk_loop.hpp"

// Sanitizers replace the allocator themselves: no interposition there. Under AddressSanitizer
// (scripts/test-sanitizers.sh) the count comes from its allocation hook instead, which its
// allocator calls for every malloc, calloc, realloc, memalign and operator new.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define WPG_ALLOCATION_TEST_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define WPG_ALLOCATION_TEST_SANITIZED 1
#endif
#if defined(__GLIBC__) && !defined(WPG_ALLOCATION_TEST_SANITIZED)
#define WPG_ALLOCATION_COUNTER 1
#define WPG_ALLOCATION_COUNTER_INTERPOSED 1
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
}
#elif defined(WPG_ALLOCATION_TEST_SANITIZED)
#define WPG_ALLOCATION_COUNTER 1
// Declared in <sanitizer/allocator_interface.h> (compiler-rt and GCC's libsanitizer alike).
extern "C" int __sanitizer_install_malloc_and_free_hooks(
    void (*malloc_hook)(const volatile void*, std::size_t),
    void (*free_hook)(const volatile void*));
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

namespace {

using Eigen::Vector3d;
using wpg::GeneratorAlgorithm;
using wpg::GeneratorSettings;
using wpg::PatternGenerator;
using wpg::WalkingParameters;

struct Counts {
  long allocations = 0;  // malloc / calloc / realloc calls
};

void startCounting() {
#ifdef EIGEN_RUNTIME_NO_MALLOC
  Eigen::internal::set_is_malloc_allowed(false);
#endif
#if WPG_ALLOCATION_COUNTER
  g_allocations = 0;
  g_counting = true;
#endif
}

Counts stopCounting() {
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

bool counterAvailable() {
#if WPG_ALLOCATION_COUNTER && !defined(WPG_ALLOCATION_COUNTER_INTERPOSED)
  return g_hook_installed != 0;
#elif WPG_ALLOCATION_COUNTER
  return true;
#else
  return false;
#endif
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

// --- The walk loop: whole NMPC iterations, recording included ------------------------------

// The request's schedule (as ScheduledCommands); counts the allocations of the iterations
// [first_counted, end) and ends the walk at `end`, so that each counted iteration runs whole:
// its command, its control periods with push and fall check, and the recording.
class CountingCommands final : public wpg::CommandSource {
 public:
  CountingCommands(const wpg::WalkRequest& request, int first_counted, int end)
      : request_(request), first_counted_(first_counted), end_(end) {}
  bool nextCommand(int iteration, double time, wpg::OnlineWalkingGenerator&,
                   Vector3d& command) override {
    if (iteration == first_counted_) startCounting();
    if (iteration == end_) {
      counts = stopCounting();
      return false;
    }
    command = request_.commandAt(time);
    return true;
  }
  Counts counts;

 private:
  const wpg::WalkRequest& request_;
  int first_counted_, end_;
};

// A walk that calls an observer too (the hooks robots/ uses), without allocating itself.
class CountingObserver final : public wpg::ControlLoopObserver {
 public:
  void beforeStep(wpg::OnlineWalkingGenerator&) override { ++before; }
  void afterStep(wpg::OnlineWalkingGenerator&, const wpg::ControlSample&) override { ++after; }
  long before = 0, after = 0;
};

TEST(NmpcAllocation, WalkLoopIterations) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  w.max_step_yaw_change = 0.17;
  wpg::WalkRequest request;
  request.duration = 20.0;
  request.reference = {{0.0, Vector3d(0.2, 0.0, 0.0)}, {7.0, Vector3d(0.2, 0.0, 0.2)},
                       {10.0, Vector3d(0.2, 0.0, 0.0)}};
  wpg::Push push;
  push.t = 8.0;
  push.force = Eigen::Vector2d(0.0, 30.0);
  push.duration = 0.1;
  request.pushes = {push};
  wpg::Obstacle circle;
  circle.center = Eigen::Vector2d(2.0, 0.9);
  circle.radius = 0.2;
  circle.margin = 0.1;
  request.obstacles = {circle};
  request.validate();
  wpg::OnlineWalkingGenerator generator(w, request.generator);
  generator.setObstacles(request.obstacles);
  const int first_counted = 30, end = 130;  // 3 s of warm-up, 10 s counted
  CountingCommands commands(request, first_counted, end);
  CountingObserver observer;
  const wpg::WalkResult result = wpg::runWalkLoop(generator, request, commands, &observer);

  EXPECT_EQ(commands.counts.allocations, 0)
      << "malloc/calloc/realloc calls in the walk loop (run under gdb, break "
         "wpg_test_allocation_seen)";
  // The counted iterations did what a walk does: NMPC iterations logged, feet landed, a push.
  EXPECT_TRUE(result.success) << result.message;
  const int periods = static_cast<int>(std::lround(w.sampling_period / w.control_period));
  EXPECT_EQ(result.trajectory.mpc.size(), static_cast<std::size_t>(end));
  EXPECT_EQ(result.trajectory.size(), static_cast<std::size_t>(end * periods + 1));
  EXPECT_EQ(observer.after, static_cast<long>(end) * periods);
  EXPECT_EQ(observer.before, observer.after);
  int landed_while_counted = 0;
  for (const wpg::Footstep& step : result.trajectory.footsteps)
    if (step.landing_time > first_counted * w.sampling_period) ++landed_while_counted;
  EXPECT_GE(landed_while_counted, 10);
  // The push is the part of the CoM acceleration the CoP does not explain (eq. 3:
  // z = c - h/g c'' of the controlled acceleration).
  const wpg::WalkTrajectory& out = result.trajectory;
  const double push_acceleration = push.force.y() / request.robot_mass;
  bool pushed = false;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double controlled = (out.com[i].y() - out.cop[i].y()) * w.gravity / w.com_height;
    if (out.time[i] > first_counted * w.sampling_period && out.time[i] < end * w.sampling_period)
      pushed = pushed || std::abs(out.com_acc[i].y() - controlled - push_acceleration) < 1e-6;
  }
  EXPECT_TRUE(pushed) << "the push must act inside the counted iterations";
}

// The progress monitor (wpg/progress_monitor.hpp) fed at every NMPC sample while the robot
// is blocked: walking into a wall with no way round, counted from 10 s to 25 s (found blocked
// at 13.7 s), the windows judged and the stretch kept without allocating.
TEST(NmpcAllocation, WalkLoopIterationsWhileBlocked) {
  if (!counterAvailable()) GTEST_SKIP() << "no allocation counter (needs glibc or ASan)";
  WalkingParameters w;
  wpg::WalkRequest request;
  request.duration = 30.0;
  request.reference = {{0.0, Vector3d::Zero()}, {1.0, Vector3d(0.2, 0.0, 0.0)}};
  wpg::Obstacle wall;
  wall.type = wpg::ObstacleType::kBox;
  wall.center = Eigen::Vector2d(2.0, 0.0);
  wall.size = Eigen::Vector2d(0.3, 6.0);
  wall.margin = 0.2;
  request.obstacles = {wall};
  request.validate();
  wpg::OnlineWalkingGenerator generator(w, request.generator);
  generator.setObstacles(request.obstacles);
  CountingCommands commands(request, 100, 250);
  const wpg::WalkResult result = wpg::runWalkLoop(generator, request, commands);
  EXPECT_EQ(commands.counts.allocations, 0)
      << "malloc/calloc/realloc calls in the walk loop while blocked";
  EXPECT_TRUE(result.blocked) << result.message;
  EXPECT_LT(result.blocked_since + 4.8, 25.0);  // found inside the counted iterations
}

}  // namespace
