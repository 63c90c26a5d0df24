// Study files (wpg/datasets/study_design/study.hpp): the expansion of grid, zip and random sweeps
// (count, order, names), the seeded random values, the fingerprint, and bad studies as InputError.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "wpg/datasets/study_design/study.hpp"

namespace fs = std::filesystem;
using wpg::datasets::InputError;
using wpg::datasets::loadStudy;
using wpg::datasets::Study;

namespace {

class StudyFiles : public wpg_test::ScratchDirectoryTest {
 protected:
  StudyFiles() : ScratchDirectoryTest("wpg_test_study") {}

  Study load(const std::string& text, int threads = 1) {
    const fs::path path = directory_ / "study.yaml";
    std::ofstream(path) << text;
    return loadStudy(
        path.string(),
        [](const std::string& base) { return wpg_test::kScenariosDir + "/" + base + ".yaml"; },
        wpg_test::kRobotsDir, threads);
  }
};

const char* const kFullSweep =
    "name: demo\n"
    "base: walk_forward\n"
    "sweep:\n"
    "  grid:\n"
    "    duration: [4.0, 5.0, 6.0]\n"
    "    walking.weight_cop: [100.0, 1000.0]\n"
    "  zip:\n"
    "    \"pushes[0]\": [{t: 2.0, force: [0, 40]}, {t: 2.5, force: [0, -40]}]\n"
    "    robot_mass: [56.0, 58.0]\n"
    "  random:\n"
    "    samples: 2\n"
    "    seed: 3\n"
    "    keys: {\"pushes[0].duration\": {uniform: [0.05, 0.15]}}\n";

}  // namespace

TEST_F(StudyFiles, GridZipRandomAreCrossedInOrder) {
  const Study study = load(kFullSweep);
  ASSERT_EQ(study.runs.size(), 3u * 2u * 2u * 2u);
  EXPECT_EQ(study.keys, (std::vector<std::string>{"duration", "walking.weight_cop", "pushes[0]",
                                                  "robot_mass", "pushes[0].duration"}));
  EXPECT_EQ(study.runs.front().name, "demo_00");  // zero-padded: names sort by index
  EXPECT_EQ(study.runs.back().name, "demo_23");
  for (std::size_t i = 0; i < study.runs.size(); ++i) {
    const auto& run = study.runs[i];
    EXPECT_EQ(run.index, i);
    EXPECT_EQ(run.scenario.name, run.name);
    // the first grid key varies slowest, the random sample fastest
    EXPECT_DOUBLE_EQ(run.scenario.request.duration, 4.0 + static_cast<double>(i / 8));
    EXPECT_DOUBLE_EQ(run.scenario.walking.weight_cop, (i / 4) % 2 ? 1000.0 : 100.0);
    const bool second_zip = (i / 2) % 2 == 1;
    ASSERT_EQ(run.scenario.request.pushes.size(), 1u);
    EXPECT_DOUBLE_EQ(run.scenario.request.pushes[0].t, second_zip ? 2.5 : 2.0);
    EXPECT_DOUBLE_EQ(run.scenario.request.pushes[0].force.y(), second_zip ? -40.0 : 40.0);
    EXPECT_DOUBLE_EQ(run.scenario.request.robot_mass, second_zip ? 58.0 : 56.0);
    // the same random sample for every grid and zip point
    EXPECT_DOUBLE_EQ(run.scenario.request.pushes[0].duration,
                     study.runs[i % 2].scenario.request.pushes[0].duration);
    EXPECT_TRUE(run.swept[0].numeric);
    EXPECT_FALSE(run.swept[2].numeric);  // a map
  }
  const double d0 = study.runs[0].scenario.request.pushes[0].duration;
  const double d1 = study.runs[1].scenario.request.pushes[0].duration;
  EXPECT_NE(d0, d1);
  for (const double d : {d0, d1}) {
    EXPECT_GE(d, 0.05);
    EXPECT_LT(d, 0.15);
  }
}

TEST_F(StudyFiles, RandomValuesDependOnTheSeedOnly) {
  const Study a = load(kFullSweep);
  const Study b = load(kFullSweep);
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (std::size_t i = 0; i < a.runs.size(); ++i) {
    EXPECT_EQ(a.runs[i].swept.back().value, b.runs[i].swept.back().value);
  }
  EXPECT_EQ(a.fingerprint, b.fingerprint);
  std::string other_seed = kFullSweep;
  other_seed.replace(other_seed.find("seed: 3"), 7, "seed: 4");
  const Study c = load(other_seed);
  EXPECT_NE(c.runs[0].swept.back().value, a.runs[0].swept.back().value);
  EXPECT_NE(c.fingerprint, a.fingerprint);  // other scenarios, other fingerprint
}

TEST(StudyRandom, UniformIsInTheUnitIntervalAndSpread) {
  std::uint64_t state = 1;
  double sum = 0.0;
  std::set<double> seen;
  constexpr int kCount = 100000;
  for (int i = 0; i < kCount; ++i) {
    const double u = wpg::datasets::nextUniform(&state);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    seen.insert(u);
  }
  // the mean of kCount uniform samples: 0.5, standard deviation 0.29 / sqrt(kCount) = 0.0009
  EXPECT_NEAR(sum / kCount, 0.5, 0.005);
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(kCount));
}

TEST_F(StudyFiles, BadStudiesNameTheFileAndTheKey) {
  const auto expectError = [&](const std::string& text, const std::string& needle) {
    try {
      load(text);
      ADD_FAILURE() << "no error for: " << text;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("study.yaml"), std::string::npos) << message;
      EXPECT_NE(message.find(needle), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  };
  const std::string head = "name: bad\nbase: walk_forward\n";
  expectError(head + "sweep: {}\n", "empty sweep");
  expectError(head + "sweep:\n  grid: {}\n", "sweep.grid");
  expectError(head + "sweep:\n  grid: {duration: []}\n", "non-empty list");
  expectError(head + "sweep:\n  grid: {walking.no_such_key: [1.0]}\n", "walking.no_such_key");
  expectError(head + "sweep:\n  grid: {duration: [5.0, -2.0]}\n", "run 1 (duration=-2.0)");
  expectError(head + "sweep:\n  zip: {duration: [5.0, 6.0], robot_mass: [50.0]}\n", "same length");
  expectError(head + "sweep:\n  random: {samples: 0, seed: 1, keys: {duration: {uniform: [1.0, 2.0]}}}\n",
              "samples");
  expectError(head + "sweep:\n  random: {samples: 2, seed: 1, keys: {duration: {normal: [1.0, 2.0]}}}\n",
              "normal");
  expectError(head + "sweep:\n  grid: {duration: [5.0]}\n  zip: {duration: [6.0]}\n",
              "swept twice");
  expectError("name: bad\nsweep:\n  grid: {duration: [5.0]}\n", "base");
  expectError("name: bad\nbase: {robot: hrp2, duration: 5.0, bogus: 1}\nsweep:\n  grid: {duration: [5.0]}\n",
              "bogus");
}

TEST_F(StudyFiles, InlineBaseAndBaseBesideTheStudy) {
  const Study inline_base = load(
      "name: inline\n"
      "base: {robot: hrp2, duration: 3.0, reference: [{t: 0.0, v: [0.1, 0.0, 0.0]}]}\n"
      "sweep:\n  grid: {walking.step_height: [0.04, 0.06]}\n");
  ASSERT_EQ(inline_base.runs.size(), 2u);
  EXPECT_DOUBLE_EQ(inline_base.runs[1].scenario.walking.step_height, 0.06);
  EXPECT_DOUBLE_EQ(inline_base.runs[1].scenario.request.duration, 3.0);

  std::ofstream(directory_ / "mine.yaml")
      << "name: mine\nrobot: hrp2\nduration: 2.0\nreference: [{t: 0.0, v: [0.0, 0.0, 0.0]}]\n";
  const Study beside = load("name: beside\nbase: mine.yaml\nsweep:\n  grid: {robot_mass: [50.0]}\n");
  EXPECT_DOUBLE_EQ(beside.runs[0].scenario.request.duration, 2.0);
}

TEST_F(StudyFiles, ThreadsDoNotChangeTheRunsNorTheError) {
  const Study one = load(kFullSweep, 1);
  const Study three = load(kFullSweep, 3);
  ASSERT_EQ(one.runs.size(), three.runs.size());
  for (std::size_t i = 0; i < one.runs.size(); ++i) {
    EXPECT_EQ(resolvedScenarioText(one.runs[i].scenario),
              resolvedScenarioText(three.runs[i].scenario));
  }
  EXPECT_EQ(one.fingerprint, three.fingerprint);
  // runs 1 and 2 are bad; the message names run 1 for any number of threads
  const std::string bad =
      "name: bad\nbase: walk_forward\nsweep:\n  grid: {duration: [5.0, -1.0, -2.0]}\n";
  for (const int threads : {1, 2, 3}) {
    try {
      load(bad, threads);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("run 1 (duration=-1.0)"), std::string::npos) << e.what();
    }
  }
}

TEST_F(StudyFiles, SetHoldsConstantsThatAreNotSwept) {
  const Study study = load(
      "name: demo\nbase: walk_forward\nset: {duration: 2.5, walking.weight_jerk: 1.0e-4}\n"
      "sweep:\n  grid:\n    walking.weight_cop: [100.0, 1000.0]\n");
  ASSERT_EQ(study.runs.size(), 2u);
  EXPECT_EQ(study.keys, (std::vector<std::string>{"walking.weight_cop"}));  // no column for set:
  for (const auto& run : study.runs) {
    EXPECT_EQ(run.scenario.request.duration, 2.5);
    EXPECT_EQ(run.scenario.walking.weight_jerk, 1.0e-4);
    ASSERT_EQ(run.swept.size(), 1u);
  }
  const auto bad = [&](const std::string& text, std::initializer_list<std::string> parts) {
    wpg_test::expectInputError([&] { load(text); }, (directory_ / "study.yaml").string(), parts);
  };
  // A key both set and swept; a value the scenario refuses, named as set:, not as swept.
  bad("name: demo\nbase: walk_forward\nset: {duration: 3.0}\nsweep: {grid: {duration: [4.0]}}\n",
      {"set", "'duration' is also swept"});
  bad("name: demo\nbase: walk_forward\nset: {duration: -1.0}\nsweep: {grid: {robot_mass: [56.0]}}\n",
      {"(set by the study's set: 'duration=-1.0')", "key 'duration'"});
  bad("name: demo\nbase: walk_forward\nset: [duration]\nsweep: {grid: {robot_mass: [56.0]}}\n",
      {"set", "a non-empty map of dotted scenario keys to values"});
}
