// The --set override grammar (scenario_overrides.hpp):
//   key := segment ('.' segment)* ; segment := name ('[' digits ']')*
// and its assignment into the parsed scenario tree.
#include "scenario_overrides.hpp"

#include <cctype>
#include <charconv>

namespace wpg::datasets::detail {
namespace {

std::vector<PathStep> parseOverrideKey(const std::string& key, const std::string& text,
                                       const Source& source) {
  auto bad = [&](const std::string& why) -> void {
    source.failFile("--set '" + text + "': expected key=value with a dotted key such as " +
                    "'generator.sqp_iterations' or 'reference[1].v', got key '" + key + "' (" +
                    why + ")");
  };
  std::vector<PathStep> path;
  std::size_t i = 0;
  const auto is_name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  };
  while (true) {
    const std::size_t start = i;
    while (i < key.size() && is_name_char(key[i])) ++i;
    if (i == start) bad("a name is empty or has a character other than letters, digits, _ and -");
    path.push_back({key.substr(start, i - start), 0});
    while (i < key.size() && key[i] == '[') {
      const std::size_t close = key.find(']', i);
      if (close == std::string::npos) bad("'[' without ']'");
      const std::string digits = key.substr(i + 1, close - i - 1);
      std::size_t index = 0;
      const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), index);
      if (digits.empty() || result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
        bad("a list index must be a non-negative integer");
      }
      path.push_back({"", index});
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
    parsed.value = YAML::Load(value_text);
  } catch (const YAML::Exception& error) {
    source->failFile("--set '" + text + "': key '" + key +
                     "': expected a YAML value, got a syntax error: " + error.msg);
  }
  // From now on, messages about this key say that the value came from --set.
  source->addOverride({pathText(parsed.path, parsed.path.size()), text});
  return parsed;
}

}  // namespace wpg::datasets::detail
