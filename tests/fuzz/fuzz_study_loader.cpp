// libFuzzer target: the study loaders (datasets/study_design), what `wpg batch STUDY.yaml` and
// `wpg compare STUDY.yaml` do before any walk: the study's keys are `--set` overrides of a base
// scenario (a sweep's keys and values, a comparison's `set:` and variants), applied and checked
// run by run.
//
// Input: the study text, then optionally a NUL byte and the text of a base scenario. Both are
// written to a private folder (the loaders open paths): the study as study.yaml, the base as
// base.yaml beside it, so that `base: base.yaml` (or a world's `scenario: base.yaml`) reads it.
// A base given by name is looked up among the shipped scenarios (datasets/scenarios), as the
// CLI does. Every input is given to both loaders (the batch one refuses a comparison's keys and
// the reverse, at the first key).
// Seeds: datasets/studies/*.yaml, tests/cli/studies/*.yaml, tests/fuzz/seeds/study_loader/.
//
// Studies of more than kMaxFuzzRuns runs are skipped (counted from the text before loading):
// each run is a scenario loaded and checked, a few ms under ASan, and a study of the documented
// limit (a million runs) is slow by design, not a hang. The count is a harness estimate; the
// loader's own count and cap are what the test exercises below that size.
//
// WPG_FUZZ_VERBOSE=1 (environment) prints what each loader made of an input (runs, or the
// refusal).
//
// Properties checked, beyond "no crash, no sanitizer report, no hang, no leak": bad input is an
// InputError (the CLI's exit 2), any other exception escapes and is reported as a crash; an
// accepted study has unique run names, one swept value per key in every run, a 16-digit
// fingerprint, and (comparison) worlds x variants x seeds runs.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <yaml-cpp/yaml.h>

#include "private_folder.hpp"
#include "wpg/datasets/input/input_error.hpp"
#include "wpg/datasets/study_design/comparison_study.hpp"
#include "wpg/datasets/study_design/study.hpp"
#include "../common/source_dir.hpp"

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxFuzzRuns = 64;

std::string g_folder;  // private folder of study.yaml and base.yaml

void removeFolder() {
  std::error_code ignored;
  fs::remove_all(g_folder, ignored);
}

[[noreturn]] void propertyViolated(const std::string& what, const std::string& text) {
  std::fprintf(stderr, "fuzz_study_loader: %s\n%s\n", what.c_str(), text.c_str());
  std::abort();
}

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) propertyViolated("cannot write " + path.string(), "");
}

// The shipped scenario `name` (datasets/scenarios/<name>.yaml), as the CLI's lookup finds it.
std::string shippedScenario(const std::string& name) {
  bool plain = !name.empty() && name.size() <= 64;
  for (const char c : name) {
    plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  }
  const fs::path path =
      fs::path(wpg_test::sourceDir()) / "datasets" / "scenarios" / (name + ".yaml");
  std::error_code ec;
  if (!plain || !fs::is_regular_file(path, ec)) {
    throw wpg::datasets::InputError("no shipped scenario '" + name + "'");
  }
  return path.string();
}

// yaml-cpp throws on the type of a missing key's node: these answer false instead.
bool isMap(const YAML::Node& node) { return node.IsDefined() && node.IsMap(); }
bool isSequence(const YAML::Node& node) { return node.IsDefined() && node.IsSequence(); }

// The length of a sequence node, 1 for anything else (a harness estimate only).
std::size_t lengthOf(const YAML::Node& node) {
  return isSequence(node) ? std::max<std::size_t>(node.size(), 1) : 1;
}

std::size_t countOf(const YAML::Node& node) {
  if (!node.IsDefined() || !node.IsScalar()) return 1;
  try {
    const long long value = node.as<long long>();
    return value < 1 ? 1 : static_cast<std::size_t>(std::min<long long>(value, 1LL << 40));
  } catch (const YAML::Exception&) {
    return 1;
  }
}

// A generous estimate of the runs the study expands to (grid x zip x samples, or worlds x
// variants x seeds); 0 when the text does not parse (the loader reports that).
std::size_t estimatedRuns(const std::string& text) {
  try {
    const YAML::Node root = YAML::Load(text);
    if (!isMap(root)) return 0;
    std::size_t runs = 1;
    const auto times = [&](std::size_t factor) {
      runs = factor != 0 && runs > (std::size_t{1} << 40) / factor ? (std::size_t{1} << 40)
                                                                   : runs * factor;
    };
    const YAML::Node sweep = root["sweep"];
    if (isMap(sweep)) {
      if (isMap(sweep["grid"])) {
        for (const auto& item : sweep["grid"]) times(lengthOf(item.second));
      }
      if (isMap(sweep["zip"])) {
        std::size_t longest = 1;
        for (const auto& item : sweep["zip"]) longest = std::max(longest, lengthOf(item.second));
        times(longest);
      }
      if (isMap(sweep["random"])) times(countOf(sweep["random"]["samples"]));
    }
    times(lengthOf(root["worlds"]));
    if (isMap(root["variants"])) times(std::max<std::size_t>(root["variants"].size(), 1));
    times(isSequence(root["seeds"]) ? lengthOf(root["seeds"]) : countOf(root["seeds"]));
    return runs;
  } catch (const std::exception&) {  // YAML::Exception; the loader says what is wrong
    return 0;
  }
}

void checkStudy(const wpg::datasets::Study& study, const std::string& text) {
  std::set<std::string> names;
  // Names and values only (study_runs.hpp: describe), of every run: at most kMaxFuzzRuns.
  for (std::size_t i = 0; i < study.runs.size(); ++i) {
    const wpg::datasets::StudyRun run = study.runs.describe(i);
    if (!names.insert(run.name).second) propertyViolated("two runs named " + run.name, text);
    if (run.swept.size() != study.keys.size()) {
      propertyViolated("run " + run.name + " has not one value per swept key", text);
    }
  }
  if (study.runs.empty()) propertyViolated("an accepted study has no run", text);
  if (study.fingerprint.size() != 16) propertyViolated("fingerprint " + study.fingerprint, text);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_folder = wpg_fuzz::makePrivateFolder("wpg-fuzz-study-");
  if (g_folder.empty()) propertyViolated("cannot create a private folder", "");
  std::atexit(removeFolder);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string robots = std::string(wpg_test::sourceDir()) + "/robots";
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t separator = input.find('\0');
  const std::string text = input.substr(0, separator);
  const std::size_t runs = estimatedRuns(text);
  if (runs > kMaxFuzzRuns) return 0;

  const fs::path study_path = fs::path(g_folder) / "study.yaml";
  const fs::path base_path = fs::path(g_folder) / "base.yaml";
  writeFile(study_path, text);
  std::error_code ec;
  if (separator == std::string::npos) {
    fs::remove(base_path, ec);
  } else {
    writeFile(base_path, input.substr(separator + 1));
  }

  static const bool verbose = std::getenv("WPG_FUZZ_VERBOSE") != nullptr;
  try {
    const wpg::datasets::Study study =
        wpg::datasets::loadStudy(study_path.string(), shippedScenario, robots, 1);
    checkStudy(study, text);
    if (verbose) std::fprintf(stderr, "batch study: %zu runs\n", study.runs.size());
  } catch (const wpg::datasets::InputError& error) {
    if (verbose) std::fprintf(stderr, "batch study: %s\n", error.what());
  }
  try {
    const wpg::datasets::ComparisonStudy comparison =
        wpg::datasets::loadComparisonStudy(study_path.string(), shippedScenario, robots, 1);
    checkStudy(comparison.study, text);
    if (comparison.study.runs.size() !=
        comparison.worlds.size() * comparison.variants.size() * comparison.seeds.size()) {
      propertyViolated("runs are not worlds x variants x seeds", text);
    }
    if (verbose) std::fprintf(stderr, "comparison study: %zu runs\n", comparison.study.runs.size());
  } catch (const wpg::datasets::InputError& error) {
    if (verbose) std::fprintf(stderr, "comparison study: %s\n", error.what());
  }
  return 0;
}
