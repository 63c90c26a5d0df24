// Limits on input (datasets/SCENARIOS.md, "Limits"): files that
// are not regular or too large, too-deep YAML and --set keys, second YAML documents in --set
// values, lengths beyond kMaxLength (scenarios and generated worlds), names too long for a file
// name, walks too short to run or replay, and control characters escaped in every message.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "wpg/datasets/comparison_study.hpp"
#include "wpg/datasets/input_limits.hpp"
#include "wpg/datasets/scenario.hpp"
#include "wpg/datasets/study.hpp"

namespace fs = std::filesystem;
using wpg::datasets::escapeControlCharacters;
using wpg::datasets::InputError;
using wpg::datasets::loadScenario;

namespace {

std::string shipped(const std::string& name) {
  return wpg_test::kScenariosDir + "/" + name + ".yaml";
}

// The message of the InputError that `load` throws ("" when none).
template <typename Load>
std::string errorOf(Load load) {
  try {
    load();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

std::string overrideError(const std::string& scenario, const std::vector<std::string>& overrides) {
  return errorOf([&] { loadScenario(shipped(scenario), overrides, wpg_test::kRobotsDir); });
}

bool hasControlCharacter(const std::string& text) {
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) return true;
  }
  return false;
}

class InputFiles : public wpg_test::ScratchDirectoryTest {
 protected:
  InputFiles() : ScratchDirectoryTest("wpg_test_input_limits") {}

  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = directory_ / name;
    std::ofstream(path) << text;
    return path.string();
  }
  std::string scenarioError(const std::string& path) {
    return errorOf([&] { loadScenario(path, {}, wpg_test::kRobotsDir); });
  }
  std::string studyError(const std::string& path) {
    return errorOf([&] {
      wpg::datasets::loadStudy(
          path, [](const std::string& base) { return shipped(base); }, wpg_test::kRobotsDir, 1);
    });
  }
  std::string comparisonError(const std::string& path) {
    return errorOf([&] {
      wpg::datasets::loadComparisonStudy(
          path, [](const std::string& base) { return shipped(base); }, wpg_test::kRobotsDir, 1);
    });
  }
};

}  // namespace

TEST(EscapeControlCharacters, EscapesControlsKeepsTheRestAndIsIdempotent) {
  EXPECT_EQ(escapeControlCharacters("a\x1b[31mb\nc\td\r\x7f"), "a\\x1b[31mb\\nc\\td\\r\\x7f");
  EXPECT_EQ(escapeControlCharacters("plain 'text' \\ é"), "plain 'text' \\ é");
  const std::string once = escapeControlCharacters(std::string("k\0\x01", 3));
  EXPECT_EQ(once, "k\\x00\\x01");
  EXPECT_EQ(escapeControlCharacters(once), once);
}

TEST_F(InputFiles, OnlyRegularFilesOfBoundedSizeAreRead) {
  // A FIFO without a writer: opened without blocking, refused without reading.
  const std::string fifo = (directory_ / "fifo.yaml").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(scenarioError(fifo).find("expected a regular file"), std::string::npos);
  EXPECT_NE(scenarioError("/dev/zero").find("expected a regular file"), std::string::npos);
  EXPECT_NE(studyError("/dev/zero").find("expected a regular file"), std::string::npos);
  EXPECT_NE(comparisonError("/dev/zero").find("expected a regular file"), std::string::npos);
  // One byte past the cap (a sparse file: nothing is written to the disk).
  const std::string big = write("big.yaml", "");
  fs::resize_file(big, wpg::datasets::kMaxInputFileBytes + 1);
  const std::string message = scenarioError(big);
  EXPECT_NE(message.find("at most 16 MiB"), std::string::npos) << message;
  EXPECT_NE(studyError(big).find("at most 16 MiB"), std::string::npos);
  EXPECT_NE(comparisonError(big).find("at most 16 MiB"), std::string::npos);
}

TEST_F(InputFiles, DeeplyNestedYamlIsNamedAsSuch) {
  const std::string nested = std::string(100000, '[') + std::string(100000, ']');
  const std::string scenario =
      write("nested.yaml", "name: x\nrobot: hrp2\nduration: 1\nreference: " + nested + "\n");
  EXPECT_NE(scenarioError(scenario).find("nested less deeply"), std::string::npos);
  const std::string study = write("study.yaml", "name: x\nbase: walk_forward\nsweep: " + nested);
  EXPECT_NE(studyError(study).find("nested less deeply"), std::string::npos);
  EXPECT_NE(comparisonError(study).find("nested less deeply"), std::string::npos);
  EXPECT_NE(overrideError("walk_forward", {"reference=" + nested}).find("nested less deeply"),
            std::string::npos);
}

TEST(OverrideLimits, DeepKeysAreRefusedAtOnceInOneShortLine) {
  std::string key = "a";
  for (int i = 0; i < 20000; ++i) key += ".a";
  const std::string message = overrideError("walk_forward", {key + "=1"});
  EXPECT_NE(message.find("at most 32 names and indices"), std::string::npos) << message;
  EXPECT_LT(message.size(), 600u);
  std::string indices = "reference";
  for (int i = 0; i < 40; ++i) indices += "[0]";
  EXPECT_NE(overrideError("walk_forward", {indices + "=1"}).find("at most 32"), std::string::npos);
  // 32 steps are still a key (an unknown one here).
  std::string longest = "a";
  for (int i = 1; i < 32; ++i) longest += ".a";
  EXPECT_NE(overrideError("walk_forward", {longest + "=1"}).find("unknown key"), std::string::npos);
}

TEST(OverrideLimits, ASecondYamlDocumentIsRefused) {
  const std::string message = overrideError("walk_forward", {"walking.weight_cop=1\n---\n2"});
  EXPECT_NE(message.find("expected one YAML value, got 2 documents"), std::string::npos) << message;
  EXPECT_FALSE(hasControlCharacter(message)) << message;
  EXPECT_EQ(overrideError("walk_forward", {"walking.weight_cop=2"}), "");
}

// yaml-cpp 0.7's LoadAll returns empty documents forever on a lone ',' (memory grows until it
// runs out): the value's documents are counted with the parser, stopping at 2.
TEST(OverrideLimits, AValueOfALoneCommaIsASyntaxErrorNotAnEndlessList) {
  for (const char* value : {",", "1\n,", ",\n---\n,"}) {
    const std::string message = overrideError("walk_forward", {std::string("duration=") + value});
    EXPECT_NE(message.find("key 'duration'"), std::string::npos) << message;
  }
}

TEST(OverrideLimits, ControlCharactersOfKeysAndValuesAreEscaped) {
  const std::string key_message = overrideError("walk_forward", {"a\x1b[2Jb\nc=1"});
  EXPECT_NE(key_message.find("a\\x1b[2Jb\\nc"), std::string::npos) << key_message;
  EXPECT_FALSE(hasControlCharacter(key_message));
  const std::string value_message = overrideError("walk_forward", {"duration=\"\x1b]0;x\x07\""});
  EXPECT_NE(value_message.find("\\x1b]0;x\\x07"), std::string::npos) << value_message;
  EXPECT_FALSE(hasControlCharacter(value_message));
}

TEST(LengthLimits, CoordinatesSizesAndDistancesBeyondTheLimitNameTheKey) {
  const struct {
    const char* scenario;
    const char* override_text;
    const char* key;
  } cases[] = {
      {"goal_u_trap", "obstacles[0].center=[1e155, 0]", "'obstacles[0].center[0]'"},
      {"goal_u_trap", "obstacles[0].size=[1, 1e160]", "'obstacles[0].size[1]'"},
      {"goal_u_trap", "obstacles[0].margin=2e4", "'obstacles[0].margin'"},
      {"goal_u_trap", "obstacles[0]={type: circle, center: [3, 0], radius: 1e200}",
       "'obstacles[0].radius'"},
      {"goal_u_trap",
       "obstacles[0]={type: polygon, vertices: [[3, 0], [4, 0], [3, -1e156]]}",
       "'obstacles[0].vertices[2][1]'"},
      {"goal_u_trap", "goal.position=[1e160, 0]", "'goal.position[0]'"},
      {"goal_u_trap", "goal.tolerance=1e10", "'goal.tolerance'"},
      {"goal_u_trap", "planner.bounds=[-1e155, 10, -5, 5]", "'planner.bounds[0]'"},
      {"goal_u_trap", "planner.lookahead=1e300", "'planner.lookahead'"},
      {"walk_forward", "walking.com_height=1e155", "'walking.com_height'"},
      {"walk_forward", "walking.feasibility_x=[0, 0, 1e200, 0, 0]", "'walking.feasibility_x[2]'"},
      {"walk_forward", "generator.obstacle_reach=1e200", "'generator.obstacle_reach'"},
      {"walk_forward", "pushes[0]={t: 1.5, force: [1e30, 0], duration: 0.1}",
       "'pushes[0].force[0]'"},
  };
  for (const auto& c : cases) {
    const std::string message = overrideError(c.scenario, {c.override_text});
    EXPECT_NE(message.find(c.key), std::string::npos) << c.override_text << ": " << message;
    EXPECT_NE(message.find("at most"), std::string::npos) << message;
  }
  // The limit itself is allowed.
  EXPECT_EQ(overrideError("goal_u_trap", {"planner.lookahead=1e4"}), "");
}

TEST_F(InputFiles, GeneratedWorldsBeyondTheLengthLimitNameTheKey) {
  const std::string head =
      "name: demo\nbase: {robot: hrp2, duration: 30.0}\nseeds: 1\n"
      "variants:\n  a: {planner.algorithm: rrtconnect}\nworlds:\n";
  EXPECT_NE(comparisonError(write("c.yaml", head + "  - {name: w, corridor: {length: 1e160}}\n"))
                .find("'worlds[0].corridor.length'"),
            std::string::npos);
  EXPECT_NE(comparisonError(write("f.yaml", head + "  - {name: w, random_field: {area: "
                                                    "[1, 1e155, -1, 1]}}\n"))
                .find("'worlds[0].random_field.area[1]'"),
            std::string::npos);
  EXPECT_NE(comparisonError(write("d.yaml", head + "  - {name: w, doorway: {offset: -1e200}}\n"))
                .find("'worlds[0].doorway.offset'"),
            std::string::npos);
  EXPECT_NE(comparisonError(write("n.yaml", head + "  - {name: w, random_field: {count: 2147483647}}\n"))
                .find("expected count at most 10000"),
            std::string::npos);
}

TEST_F(InputFiles, NamesTooLongForAFileNameAreRefused) {
  const std::string long_name(129, 'a');
  EXPECT_NE(overrideError("walk_forward", {"name=" + long_name}).find("at most 128"),
            std::string::npos);
  EXPECT_EQ(overrideError("walk_forward", {"name=" + std::string(128, 'a')}), "");
  const std::string study =
      write("s.yaml", "name: " + std::string(33, 's') + "\nbase: walk_forward\n"
                      "sweep: {grid: {duration: [4.0]}}\n");
  EXPECT_NE(studyError(study).find("at most 32"), std::string::npos);
}

TEST(WalkLength, TooShortToRunOrToReplayIsBadInput) {
  // lround(duration / T) NMPC iterations: none below T / 2 = 0.05 s.
  EXPECT_NE(overrideError("walk_forward", {"duration=0.02"}).find("half a sampling period"),
            std::string::npos);
  EXPECT_EQ(overrideError("walk_forward", {"duration=0.05"}), "");
  // One iteration of one control period is 2 samples: the replay needs 3.
  EXPECT_NE(overrideError("walk_forward", {"duration=0.1", "walking.control_period=0.1",
                                           "replay=true"})
                .find("at least 2 control periods"),
            std::string::npos);
  EXPECT_EQ(overrideError("walk_forward", {"duration=0.1", "walking.control_period=0.1"}), "");
}
