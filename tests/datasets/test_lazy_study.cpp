// Lazy studies (wpg/datasets/study_design/study_runs.hpp): run i made from i alone is the run
// of the list the expansion used to build (grid index arithmetic, the random generator drawn in
// order), whatever order the runs are asked in; a study of 10^7 runs loads with a bounded
// number of checked runs; a run left unchecked and refused by the scenario is named when made.
#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "wpg/datasets/study_design/study.hpp"

namespace fs = std::filesystem;
using wpg::datasets::InputError;
using wpg::datasets::Study;
using wpg::datasets::StudyRun;

namespace {

class LazyStudy : public wpg_test::ScratchDirectoryTest {
 protected:
  LazyStudy() : ScratchDirectoryTest("wpg_test_lazy_study") {}

  Study load(const std::string& text, int threads = 1) {
    const fs::path path = directory_ / "study.yaml";
    std::ofstream(path) << text;
    return wpg::datasets::loadStudy(
        path.string(),
        [](const std::string& base) { return wpg_test::kScenariosDir + "/" + base + ".yaml"; },
        wpg_test::kRobotsDir, threads);
  }
};

std::string numberList(int count, double first, double step) {
  std::string text = "[";
  for (int i = 0; i < count; ++i) text += (i ? ", " : "") + std::to_string(first + step * i);
  return text + "]";
}

}  // namespace

// The draw n of a seeded generator, computed from n, is the n-th of the sequence, bit for bit.
TEST(LazyRandom, DrawNIsTheNthOfTheSequence) {
  for (const std::uint64_t seed : {0ull, 7ull, 1ull << 40}) {
    std::uint64_t state = seed;
    for (std::uint64_t n = 0; n < 2000; ++n) {
      const double sequential = wpg::datasets::nextUniform(&state);
      ASSERT_EQ(wpg::datasets::uniformAt(seed, n), sequential) << "seed " << seed << " draw " << n;
    }
  }
}

// Every run of a grid x zip x random sweep, made from its index, holds the values of the list
// built in order (grid first key slowest, then zip, random samples fastest, drawn sample by
// sample in the keys' order from one generator): the same bits as before the runs were lazy.
TEST_F(LazyStudy, RunIFromIAloneIsTheRunOfTheOrderedExpansion) {
  const Study study = load(
      "name: order\nbase: walk_forward\nsweep:\n"
      "  grid: {duration: [4.0, 5.0, 6.0], walking.weight_cop: [100.0, 1000.0]}\n"
      "  zip: {robot_mass: [56.0, 58.0]}\n"
      "  random: {samples: 5, seed: 11, keys: {walking.com_height: {uniform: [0.78, 0.84]},"
      " walking.step_height: {uniform: [0.04, 0.06]}}}\n");
  const std::vector<double> durations = {4.0, 5.0, 6.0}, weights = {100.0, 1000.0},
                            masses = {56.0, 58.0};
  // The random values as the old expansion drew them: one generator, in order.
  std::vector<std::vector<double>> drawn(5, std::vector<double>(2));
  std::uint64_t state = 11;
  for (auto& sample : drawn) {
    sample[0] = 0.78 + (0.84 - 0.78) * wpg::datasets::nextUniform(&state);
    sample[1] = 0.04 + (0.06 - 0.04) * wpg::datasets::nextUniform(&state);
  }
  ASSERT_EQ(study.runs.size(), 3u * 2u * 2u * 5u);
  std::vector<std::size_t> order(study.runs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = order.size() - 1 - i;  // backwards
  std::size_t expected_index = 0;
  for (const double duration : durations) {
    for (const double weight : weights) {
      for (const double mass : masses) {
        for (const auto& sample : drawn) {
          const StudyRun run = study.runs.describe(expected_index);
          ASSERT_EQ(run.swept.size(), 5u);
          EXPECT_EQ(run.swept[0].number, duration);
          EXPECT_EQ(run.swept[1].number, weight);
          EXPECT_EQ(run.swept[2].number, mass);
          EXPECT_EQ(run.swept[3].number, sample[0]);
          EXPECT_EQ(run.swept[4].number, sample[1]);
          EXPECT_EQ(run.name, "order_" + std::string(expected_index < 10 ? "0" : "") +
                                  std::to_string(expected_index));
          ++expected_index;
        }
      }
    }
  }
  // Made backwards, on another copy of the study: the same scenario, to the byte.
  const Study again = load(std::string("name: order\nbase: walk_forward\nsweep:\n") +
                           "  grid: {duration: [4.0, 5.0, 6.0], walking.weight_cop: [100.0, 1000.0]}\n"
                           "  zip: {robot_mass: [56.0, 58.0]}\n"
                           "  random: {samples: 5, seed: 11, keys: {walking.com_height: {uniform: "
                           "[0.78, 0.84]}, walking.step_height: {uniform: [0.04, 0.06]}}}\n",
                           2);
  EXPECT_EQ(again.fingerprint, study.fingerprint);
  for (const std::size_t i : {std::size_t{59}, std::size_t{0}, std::size_t{31}, std::size_t{7}}) {
    EXPECT_EQ(resolvedScenarioText(again.runs[i].scenario),
              resolvedScenarioText(study.runs[i].scenario))
        << i;
  }
  // Every run of a small study is checked before any work.
  EXPECT_EQ(study.checked_runs.size(), study.runs.size());
}

// Which runs a large study checks: run 0, each value of each grid key with the other keys at
// their first (its stride), each zip entry, then the first random samples, at most 256.
TEST(LazyChecks, TheCheckedRunsTakeEveryValueOnce) {
  using wpg::datasets::checkedRuns;
  EXPECT_EQ(checkedRuns({3, 2}, 1, 1), (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));  // all
  // grid 3 x 2, zip 2, random 100: 1200 runs; strides: key 1 200, key 0 400; zip 100; the
  // samples 1..99.
  std::vector<std::size_t> expected = {0, 200, 400, 800, 100};
  for (std::size_t r = 1; r < 100; ++r) expected.push_back(r);
  std::sort(expected.begin(), expected.end());
  expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
  EXPECT_EQ(checkedRuns({3, 2}, 2, 100), expected);
  // Capped: 1000 values of one key take the 256.
  const std::vector<std::size_t> capped = checkedRuns({1000, 1000}, 1, 1000);
  EXPECT_EQ(capped.size(), wpg::datasets::kCheckedStudyRuns);
  EXPECT_EQ(capped[1], 1000u);  // the second value of the last grid key (stride 1000)
}

// A study of 10^7 runs: loaded with 256 runs checked, any run made from its index (the last
// one too), and the fingerprint the same whatever the threads.
TEST_F(LazyStudy, TenMillionRunsLoadWithABoundedCheck) {
  const std::string text = "name: big\nbase: walk_forward\nsweep:\n  grid:\n    walking.weight_cop: " +
                           numberList(100, 300.0, 10.0) + "\n    robot_mass: " +
                           numberList(100, 50.0, 0.1) +
                           "\n  random: {samples: 1000, seed: 1, keys: {walking.com_height: "
                           "{uniform: [0.78, 0.84]}}}\n";
  const Study study = load(text);
  ASSERT_EQ(study.runs.size(), 10000000u);
  EXPECT_EQ(study.checked_runs.size(), wpg::datasets::kCheckedStudyRuns);
  EXPECT_EQ(study.checked.size(), study.checked_runs.size());
  const StudyRun last = study.runs[9999999];
  EXPECT_EQ(last.name, "big_9999999");
  EXPECT_EQ(last.swept[0].number, 300.0 + 10.0 * 99);
  EXPECT_EQ(last.swept[1].number, 50.0 + 0.1 * 99);
  EXPECT_EQ(last.swept[2].number, 0.78 + (0.84 - 0.78) * wpg::datasets::uniformAt(1, 999));
  EXPECT_NE(resolvedScenarioText(last.scenario).find("name: big_9999999"), std::string::npos);
  EXPECT_EQ(load(text, 2).fingerprint, study.fingerprint);
}

// A value refused by the scenario in a run that is not checked (the 300th value of a grid key,
// beyond the 256 checked runs) is named, with its run, when the run is made.
TEST_F(LazyStudy, AnUncheckedRefusedRunIsNamedWhenMade) {
  std::string heights = numberList(299, 0.70, 0.0005);
  heights.back() = ',';
  heights += " -1.0]";
  const Study study = load("name: late\nbase: walk_forward\nsweep:\n  grid:\n"
                           "    walking.com_height: " + heights + "\n");
  ASSERT_EQ(study.runs.size(), 300u);
  EXPECT_NO_THROW((void)study.runs[298]);
  try {
    (void)study.runs[299];
    FAIL() << "run 299 was made";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("study.yaml: run 299 (walking.com_height=-1.0): "), std::string::npos)
        << message;
    EXPECT_NE(message.find("'com_height': expected a positive finite number"), std::string::npos)
        << message;
  }
}
