// The generator's blocked keys (datasets/SCENARIOS.md, "generator"): their defaults, values read
// from a file and from --set, the resolved YAML that reproduces them, and bad values refused with
// one line naming the file, the key and what is expected.
#include <string>

#include <gtest/gtest.h>

#include "scenario_files.hpp"
#include "wpg/datasets/input/scenario.hpp"

namespace {

using wpg_test::kValidScenario;
using wpg_test::replaced;

class BlockedKeys : public wpg_test::ScenarioFiles {
 protected:
  wpg::datasets::Scenario load(const std::string& generator,
                               const std::vector<std::string>& overrides = {}) {
    const std::string text =
        replaced(kValidScenario, "generator: {algorithm: nmpc, sqp_iterations: 1}",
                 "generator: " + generator);
    return wpg::datasets::loadScenario(write("blocked.yaml", text), overrides,
                                       wpg_test::kRobotsDir);
  }
};

TEST_F(BlockedKeys, DefaultsAreThreeCyclesAQuarterAndRunningOn) {
  const wpg::GeneratorSettings& g = load("{}").request.generator;
  EXPECT_EQ(g.blocked_window_cycles, 3);
  EXPECT_EQ(g.blocked_progress, 0.25);
  EXPECT_FALSE(g.stop_when_blocked);
}

TEST_F(BlockedKeys, ReadFromTheFileAndFromSetAndResolvedAgain) {
  const wpg::datasets::Scenario s =
      load("{blocked_window_cycles: 5, blocked_progress: 0.1, stop_when_blocked: true}");
  EXPECT_EQ(s.request.generator.blocked_window_cycles, 5);
  EXPECT_EQ(s.request.generator.blocked_progress, 0.1);
  EXPECT_TRUE(s.request.generator.stop_when_blocked);
  for (const char* line :
       {"blocked_window_cycles: 5", "blocked_progress: 0.1", "stop_when_blocked: true"})
    EXPECT_NE(resolvedScenarioText(s).find(line), std::string::npos) << line;
  // The resolved text loads to the same scenario.
  const std::string again = write("resolved.yaml", resolvedScenarioText(s));
  EXPECT_EQ(resolvedScenarioText(wpg::datasets::loadScenario(again, {}, wpg_test::kRobotsDir)),
            resolvedScenarioText(s));
  const wpg::datasets::Scenario set =
      load("{}", {"generator.blocked_window_cycles=1", "generator.stop_when_blocked=true"});
  EXPECT_EQ(set.request.generator.blocked_window_cycles, 1);
  EXPECT_TRUE(set.request.generator.stop_when_blocked);
}

TEST_F(BlockedKeys, BadValuesNameTheKeyAndTheExpectation) {
  const struct {
    const char* generator;
    const char* key;
    const char* expected;
  } cases[] = {
      {"{blocked_window_cycles: 0}", "generator.blocked_window_cycles", "an integer in [1, 100]"},
      {"{blocked_window_cycles: 101}", "generator.blocked_window_cycles", "an integer in [1, 100]"},
      {"{blocked_window_cycles: 2.5}", "generator.blocked_window_cycles", "an integer in [1, 100]"},
      {"{blocked_progress: 0}", "generator.blocked_progress", "a ratio in (0, 1)"},
      {"{blocked_progress: 1}", "generator.blocked_progress", "a ratio in (0, 1)"},
      {"{blocked_progress: -0.5}", "generator.blocked_progress", "a ratio in (0, 1)"},
      {"{blocked_progress: .nan}", "generator.blocked_progress", "a ratio in (0, 1)"},
      {"{stop_when_blocked: maybe}", "generator.stop_when_blocked", "true or false"},
      {"{stop_when_blockd: true}", "generator.stop_when_blockd", "stop_when_blocked"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.generator);
    expectError("bad.yaml",
                replaced(kValidScenario, "generator: {algorithm: nmpc, sqp_iterations: 1}",
                         std::string("generator: ") + c.generator),
                {c.key, c.expected});
  }
}

}  // namespace
