// Scenario files: YAML in, a validated Scenario out. Every key is documented in
// datasets/SCENARIOS.md. Reading is strict on purpose: a typo in a key, a string where a
// number belongs or a NaN must stop the run with a message naming the file and the key,
// never be ignored silently (a batch of a thousand runs with a misspelled parameter is worse
// than no batch).
#include "wpg/datasets/scenario.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <yaml-cpp/yaml.h>

namespace wpg::datasets {
namespace {

namespace fs = std::filesystem;

// ------------------------------------------------------------------------------------------
// Text helpers
// ------------------------------------------------------------------------------------------

std::string oneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  }
  return text;
}

std::string shortened(const std::string& text, std::size_t max_length = 80) {
  if (text.size() <= max_length) return text;
  return text.substr(0, max_length - 3) + "...";
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

std::string childKey(const std::string& parent, const std::string& name) {
  return parent.empty() ? name : parent + "." + name;
}

std::string indexKey(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

// A quoted scalar ("10", '0.2') is a string for us even when its text is a number.
bool isQuoted(const YAML::Node& node) { return node.IsScalar() && node.Tag() == "!"; }

// What a node is, for "got ..." in messages.
std::string describe(const YAML::Node& node) {
  if (!node.IsDefined()) return "nothing (the key is missing)";
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return "null (no value)";
    case YAML::NodeType::Scalar:
      if (isQuoted(node)) return "the string \"" + shortened(oneLine(node.Scalar()), 60) + "\"";
      return shortened(oneLine(node.Scalar()), 60);
    case YAML::NodeType::Sequence:
    case YAML::NodeType::Map: {
      YAML::Emitter flow;
      flow.SetMapFormat(YAML::Flow);
      flow.SetSeqFormat(YAML::Flow);
      flow << node;
      const std::string what = node.IsSequence()
                                   ? "a list of " + std::to_string(node.size()) + " entries "
                                   : std::string("a map ");
      return what + shortened(oneLine(flow.c_str()), 60);
    }
    case YAML::NodeType::Undefined:
      break;
  }
  return "nothing";
}

// Shortest text that reads back to the same double, always recognisable as a float by YAML
// readers (PyYAML needs a dot: "10.0", "1.0e-05").
std::string formatNumber(double value) {
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  std::string text(buffer.data(), result.ptr);
  if (text.find_first_of(".ein") == std::string::npos) return text + ".0";
  const std::size_t e = text.find('e');
  if (e != std::string::npos && text.find('.') == std::string::npos) text.insert(e, ".0");
  return text;
}

// ------------------------------------------------------------------------------------------
// Where an error comes from: the file, and the --set overrides that changed its tree.
// ------------------------------------------------------------------------------------------

struct AppliedOverride {
  std::string key;   // canonical dotted path, e.g. reference[1].v
  std::string text;  // as given, key=value
};

class Source {
 public:
  explicit Source(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }
  void addOverride(AppliedOverride applied) { overrides_.push_back(std::move(applied)); }

  // "<file>: key '<key>': expected <expected>, got <what came>"
  [[noreturn]] void fail(const std::string& key, const std::string& expected,
                         const YAML::Node& got) const {
    failWith(key, "expected " + expected + ", got " + describe(got));
  }
  [[noreturn]] void failWith(const std::string& key, const std::string& message) const {
    throw InputError(oneLine(file_ + ": key '" + key + "': " + message + overrideNote(key)));
  }
  [[noreturn]] void failFile(const std::string& message) const {
    throw InputError(oneLine(file_ + ": " + message));
  }

 private:
  // Points at the --set that produced a bad value, since the file itself may be fine.
  std::string overrideNote(const std::string& key) const {
    for (const AppliedOverride& applied : overrides_) {
      // The bad key is the override's key, lies below it, or holds it (a list that an
      // override lengthened).
      if (encloses(applied.key, key) || encloses(key, applied.key)) {
        return " (set by --set '" + applied.text + "')";
      }
    }
    return "";
  }

  // `outer` is `inner` or one of its parents (dotted path / list index).
  static bool encloses(const std::string& outer, const std::string& inner) {
    if (inner.compare(0, outer.size(), outer) != 0) return false;
    return inner.size() == outer.size() || inner[outer.size()] == '.' ||
           inner[outer.size()] == '[';
  }

  std::string file_;
  std::vector<AppliedOverride> overrides_;
};

// ------------------------------------------------------------------------------------------
// Typed readers. `node` may be undefined (missing key): the message then says so.
// ------------------------------------------------------------------------------------------

// YAML's non-finite spellings (.inf, -.Inf, .NaN, ...) and the bare C ones.
bool isNonFiniteSpelling(const std::string& text) {
  static const std::set<std::string> spellings = {
      ".inf", ".Inf", ".INF", "+.inf", "+.Inf", "+.INF", "-.inf", "-.Inf", "-.INF",
      ".nan", ".NaN", ".NAN", "inf",   "-inf",  "+inf",  "nan",   "NaN",   "Infinity",
      "-Infinity"};
  return spellings.count(text) > 0;
}

double readNumber(const YAML::Node& node, const std::string& key, const std::string& expected,
                  const Source& source) {
  if (!node.IsDefined() || !node.IsScalar() || isQuoted(node)) source.fail(key, expected, node);
  std::string text = node.Scalar();
  if (isNonFiniteSpelling(text)) {
    source.failWith(key, "expected " + expected + ", got " + text + " (not a finite number)");
  }
  if (!text.empty() && text[0] == '+') text.erase(0, 1);
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(begin, end, value);
  if (text.empty() || result.ec != std::errc() || result.ptr != end) {
    source.fail(key, expected, node);
  }
  if (!std::isfinite(value)) {
    source.failWith(key, "expected " + expected + ", got " + text + " (not a finite number)");
  }
  return value;
}

double readNumberAtLeast(const YAML::Node& node, const std::string& key, double minimum,
                         const std::string& expected, const Source& source) {
  const double value = readNumber(node, key, expected, source);
  if (value < minimum) source.fail(key, expected, node);
  return value;
}

double readPositive(const YAML::Node& node, const std::string& key, const std::string& expected,
                    const Source& source) {
  const double value = readNumber(node, key, expected, source);
  if (!(value > 0.0)) source.fail(key, expected, node);
  return value;
}

int readInteger(const YAML::Node& node, const std::string& key, int minimum,
                const std::string& expected, const Source& source) {
  if (!node.IsDefined() || !node.IsScalar() || isQuoted(node)) source.fail(key, expected, node);
  std::string text = node.Scalar();
  if (!text.empty() && text[0] == '+') text.erase(0, 1);
  int value = 0;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  if (text.empty() || result.ec != std::errc() || result.ptr != end || value < minimum) {
    source.fail(key, expected, node);
  }
  return value;
}

// YAML 1.2's core booleans; quoted text is a string, and yes/no/on/off (YAML 1.1) are not
// accepted: they read as strings in other YAML readers.
bool readBoolean(const YAML::Node& node, const std::string& key, const std::string& expected,
                 const Source& source) {
  if (!node.IsDefined() || !node.IsScalar() || isQuoted(node)) source.fail(key, expected, node);
  const std::string& text = node.Scalar();
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  source.fail(key, expected, node);
}

// Names become folder names (robot) and HDF5 group names (scenario): keep them plain.
std::string readName(const YAML::Node& node, const std::string& key, const std::string& expected,
                     const Source& source) {
  if (!node.IsDefined() || !node.IsScalar()) source.fail(key, expected, node);
  const std::string& text = node.Scalar();
  const bool plain = !text.empty() && text != "." && text != ".." &&
                     text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                            "0123456789_-.") == std::string::npos;
  if (!plain) source.fail(key, expected, node);
  return text;
}

template <int Size>
Eigen::Matrix<double, Size, 1> readVector(const YAML::Node& node, const std::string& key,
                                          const std::string& expected, const Source& source) {
  if (!node.IsDefined() || !node.IsSequence() || node.size() != static_cast<std::size_t>(Size)) {
    source.fail(key, expected, node);
  }
  Eigen::Matrix<double, Size, 1> vector;
  for (int i = 0; i < Size; ++i) {
    vector[i] = readNumber(node[static_cast<std::size_t>(i)], indexKey(key, i), "a number", source);
  }
  return vector;
}

// The entries of a map, checked: keys are plain scalars, not repeated, all known. A map is
// required; `null_is_empty` accepts `key:` with no value as an empty map (optional sections).
using Entries = std::map<std::string, YAML::Node>;

Entries readMap(const YAML::Node& node, const std::string& key,
                const std::vector<std::string>& known_keys, const std::string& expected,
                const Source& source, bool null_is_empty = false) {
  Entries entries;
  if (null_is_empty && node.IsDefined() && node.IsNull()) return entries;
  if (!node.IsDefined() || !node.IsMap()) {
    if (key.empty()) source.failFile("expected " + expected + ", got " + describe(node));
    source.fail(key, expected, node);
  }
  for (const auto& pair : node) {
    if (!pair.first.IsScalar()) {
      source.fail(key.empty() ? "<top level>" : key, "keys that are plain names",
                  pair.first);
    }
    const std::string name = pair.first.Scalar();
    const std::string full = childKey(key, name);
    bool known = false;
    for (const std::string& k : known_keys) known = known || k == name;
    if (!known) {
      source.failWith(full, "unknown key (a typo?); known keys" +
                                (key.empty() ? std::string() : " of '" + key + "'") + ": " +
                                joinNames(known_keys));
    }
    if (!entries.emplace(name, pair.second).second) {
      source.failWith(full, "appears twice; give each key once");
    }
  }
  return entries;
}

// The entry `name` of `entries`, or an undefined node (missing key).
YAML::Node entry(const Entries& entries, const std::string& name) {
  const auto it = entries.find(name);
  if (it == entries.end()) return YAML::Node(YAML::NodeType::Undefined);
  return it->second;
}

bool present(const Entries& entries, const std::string& name) {
  const auto it = entries.find(name);
  return it != entries.end() && !it->second.IsNull();
}

// ------------------------------------------------------------------------------------------
// Reading a YAML file with syntax errors reported by line.
// ------------------------------------------------------------------------------------------

// `text` parsed as one YAML document; `origin` names it in messages.
YAML::Node parseYamlText(const std::string& text, const std::string& origin) {
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& error) {
    std::string where;
    if (!error.mark.is_null()) {
      where = "line " + std::to_string(error.mark.line + 1) + ", column " +
              std::to_string(error.mark.column + 1) + ": ";
    }
    throw InputError(oneLine(origin + ": " + where + "YAML syntax error: " + error.msg));
  }
  if (documents.size() > 1) {
    throw InputError(origin + ": expected one YAML document, got " +
                     std::to_string(documents.size()) + " (separated by '---')");
  }
  if (documents.empty()) return YAML::Node(YAML::NodeType::Null);
  return documents.front();
}

YAML::Node readYamlFile(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    throw InputError(path + ": cannot read the " + what + ": it is a directory");
  }
  errno = 0;
  std::ifstream stream(path, std::ios::binary);
  if (!stream) {
    const int error = errno;
    throw InputError(path + ": cannot read the " + what + ": " +
                     (error != 0 ? std::strerror(error) : "cannot open the file"));
  }
  std::ostringstream text;
  text << stream.rdbuf();
  if (stream.bad()) throw InputError(path + ": cannot read the " + what + ": read error");
  return parseYamlText(text.str(), path);
}

// ------------------------------------------------------------------------------------------
// Walking parameters: one YAML key per WalkingParameters field, same name.
// ------------------------------------------------------------------------------------------

struct WalkingField {
  const char* name;
  double WalkingParameters::*number;
  int WalkingParameters::*integer;
  std::array<double, 5> WalkingParameters::*polygon;
  HeadingReference WalkingParameters::*heading;
};

WalkingField numberField(const char* name, double WalkingParameters::*member) {
  return {name, member, nullptr, nullptr, nullptr};
}
WalkingField integerField(const char* name, int WalkingParameters::*member) {
  return {name, nullptr, member, nullptr, nullptr};
}
WalkingField polygonField(const char* name, std::array<double, 5> WalkingParameters::*member) {
  return {name, nullptr, nullptr, member, nullptr};
}
WalkingField headingField(const char* name, HeadingReference WalkingParameters::*member) {
  return {name, nullptr, nullptr, nullptr, member};
}

// In the struct's order (walking_parameters.hpp); the resolved YAML keeps it.
const std::vector<WalkingField>& walkingFields() {
  using P = WalkingParameters;
  static const std::vector<WalkingField> fields = {
      numberField("com_height", &P::com_height),
      numberField("gravity", &P::gravity),
      numberField("sampling_period", &P::sampling_period),
      integerField("horizon_length", &P::horizon_length),
      integerField("single_support_samples", &P::single_support_samples),
      integerField("double_support_samples", &P::double_support_samples),
      integerField("previewed_steps", &P::previewed_steps),
      integerField("start_double_support_samples", &P::start_double_support_samples),
      integerField("velocity_window_samples", &P::velocity_window_samples),
      headingField("heading_reference", &P::heading_reference),
      numberField("control_period", &P::control_period),
      numberField("foot_length", &P::foot_length),
      numberField("foot_width", &P::foot_width),
      numberField("ankle_height", &P::ankle_height),
      numberField("cop_margin_x", &P::cop_margin_x),
      numberField("cop_margin_y", &P::cop_margin_y),
      numberField("initial_foot_separation", &P::initial_foot_separation),
      numberField("stop_foot_separation", &P::stop_foot_separation),
      numberField("obstacle_foot_radius", &P::obstacle_foot_radius),
      polygonField("feasibility_x", &P::feasibility_x),
      polygonField("feasibility_y", &P::feasibility_y),
      numberField("max_step_yaw_change", &P::max_step_yaw_change),
      numberField("weight_velocity", &P::weight_velocity),
      numberField("weight_yaw", &P::weight_yaw),
      numberField("weight_cop", &P::weight_cop),
      numberField("weight_jerk", &P::weight_jerk),
      numberField("step_height", &P::step_height),
      numberField("max_forward_velocity", &P::max_forward_velocity),
      numberField("max_lateral_velocity", &P::max_lateral_velocity),
      numberField("max_angular_velocity", &P::max_angular_velocity),
  };
  return fields;
}

std::vector<std::string> walkingFieldNames() {
  std::vector<std::string> names;
  for (const WalkingField& field : walkingFields()) names.push_back(field.name);
  return names;
}

// Sets the fields present in `entries`; `require_all` for a robot file, which must state
// every parameter (a new robot silently inheriting HRP-2's feet would be a bad surprise).
void readWalkingFields(const Entries& entries, const std::string& prefix, bool require_all,
                       const Source& source, WalkingParameters* parameters) {
  for (const WalkingField& field : walkingFields()) {
    const YAML::Node node = entry(entries, field.name);
    const std::string key = childKey(prefix, field.name);
    if (!node.IsDefined()) {
      if (require_all) source.fail(key, "a value (every walking parameter is required here)", node);
      continue;
    }
    if (field.number) {
      parameters->*field.number = readNumber(node, key, "a number", source);
    } else if (field.integer) {
      parameters->*field.integer =
          readInteger(node, key, std::numeric_limits<int>::min(), "an integer", source);
    } else if (field.heading) {
      if (!node.IsScalar() || !parseHeadingReference(node.Scalar(), &(parameters->*field.heading)))
        source.fail(key, "support_foot or command", node);
    } else {
      const Eigen::Matrix<double, 5, 1> values =
          readVector<5>(node, key, "a list of 5 numbers [m]", source);
      for (int i = 0; i < 5; ++i) (parameters->*field.polygon)[i] = values[i];
    }
  }
}

struct Robot {
  WalkingParameters walking;
  double mass = 0.0;
  Entries nodes;  // the file's walking parameters as YAML, merged under the scenario's
};

std::vector<std::string> knownRobots(const std::string& robots_dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(robots_dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code file_ec;
    if (fs::is_regular_file(it->path() / "walking.yaml", file_ec)) {
      names.push_back(it->path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

Robot loadRobot(const std::string& robot_file) {
  const Source source(robot_file);
  const YAML::Node root = readYamlFile(robot_file, "robot walking parameters");
  std::vector<std::string> keys = walkingFieldNames();
  keys.push_back("mass");
  const Entries entries =
      readMap(root, "", keys, "a map of walking parameters (robots/README)", source);
  Robot robot;
  readWalkingFields(entries, "", /*require_all=*/true, source, &robot.walking);
  robot.nodes = entries;
  robot.nodes.erase("mass");
  robot.mass = readPositive(entry(entries, "mass"), "mass", "a positive mass in kg", source);
  return robot;
}

// ------------------------------------------------------------------------------------------
// --set key=value
// ------------------------------------------------------------------------------------------

struct PathStep {
  std::string key;          // map key, or empty for a list index
  std::size_t index = 0;    // list index when key is empty
};

std::string pathText(const std::vector<PathStep>& path, std::size_t count) {
  std::string text;
  for (std::size_t i = 0; i < count; ++i) {
    text = path[i].key.empty() ? indexKey(text, path[i].index) : childKey(text, path[i].key);
  }
  return text;
}

// key := segment ('.' segment)* ; segment := name ('[' digits ']')*
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

// Sets path[step..] below `node` (a handle sharing the tree's data) to `value`.
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

struct ParsedOverride {
  std::vector<PathStep> path;
  YAML::Node value;
  std::string text;
};

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

// ------------------------------------------------------------------------------------------
// The scenario sections
// ------------------------------------------------------------------------------------------

const std::vector<std::string>& topLevelKeys() {
  static const std::vector<std::string> keys = {
      "name",   "robot",     "duration", "robot_mass", "generator",      "reference",
      "pushes", "obstacles", "walking",  "replay",     "filter",         "filter_settings"};
  return keys;
}

GeneratorSettings readGenerator(const YAML::Node& node, const Source& source) {
  GeneratorSettings settings;
  if (!node.IsDefined()) return settings;
  const Entries entries = readMap(
      node, "generator",
      {"algorithm", "sqp_iterations", "max_sqp_iterations", "sqp_tolerance", "max_qp_iterations",
       "slack_weight", "fall_capture_distance", "max_obstacles_in_qp", "obstacle_reach"},
      "a map of generator settings", source, /*null_is_empty=*/true);
  if (present(entries, "algorithm")) {
    const YAML::Node algorithm = entry(entries, "algorithm");
    if (!algorithm.IsScalar() ||
        !parseGeneratorAlgorithm(algorithm.Scalar(), &settings.algorithm)) {
      source.fail("generator.algorithm", "nmpc or lmpc", algorithm);
    }
  }
  if (present(entries, "sqp_iterations")) {
    settings.sqp_iterations =
        readInteger(entry(entries, "sqp_iterations"), "generator.sqp_iterations", 0,
                    "an integer >= 0 (1 = real-time iteration, 0 = to convergence)", source);
  }
  if (present(entries, "max_sqp_iterations")) {
    settings.max_sqp_iterations = readInteger(entry(entries, "max_sqp_iterations"),
                                              "generator.max_sqp_iterations", 1,
                                              "an integer >= 1", source);
  }
  if (present(entries, "sqp_tolerance")) {
    settings.sqp_tolerance = readPositive(entry(entries, "sqp_tolerance"),
                                          "generator.sqp_tolerance", "a positive number", source);
  }
  if (present(entries, "max_qp_iterations")) {
    settings.max_qp_iterations = readInteger(entry(entries, "max_qp_iterations"),
                                             "generator.max_qp_iterations", 1,
                                             "an integer >= 1", source);
  }
  if (present(entries, "slack_weight")) {
    settings.slack_weight = readPositive(entry(entries, "slack_weight"), "generator.slack_weight",
                                         "a positive number", source);
  }
  if (present(entries, "fall_capture_distance")) {
    settings.fall_capture_distance =
        readPositive(entry(entries, "fall_capture_distance"), "generator.fall_capture_distance",
                     "a positive distance in m", source);
  }
  if (present(entries, "max_obstacles_in_qp")) {
    const std::string expected = "an integer in [0, 32] (obstacles in the QP at each sample)";
    settings.max_obstacles_in_qp =
        readInteger(entry(entries, "max_obstacles_in_qp"), "generator.max_obstacles_in_qp", 0,
                    expected, source);
    if (settings.max_obstacles_in_qp > 32) {
      source.fail("generator.max_obstacles_in_qp", expected, entry(entries, "max_obstacles_in_qp"));
    }
  }
  if (present(entries, "obstacle_reach")) {
    settings.obstacle_reach =
        readPositive(entry(entries, "obstacle_reach"), "generator.obstacle_reach",
                     "a positive distance in m", source);
  }
  return settings;
}

// The dynamic filter's preview controller (Kajita et al. 2003; wpg/preview_control.hpp).
PreviewControlSettings readFilterSettings(const YAML::Node& node, const Source& source) {
  PreviewControlSettings settings;
  if (!node.IsDefined()) return settings;
  const Entries entries =
      readMap(node, "filter_settings", {"error_weight", "input_weight", "preview_time"},
              "a map {error_weight, input_weight, preview_time}", source, /*null_is_empty=*/true);
  if (present(entries, "error_weight")) {
    settings.error_weight = readPositive(entry(entries, "error_weight"),
                                         "filter_settings.error_weight",
                                         "a positive weight (Qe)", source);
  }
  if (present(entries, "input_weight")) {
    settings.input_weight = readPositive(entry(entries, "input_weight"),
                                         "filter_settings.input_weight",
                                         "a positive weight (R)", source);
  }
  if (present(entries, "preview_time")) {
    settings.preview_time = readPositive(entry(entries, "preview_time"),
                                         "filter_settings.preview_time",
                                         "a positive duration in seconds", source);
  }
  return settings;
}

std::vector<VelocityCommand> readReference(const YAML::Node& node, const Source& source) {
  const std::string expected =
      "a list of {t: seconds, v: [vx, vy, omega]} entries (may be empty: stand still)";
  if (!node.IsDefined() || !node.IsSequence()) source.fail("reference", expected, node);
  std::vector<VelocityCommand> reference;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string key = indexKey("reference", i);
    const Entries entries = readMap(node[i], key, {"t", "v"}, "a map {t: seconds, v: [vx, vy, omega]}", source);
    VelocityCommand command;
    command.t = readNumberAtLeast(entry(entries, "t"), key + ".t", 0.0,
                                  "a time >= 0 in seconds", source);
    if (!reference.empty() && !(command.t > reference.back().t)) {
      source.fail(key + ".t",
                  "a time after " + indexKey("reference", i - 1) + ".t = " +
                      formatNumber(reference.back().t) + " s (times strictly ascending)",
                  entry(entries, "t"));
    }
    command.velocity = readVector<3>(entry(entries, "v"), key + ".v",
                                     "[vx m/s, vy m/s, omega rad/s] (3 numbers)", source);
    reference.push_back(command);
  }
  return reference;
}

std::vector<Push> readPushes(const YAML::Node& node, const Source& source) {
  std::vector<Push> pushes;
  if (!node.IsDefined() || node.IsNull()) return pushes;
  if (!node.IsSequence()) {
    source.fail("pushes", "a list of {t: s, force: [fx, fy] N, duration: s} entries", node);
  }
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string key = indexKey("pushes", i);
    const Entries entries =
        readMap(node[i], key, {"t", "force", "duration"},
                "a map {t: s, force: [fx, fy] N, duration: s}", source);
    Push push;
    push.t = readNumberAtLeast(entry(entries, "t"), key + ".t", 0.0, "a time >= 0 in seconds",
                               source);
    push.force = readVector<2>(entry(entries, "force"), key + ".force",
                               "[fx, fy] in N, world frame (2 numbers)", source);
    if (present(entries, "duration")) {
      push.duration = readPositive(entry(entries, "duration"), key + ".duration",
                                   "a positive duration in seconds", source);
    }
    pushes.push_back(push);
  }
  return pushes;
}

// Convex obstacles (paper Sec. III-D): the keys depend on the type, read first.
std::vector<Obstacle> readObstacles(const YAML::Node& node, const Source& source) {
  std::vector<Obstacle> obstacles;
  if (!node.IsDefined() || node.IsNull()) return obstacles;
  if (!node.IsSequence()) {
    source.fail("obstacles",
                "a list of obstacles such as {type: circle, center: [x, y], radius: r, margin: m}",
                node);
  }
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string key = indexKey("obstacles", i);
    const YAML::Node item = node[i];
    const std::string map_expected = "a map {type: circle, box or polygon, ...} (SCENARIOS.md)";
    if (!item.IsMap()) source.fail(key, map_expected, item);
    // (A missing key of a const map is an invalid node: replace it by an undefined one.)
    const YAML::Node found_type = item["type"];
    const YAML::Node type_node =
        found_type.IsDefined() ? found_type : YAML::Node(YAML::NodeType::Undefined);
    Obstacle obstacle;
    std::vector<std::string> keys;
    const std::string type = type_node.IsScalar() ? type_node.Scalar() : "";
    if (type == "circle") {
      obstacle.type = ObstacleType::kCircle;
      keys = {"type", "center", "radius", "margin"};
    } else if (type == "box") {
      obstacle.type = ObstacleType::kBox;
      keys = {"type", "center", "size", "yaw", "margin"};
    } else if (type == "polygon") {
      obstacle.type = ObstacleType::kPolygon;
      keys = {"type", "vertices", "margin"};
    } else {
      source.fail(key + ".type", "circle, box or polygon", type_node);
    }
    const Entries entries = readMap(item, key, keys, map_expected, source);
    if (obstacle.type == ObstacleType::kCircle || obstacle.type == ObstacleType::kBox) {
      obstacle.center = readVector<2>(entry(entries, "center"), key + ".center",
                                      "[x, y] in m, world frame (2 numbers)", source);
    }
    if (obstacle.type == ObstacleType::kCircle) {
      obstacle.radius =
          readPositive(entry(entries, "radius"), key + ".radius", "a positive radius in m", source);
    }
    if (obstacle.type == ObstacleType::kBox) {
      const std::string size_expected = "[length along its x, width] in m (2 positive numbers)";
      obstacle.size = readVector<2>(entry(entries, "size"), key + ".size", size_expected, source);
      if (!(obstacle.size.minCoeff() > 0.0))
        source.fail(key + ".size", size_expected, entry(entries, "size"));
      if (present(entries, "yaw")) {
        obstacle.yaw = readNumber(entry(entries, "yaw"), key + ".yaw", "an angle in rad", source);
      }
    }
    if (obstacle.type == ObstacleType::kPolygon) {
      const std::string vertices_expected =
          "a list of at least 3 [x, y] vertices in m, world frame, of a convex polygon";
      const YAML::Node vertices = entry(entries, "vertices");
      if (!vertices.IsDefined() || !vertices.IsSequence() || vertices.size() < 3) {
        source.fail(key + ".vertices", vertices_expected, vertices);
      }
      for (std::size_t v = 0; v < vertices.size(); ++v) {
        obstacle.vertices.push_back(readVector<2>(vertices[v], indexKey(key + ".vertices", v),
                                                  "[x, y] in m (2 numbers)", source));
      }
    }
    if (present(entries, "margin")) {
      obstacle.margin = readNumberAtLeast(entry(entries, "margin"), key + ".margin", 0.0,
                                          "a distance >= 0 in m", source);
    }
    // Shape checks owned by libwpg (convexity, degenerate polygons). Their message reads
    // "'<key>': expected <field>: <what>"; ours names the field's key instead.
    try {
      obstacle.validate(key);
    } catch (const std::invalid_argument& error) {
      std::string message = error.what();
      std::string field_key = key;
      const std::string prefix = "'" + key + "': ";
      if (message.compare(0, prefix.size(), prefix) == 0) message.erase(0, prefix.size());
      const std::string expected = "expected ";
      const std::size_t colon = message.find(": ");
      if (message.compare(0, expected.size(), expected) == 0 && colon != std::string::npos) {
        const std::string field = message.substr(expected.size(), colon - expected.size());
        if (!field.empty() &&
            field.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == std::string::npos) {
          field_key = childKey(key, field);
          message = expected + message.substr(colon + 2);
        }
      }
      source.failWith(field_key, message);
    }
    obstacles.push_back(obstacle);
  }
  return obstacles;
}

// ------------------------------------------------------------------------------------------
// The resolved scenario, emitted: every key explicit, numbers in a canonical form.
// ------------------------------------------------------------------------------------------

void emitNumbers(YAML::Emitter& out, const double* values, int count) {
  out << YAML::Flow << YAML::BeginSeq;
  for (int i = 0; i < count; ++i) out << formatNumber(values[i]);
  out << YAML::EndSeq;
}

std::string emitResolved(const Scenario& scenario) {
  const WalkRequest& request = scenario.request;
  const GeneratorSettings& generator = request.generator;
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << scenario.name;
  out << YAML::Key << "robot" << YAML::Value << scenario.robot;
  out << YAML::Key << "duration" << YAML::Value << formatNumber(request.duration);
  out << YAML::Key << "robot_mass" << YAML::Value << formatNumber(request.robot_mass);

  out << YAML::Key << "generator" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "algorithm" << YAML::Value << generatorAlgorithmName(generator.algorithm);
  out << YAML::Key << "sqp_iterations" << YAML::Value << generator.sqp_iterations;
  out << YAML::Key << "max_sqp_iterations" << YAML::Value << generator.max_sqp_iterations;
  out << YAML::Key << "sqp_tolerance" << YAML::Value << formatNumber(generator.sqp_tolerance);
  out << YAML::Key << "max_qp_iterations" << YAML::Value << generator.max_qp_iterations;
  out << YAML::Key << "slack_weight" << YAML::Value << formatNumber(generator.slack_weight);
  out << YAML::Key << "fall_capture_distance" << YAML::Value
      << formatNumber(generator.fall_capture_distance);
  out << YAML::Key << "max_obstacles_in_qp" << YAML::Value << generator.max_obstacles_in_qp;
  out << YAML::Key << "obstacle_reach" << YAML::Value << formatNumber(generator.obstacle_reach);
  out << YAML::EndMap;

  out << YAML::Key << "reference" << YAML::Value;
  if (request.reference.empty()) out << YAML::Flow;
  out << YAML::BeginSeq;
  for (const VelocityCommand& command : request.reference) {
    out << YAML::Flow << YAML::BeginMap;
    out << YAML::Key << "t" << YAML::Value << formatNumber(command.t);
    out << YAML::Key << "v" << YAML::Value;
    emitNumbers(out, command.velocity.data(), 3);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;

  out << YAML::Key << "pushes" << YAML::Value;
  if (request.pushes.empty()) out << YAML::Flow;
  out << YAML::BeginSeq;
  for (const Push& push : request.pushes) {
    out << YAML::Flow << YAML::BeginMap;
    out << YAML::Key << "t" << YAML::Value << formatNumber(push.t);
    out << YAML::Key << "force" << YAML::Value;
    emitNumbers(out, push.force.data(), 2);
    out << YAML::Key << "duration" << YAML::Value << formatNumber(push.duration);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;

  out << YAML::Key << "obstacles" << YAML::Value;
  if (request.obstacles.empty()) out << YAML::Flow;
  out << YAML::BeginSeq;
  for (const Obstacle& obstacle : request.obstacles) {
    out << YAML::Flow << YAML::BeginMap;
    out << YAML::Key << "type" << YAML::Value << obstacleTypeName(obstacle.type);
    if (obstacle.type == ObstacleType::kPolygon) {
      out << YAML::Key << "vertices" << YAML::Value << YAML::Flow << YAML::BeginSeq;
      for (const Eigen::Vector2d& vertex : obstacle.vertices) emitNumbers(out, vertex.data(), 2);
      out << YAML::EndSeq;
    } else {
      out << YAML::Key << "center" << YAML::Value;
      emitNumbers(out, obstacle.center.data(), 2);
    }
    if (obstacle.type == ObstacleType::kCircle) {
      out << YAML::Key << "radius" << YAML::Value << formatNumber(obstacle.radius);
    }
    if (obstacle.type == ObstacleType::kBox) {
      out << YAML::Key << "size" << YAML::Value;
      emitNumbers(out, obstacle.size.data(), 2);
      out << YAML::Key << "yaw" << YAML::Value << formatNumber(obstacle.yaw);
    }
    out << YAML::Key << "margin" << YAML::Value << formatNumber(obstacle.margin);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;

  out << YAML::Key << "replay" << YAML::Value << scenario.replay;
  out << YAML::Key << "filter" << YAML::Value << scenario.filter;
  out << YAML::Key << "filter_settings" << YAML::Value << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "error_weight" << YAML::Value
      << formatNumber(scenario.filter_settings.error_weight);
  out << YAML::Key << "input_weight" << YAML::Value
      << formatNumber(scenario.filter_settings.input_weight);
  out << YAML::Key << "preview_time" << YAML::Value
      << formatNumber(scenario.filter_settings.preview_time);
  out << YAML::EndMap;

  out << YAML::Key << "walking" << YAML::Value << YAML::BeginMap;
  for (const WalkingField& field : walkingFields()) {
    out << YAML::Key << field.name << YAML::Value;
    if (field.number) {
      out << formatNumber(scenario.walking.*field.number);
    } else if (field.integer) {
      out << scenario.walking.*field.integer;
    } else if (field.heading) {
      out << headingReferenceName(scenario.walking.*field.heading);
    } else {
      emitNumbers(out, (scenario.walking.*field.polygon).data(), 5);
    }
  }
  out << YAML::EndMap;
  out << YAML::EndMap;
  if (!out.good()) throw std::logic_error("emitting the resolved scenario: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

}  // namespace

namespace {

// `root` is the parsed scenario of `path` (a file, or the origin of a text).
Scenario loadScenarioTree(YAML::Node root, const std::string& path,
                          const std::vector<std::string>& overrides,
                          const std::string& robots_dir) {
  Source source(path);
  Scenario scenario;
  scenario.source_path = path;
  try {
    if (root.IsNull() && !overrides.empty()) root = YAML::Node(YAML::NodeType::Map);
    if (!root.IsMap()) {
      source.failFile("expected a map of scenario keys (" + joinNames(topLevelKeys()) +
                      "), got " + (root.IsNull() ? std::string("an empty file") : describe(root)));
    }
    std::vector<ParsedOverride> parsed_overrides;
    for (const std::string& text : overrides) {
      parsed_overrides.push_back(parseOverride(text, &source));
    }

    // The robot first (a --set robot=... included): its walking parameters are the base that
    // the scenario's `walking:` map and then the overrides modify, so that an override such
    // as walking.feasibility_y[2]=0.35 changes one entry of the robot's list.
    // Reads through a const handle: yaml-cpp's non-const operator[] inserts keys, and
    // assigning to a Node that refers into the tree overwrites the tree.
    const YAML::Node& const_root = root;
    // Unknown keys first: a misspelt `robot:` should be reported as the typo it is.
    readMap(const_root, "", topLevelKeys(), "a map of scenario keys", source);
    const ParsedOverride* robot_override = nullptr;
    for (const ParsedOverride& parsed : parsed_overrides) {
      if (parsed.path.size() == 1 && parsed.path[0].key == "robot") robot_override = &parsed;
    }
    const YAML::Node robot_node = robot_override ? robot_override->value : const_root["robot"];
    const std::vector<std::string> robots = knownRobots(robots_dir);
    const std::string robot_expected =
        "the name of a folder of " + robots_dir + " holding walking.yaml (known robots: " +
        (robots.empty() ? std::string("none") : joinNames(robots)) + ")";
    scenario.robot = readName(robot_node, "robot", robot_expected, source);
    const fs::path robot_file = fs::path(robots_dir) / scenario.robot / "walking.yaml";
    std::error_code ec;
    if (!fs::is_regular_file(robot_file, ec)) source.fail("robot", robot_expected, robot_node);
    const Robot robot = loadRobot(robot_file.string());
    scenario.request.robot_mass = robot.mass;

    // walking := robot's parameters, then the scenario's (checked: known keys, given once).
    {
      Entries scenario_walking;
      const YAML::Node own_walking = const_root["walking"];
      if (own_walking.IsDefined() && !own_walking.IsNull()) {
        scenario_walking = readMap(own_walking, "walking", walkingFieldNames(),
                                   "a map of walking parameters", source);
      }
      YAML::Node merged(YAML::NodeType::Map);
      for (const WalkingField& field : walkingFields()) {
        const auto own = scenario_walking.find(field.name);
        merged[field.name] = YAML::Clone(own != scenario_walking.end()
                                             ? own->second
                                             : robot.nodes.at(field.name));
      }
      root["walking"] = merged;
    }
    for (const ParsedOverride& parsed : parsed_overrides) {
      assignPath(root, parsed.path, 0, parsed.value, parsed.text, source);
    }

    const Entries entries = readMap(root, "", topLevelKeys(), "a map of scenario keys", source);

    scenario.name = readName(entry(entries, "name"), "name",
                             "a name of letters, digits, '_', '-', '.' (the HDF5 group name)",
                             source);
    if (readName(entry(entries, "robot"), "robot", robot_expected, source) != scenario.robot) {
      throw std::logic_error("loadScenario: the robot changed while merging");
    }
    scenario.walking = robot.walking;
    const Entries walking = readMap(entry(entries, "walking"), "walking", walkingFieldNames(),
                                    "a map of walking parameters", source);
    readWalkingFields(walking, "walking", /*require_all=*/false, source, &scenario.walking);

    scenario.request.duration = readPositive(entry(entries, "duration"), "duration",
                                             "a positive number of seconds", source);
    if (present(entries, "robot_mass")) {
      scenario.request.robot_mass = readPositive(entry(entries, "robot_mass"), "robot_mass",
                                                 "a positive mass in kg", source);
    }
    scenario.request.generator = readGenerator(entry(entries, "generator"), source);
    scenario.request.reference = readReference(entry(entries, "reference"), source);
    scenario.request.pushes = readPushes(entry(entries, "pushes"), source);
    scenario.request.obstacles = readObstacles(entry(entries, "obstacles"), source);
    if (present(entries, "filter")) {
      scenario.filter = readBoolean(entry(entries, "filter"), "filter", "true or false", source);
    }
    // The filter replays the walk (before and after its correction): filter implies replay.
    scenario.replay = scenario.filter;
    if (present(entries, "replay") &&
        readBoolean(entry(entries, "replay"), "replay", "true or false", source)) {
      scenario.replay = true;
    }
    scenario.filter_settings = readFilterSettings(entry(entries, "filter_settings"), source);
  } catch (const YAML::Exception& error) {
    // Not expected (types are checked before conversion); still one line naming the file.
    throw InputError(oneLine(path + ": " + error.what()));
  }

  // Cross-field checks owned by libwpg (ranges, consistency of timings, ...).
  try {
    scenario.walking.validate();
  } catch (const std::invalid_argument& error) {
    source.failFile(std::string("invalid walking parameters (robot '") + scenario.robot +
                    "' merged with 'walking:' and --set): " + error.what());
  }
  try {
    scenario.request.validate();
  } catch (const std::invalid_argument& error) {
    source.failFile(std::string("invalid walk request: ") + error.what());
  }

  scenario.resolved_yaml = emitResolved(scenario);
  return scenario;
}

}  // namespace

Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides,
                      const std::string& robots_dir) {
  return loadScenarioTree(readYamlFile(path, "scenario file"), path, overrides, robots_dir);
}

Scenario loadScenarioText(const std::string& text, const std::string& origin,
                          const std::vector<std::string>& overrides,
                          const std::string& robots_dir) {
  return loadScenarioTree(parseYamlText(text, origin), origin, overrides, robots_dir);
}

}  // namespace wpg::datasets
