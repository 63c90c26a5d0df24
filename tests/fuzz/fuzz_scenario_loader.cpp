// libFuzzer target: the scenario loader with `--set` overrides (datasets/scenario.hpp), what
// `wpg run FILE --set key=value...` does before anything is computed.
//
// Input: the scenario text, then up to kMaxOverrides override strings, separated by NUL bytes
// (a NUL cannot come from a YAML file or a command line, so the split never hides a case).
// Seeds: datasets/scenarios/*.yaml (no NUL: no override) and tests/fuzz/seeds/scenario_loader/.
//
// Properties checked, beyond "no crash, no sanitizer report, no hang":
//  - bad input is an InputError (the CLI's exit 2); any other exception escapes and is
//    reported by libFuzzer as a crash;
//  - an accepted scenario's resolved text (stored in every dataset, read back by `wpg replay`)
//    loads again, without overrides, to the same resolved text.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/input/scenario.hpp"
#include "../common/source_dir.hpp"

namespace {

constexpr std::size_t kMaxOverrides = 4;

const std::string& robotsDirectory() {
  static const std::string directory = std::string(wpg_test::sourceDir()) + "/robots";
  return directory;
}

[[noreturn]] void propertyViolated(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_scenario_loader: %s\n%s\n", what, detail.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (parts.size() <= kMaxOverrides) {
    const std::size_t end = input.find('\0', start);
    parts.push_back(input.substr(start, end == std::string::npos ? end : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  const std::string text = parts.front();
  const std::vector<std::string> overrides(parts.begin() + 1, parts.end());

  wpg::datasets::Scenario scenario;
  try {
    scenario = wpg::datasets::loadScenarioText(text, "fuzz.yaml", overrides, robotsDirectory());
  } catch (const wpg::datasets::InputError&) {
    return 0;  // rejected with the one-line message the CLI prints (exit 2)
  }
  try {
    const wpg::datasets::Scenario again = wpg::datasets::loadScenarioText(
        resolvedScenarioText(scenario), "fuzz.yaml:/scenario", {}, robotsDirectory());
    if (resolvedScenarioText(again) != resolvedScenarioText(scenario)) {
      propertyViolated(
          "the resolved scenario does not load to itself",
          "first:\n" + resolvedScenarioText(scenario) + "\nagain:\n" + resolvedScenarioText(again));
    }
  } catch (const wpg::datasets::InputError& error) {
    propertyViolated("the resolved scenario of an accepted scenario is rejected",
                     std::string(error.what()) + "\n" + resolvedScenarioText(scenario));
  }
  return 0;
}
