// The --set override grammar (scenario_overrides.hpp):
//   key := segment ('.' segment)* ; segment := name ('[' digits ']')*
// and its assignment into the parsed scenario tree.
#include "scenario_overrides.hpp"

#include <cctype>
#include <charconv>

#include <yaml-cpp/depthguard.h>

#include "wpg/datasets/input/input_limits.hpp"

namespace wpg::datasets::detail {
namespace {

std::vector<PathStep> parseOverrideKey(const std::string& key, const std::string& text,
                                       const Source& source) {
  // A key of thousands of names is shown by its start: the message stays one short line.
  const auto start_of = [](const std::string& long_text) {
    constexpr std::size_t kShown = 100;
    return long_text.size() <= kShown ? long_text : long_text.substr(0, kShown) + "...";
  };
  auto bad = [&](const std::string& why) -> void {
    source.failFile("--set '" + start_of(text) + "': expected key=value with a dotted key such " +
                    "as 'generator.sqp_iterations' or 'reference[1].v', got key '" +
                    start_of(key) + "' (" + why + ")");
  };
  std::vector<PathStep> path;
  std::size_t i = 0;
  const auto is_name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  };
  // Bounded before the path is walked (assignPath recurses, and names each step's container).
  const auto add = [&](PathStep step) {
    if (path.size() == kMaxOverridePathSteps) {
      bad("expected at most " + std::to_string(kMaxOverridePathSteps) +
          " names and indices; SCENARIOS.md, \"Limits\"");
    }
    path.push_back(std::move(step));
  };
  while (true) {
    const std::size_t start = i;
    while (i < key.size() && is_name_char(key[i])) ++i;
    if (i == start) bad("a name is empty or has a character other than letters, digits, _ and -");
    add({key.substr(start, i - start), 0});
    while (i < key.size() && key[i] == '[') {
      const std::size_t close = key.find(']', i);
      if (close == std::string::npos) bad("'[' without ']'");
      const std::string digits = key.substr(i + 1, close - i - 1);
      std::size_t index = 0;
      const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), index);
      if (digits.empty() || result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
        bad("a list index must be a non-negative integer");
      }
      add({"", index});
      i = close + 1;
    }
    if (i == key.size()) break;
    if (key[i] != '.') bad(std::string("unexpected '") + key[i] + "'");
    ++i;
  }
  return path;
}

}  // namespace

std::string pathText(const std::vector<PathStep>& path, std::size_t count) {
  std::string text;
  for (std::size_t i = 0; i < count; ++i) {
    text = path[i].key.empty() ? indexKey(text, path[i].index) : childKey(text, path[i].key);
  }
  return text;
}

void assignPath(YAML::Node node, const std::vector<PathStep>& path, std::size_t step,
                const YAML::Node& value, const std::string& text, const Source& source) {
  const PathStep& here = path[step];
  const bool last = step + 1 == path.size();
  const std::string where = pathText(path, step);  // the container being indexed
  const std::string target = pathText(path, step + 1);
  if (!here.key.empty()) {
    if (!node.IsDefined() || node.IsNull()) {
      node = YAML::Node(YAML::NodeType::Map);
    } else if (!node.IsMap()) {
      source.failFile("--set '" + text + "': key '" + target + "': '" + where +
                      "' is not a map, it is " + describe(node));
    }
    if (last) {
      node[here.key] = YAML::Clone(value);
    } else {
      assignPath(node[here.key], path, step + 1, value, text, source);
    }
    return;
  }
  if (!node.IsDefined() || node.IsNull()) node = YAML::Node(YAML::NodeType::Sequence);
  if (!node.IsSequence()) {
    source.failFile("--set '" + text + "': key '" + target + "': '" + where +
                    "' is not a list, it is " + describe(node));
  }
  if (here.index > node.size()) {
    source.failFile("--set '" + text + "': key '" + target + "': index " +
                    std::to_string(here.index) + " is out of range ('" + where + "' has " +
                    std::to_string(node.size()) + " entries; index " +
                    std::to_string(node.size()) + " appends)");
  }
  // Append explicitly: yaml-cpp's operator[] past the end would turn the list into a map.
  if (here.index == node.size()) node.push_back(YAML::Node(YAML::NodeType::Null));
  if (last) {
    node[here.index] = YAML::Clone(value);
  } else {
    assignPath(node[here.index], path, step + 1, value, text, source);
  }
}

ParsedOverride parseOverride(const std::string& text, Source* source) {
  const std::size_t equal = text.find('=');
  if (equal == std::string::npos) {
    source->failFile("--set '" + text +
                     "': expected key=value (e.g. duration=20 or reference[1].v=[0.3,0,0]), "
                     "got no '='");
  }
  const std::string key = text.substr(0, equal);
  const std::string value_text = text.substr(equal + 1);
  ParsedOverride parsed;
  parsed.text = text;
  parsed.path = parseOverrideKey(key, text, *source);
  try {
    // A second document ('1\n---\n2') would otherwise be dropped without a word.
    if (countYamlDocuments(value_text, 2) > 1) {
      source->failFile("--set '" + text + "': key '" + key +
                       (value_text.find("---") != std::string::npos
                            ? "': expected one YAML value, got 2 documents (separated by '---')"
                            : "': expected a YAML value, got a text yaml-cpp reads as endless "
                              "empty documents (a lone ',' does that)"));
    }
    parsed.value = YAML::Load(value_text);  // null when the text has no document
  } catch (const YAML::DeepRecursion&) {
    source->failFile("--set '" + text + "': key '" + key +
                     "': expected a YAML value with lists and maps nested less deeply (the YAML "
                     "reader stops past a few hundred levels)");
  } catch (const YAML::Exception& error) {
    source->failFile("--set '" + text + "': key '" + key +
                     "': expected a YAML value, got a syntax error: " + error.msg);
  }
  // From now on, messages about this key say that the value came from --set.
  source->addOverride({pathText(parsed.path, parsed.path.size()), text});
  return parsed;
}

}  // namespace wpg::datasets::detail
