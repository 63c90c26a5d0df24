// Comparison study files (wpg/datasets/study_design/comparison_study.hpp): the expansion worlds x
// variants x seeds (order, names, swept values), what reaches each run's scenario (variant keys,
// the seed, generated obstacles and goal), the generators' geometry and determinism, and bad
// studies as InputError naming the key.
#include <cmath>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "wpg/datasets/study_design/comparison_study.hpp"

namespace fs = std::filesystem;
using wpg::datasets::ComparisonStudy;
using wpg::datasets::InputError;

namespace {

class ComparisonFiles : public wpg_test::ScratchDirectoryTest {
 protected:
  ComparisonFiles() : ScratchDirectoryTest("wpg_test_comparison") {}

  ComparisonStudy load(const std::string& text, int threads = 1) {
    const fs::path path = directory_ / "study.yaml";
    std::ofstream(path) << text;
    return wpg::datasets::loadComparisonStudy(
        path.string(),
        [](const std::string& base) { return wpg_test::kScenariosDir + "/" + base + ".yaml"; },
        wpg_test::kRobotsDir, threads);
  }

  // The message of the InputError that loading `text` throws ("" when none).
  std::string error(const std::string& text) {
    try {
      load(text);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

const std::string kBase =
    "name: demo\n"
    "base: {robot: hrp2, duration: 30.0, generator: {algorithm: nmpc}}\n";

const std::string kStudy = kBase +
    "seeds: 3\n"
    "worlds:\n"
    "  - {name: trap, u_trap: {}}\n"
    "  - {name: field, random_field: {count: 6, seed: 4}}\n"
    "  - {name: cluttered, scenario: goal_cluttered, goal: {tolerance: 0.3}}\n"
    "variants:\n"
    "  star: {planner.algorithm: rrtstar}\n"
    "  lmpc: {planner.algorithm: rrtconnect, generator.algorithm: lmpc}\n";

}  // namespace

TEST_F(ComparisonFiles, WorldsVariantsSeedsAreCrossedInOrder) {
  const ComparisonStudy c = load(kStudy);
  ASSERT_EQ(c.study.runs.size(), 3u * 2u * 3u);
  EXPECT_EQ(c.worlds, (std::vector<std::string>{"trap", "field", "cluttered"}));
  EXPECT_EQ(c.variants, (std::vector<std::string>{"star", "lmpc"}));
  EXPECT_EQ(c.seeds, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(c.study.keys, (std::vector<std::string>{"world", "variant", "seed"}));
  EXPECT_EQ(c.study.created_by, "wpg compare");
  std::size_t i = 0;
  for (std::size_t w = 0; w < 3; ++w) {
    for (std::size_t v = 0; v < 2; ++v) {
      for (int seed = 1; seed <= 3; ++seed, ++i) {
        const auto& run = c.study.runs[i];
        EXPECT_EQ(run.index, i);
        EXPECT_EQ(c.runs[i].world, w);
        EXPECT_EQ(c.runs[i].variant, v);
        EXPECT_EQ(c.runs[i].seed, seed);
        EXPECT_EQ(run.name, c.worlds[w] + "." + c.variants[v] + "." + std::to_string(seed));
        EXPECT_EQ(run.scenario.name, run.name);
        EXPECT_EQ(run.swept[0].value, c.worlds[w]);
        EXPECT_EQ(run.swept[1].value, c.variants[v]);
        EXPECT_DOUBLE_EQ(run.swept[2].number, seed);
        // The variant's keys and the seed reach the scenario.
        EXPECT_TRUE(run.scenario.goal.enabled);
        EXPECT_EQ(run.scenario.goal.planner.seed, static_cast<unsigned>(seed));
        EXPECT_EQ(run.scenario.goal.planner.algorithm, v == 0 ? "rrtstar" : "rrtconnect");
      }
    }
  }
  // The scenario world keeps its obstacles and gets the world's goal keys.
  const auto& cluttered = c.study.runs[12].scenario;
  EXPECT_EQ(cluttered.request.obstacles.size(), 9u);
  EXPECT_DOUBLE_EQ(cluttered.goal.goal.tolerance, 0.3);
  EXPECT_DOUBLE_EQ(cluttered.goal.goal.position.x(), 6.6);
}

TEST_F(ComparisonFiles, UTrapHasTheShippedScenariosGeometry) {
  const ComparisonStudy c = load(kStudy);
  const auto& trap = c.study.runs[0].scenario;
  ASSERT_EQ(trap.request.obstacles.size(), 3u);  // back wall, two arms (goal_u_trap.yaml)
  EXPECT_DOUBLE_EQ(trap.request.obstacles[0].center.x(), 2.6);
  EXPECT_DOUBLE_EQ(trap.request.obstacles[0].size.y(), 2.2);
  EXPECT_DOUBLE_EQ(trap.request.obstacles[1].center.x(), 1.9);
  EXPECT_DOUBLE_EQ(trap.request.obstacles[1].center.y(), 1.0);
  EXPECT_DOUBLE_EQ(trap.request.obstacles[2].size.x(), 1.6);
  EXPECT_DOUBLE_EQ(trap.goal.goal.position.x(), 4.2);
  // Fixed worlds do not depend on the seed.
  EXPECT_EQ(c.study.runs[0].scenario.request.obstacles[1].center,
            c.study.runs[2].scenario.request.obstacles[1].center);
}

TEST_F(ComparisonFiles, RandomFieldsAreDrawnPerSeedAndReproducible) {
  const ComparisonStudy a = load(kStudy, 1);
  const ComparisonStudy b = load(kStudy, 3);
  EXPECT_EQ(a.study.fingerprint, b.study.fingerprint);  // whatever the threads
  std::set<std::string> fields;
  for (std::size_t i = 6; i < 12; ++i) {  // world "field": 2 variants x 3 seeds
    const auto& scenario = a.study.runs[i].scenario;
    EXPECT_EQ(
        resolvedScenarioText(scenario).substr(resolvedScenarioText(scenario).find("obstacles")),
        resolvedScenarioText(b.study.runs[i].scenario)
            .substr(resolvedScenarioText(b.study.runs[i].scenario).find("obstacles")));
    ASSERT_EQ(scenario.request.obstacles.size(), 6u);
    const Eigen::Vector2d goal = scenario.goal.goal.position;
    EXPECT_DOUBLE_EQ(goal.x(), 6.0);  // default area [1, 5, -1.5, 1.5]: x_max + 1
    std::string centres;
    for (const auto& obstacle : scenario.request.obstacles) {
      EXPECT_GE(obstacle.center.x(), 1.0);
      EXPECT_LE(obstacle.center.x(), 5.0);
      EXPECT_GE(obstacle.center.y(), -1.5);
      EXPECT_LE(obstacle.center.y(), 1.5);
      EXPECT_GE(obstacle.radius, 0.15);
      EXPECT_LE(obstacle.radius, 0.3);
      const double reach = obstacle.radius + obstacle.margin + 0.5;  // default clearance
      EXPECT_GE(obstacle.center.norm(), reach - 1e-3);  // rounded to the mm
      EXPECT_GE((obstacle.center - goal).norm(), reach - 1e-3);
      centres += std::to_string(obstacle.center.x()) + "," + std::to_string(obstacle.center.y());
    }
    fields.insert(centres);
  }
  EXPECT_EQ(fields.size(), 3u);  // one field per seed, the same for both variants
}

TEST_F(ComparisonFiles, BadStudiesNameTheKey) {
  const std::string variants = "variants:\n  a: {planner.algorithm: rrtconnect}\n";
  EXPECT_NE(error(kBase + "seeds: 1\nworlds:\n  - {name: w, spiral: {}}\n" + variants)
                .find("worlds[0].spiral"),
            std::string::npos);
  EXPECT_NE(error(kBase + "seeds: 1\nworlds:\n  - {name: w, u_trap: {}}\n"
                          "variants:\n  a: {planner.nope: 1}\n")
                .find("planner.nope"),
            std::string::npos);
  EXPECT_NE(error(kBase + "seeds: 0\nworlds:\n  - {name: w, u_trap: {}}\n" + variants)
                .find("'seeds'"),
            std::string::npos);
  EXPECT_NE(error(kBase + "seeds: 1\nworlds:\n  - {name: w, u_trap: {}}\n  - {name: w, corridor: {}}\n" +
                  variants)
                .find("named twice"),
            std::string::npos);
  EXPECT_NE(error(kBase + "seeds: 1\nworlds:\n  - {name: w, u_trap: {}, corridor: {}}\n" + variants)
                .find("'worlds[0]'"),
            std::string::npos);
  EXPECT_NE(error(kBase + "seeds: 1\nworlds:\n  - {name: w, random_field: {area: [5, 1, 0, 1]}}\n" +
                  variants)
                .find("random_field.area"),
            std::string::npos);
  EXPECT_NE(error(kBase + "seeds: 1\nworlds:\n  - {name: w, random_field: {count: 1, area: [0.1, 0.3, -0.1, 0.1]}}\n" +
                  variants)
                .find("could not place"),
            std::string::npos);
  EXPECT_NE(error("name: x\nseeds: 1\nworlds:\n  - {name: w, doorway: {}}\n" + variants)
                .find("'base'"),
            std::string::npos);
  EXPECT_NE(error(kBase + "seeds: 1\nworlds:\n  - {name: w, u_trap: {}}\nvariants: {}\n")
                .find("'variants'"),
            std::string::npos);
}
