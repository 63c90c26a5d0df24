#pragma once
// What the scenario-file tests share (test_scenario.cpp, test_scenario_overrides.cpp): the
// shipped scenarios by name, a valid scenario text to break one line of, and a fixture that
// writes scenario files and expects one InputError line naming the file and the key.
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "wpg/datasets/input/scenario.hpp"

namespace wpg_test {

inline std::string shipped(const std::string& name) { return kScenariosDir + "/" + name + ".yaml"; }

inline wpg::datasets::Scenario loadShipped(const std::string& name,
                                           const std::vector<std::string>& overrides = {}) {
  return wpg::datasets::loadScenario(shipped(name), overrides, kRobotsDir);
}

// A valid scenario; tests replace one line to make it malformed.
inline const char* const kValidScenario =
    "name: test_case\n"
    "robot: hrp2\n"
    "duration: 5.0\n"
    "generator: {algorithm: nmpc, sqp_iterations: 1}\n"
    "reference:\n"
    "  - {t: 0.0, v: [0.0, 0.0, 0.0]}\n"
    "  - {t: 1.0, v: [0.2, 0.0, 0.0]}\n"
    "pushes:\n"
    "  - {t: 2.0, force: [0.0, 90.0], duration: 0.1}\n"
    "walking: {max_step_yaw_change: 0.17}\n";

inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test bug: '" + from + "' not found");
  return text.replace(at, from.size(), to);
}

class ScenarioFiles : public ScratchDirectoryTest {
 protected:
  ScenarioFiles() : ScratchDirectoryTest("wpg_test_scenario") {}

  std::string write(const std::string& file_name, const std::string& text) {
    const std::filesystem::path path = directory_ / file_name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path) << text;
    return path.string();
  }

  // Loading `text` (written as `file_name`) must throw one InputError line holding the file
  // name and every one of `parts`.
  void expectError(const std::string& file_name, const std::string& text,
                   std::initializer_list<std::string> parts,
                   const std::vector<std::string>& overrides = {}) {
    const std::string path = write(file_name, text);
    expectErrorAt(path, parts, overrides, kRobotsDir);
  }

  static void expectErrorAt(const std::string& path, std::initializer_list<std::string> parts,
                            const std::vector<std::string>& overrides,
                            const std::string& robots_dir) {
    expectInputError([&] { wpg::datasets::loadScenario(path, overrides, robots_dir); }, path,
                     parts);
  }
};

}  // namespace wpg_test
